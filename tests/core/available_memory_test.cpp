// The memory this process may use (core/available_memory.hpp).
#include "roughgas/core/available_memory.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>

namespace roughgas {
namespace {

// MemAvailable from /proc/meminfo's text, in bytes; none without the line; the live value is
// positive on any Linux machine.
TEST(AvailableMemory, ReadsMemAvailable) {
    EXPECT_EQ(mem_available_of("MemTotal:       32768 kB\nMemFree:  100 kB\nMemAvailable:   2048 kB\n"),
              std::uint64_t{2048} * 1024);
    EXPECT_EQ(mem_available_of("MemTotal:       32768 kB\n"), std::nullopt);
    const std::optional<AvailableMemory> a = available_memory();
    ASSERT_TRUE(a.has_value());
    EXPECT_GT(a->bytes, 0u);
}

} // namespace
} // namespace roughgas
