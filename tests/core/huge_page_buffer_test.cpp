// resize_on_huge_pages: a vector grown on new (advised) storage keeps its elements in order and
// value-initialises the new ones, as std::vector::resize does; a vector that does not grow keeps
// its storage.
#include "roughgas/core/huge_page_buffer.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace roughgas {
namespace {

TEST(ResizeOnHugePages, KeepsTheElementsHeldAndValueInitialisesTheNewOnes) {
    std::vector<std::uint64_t> v;
    resize_on_huge_pages(v, 1000);
    ASSERT_EQ(v.size(), 1000u);
    for (std::size_t i = 0; i < v.size(); ++i) {
        ASSERT_EQ(v[i], 0u) << i;
        v[i] = 3 * i + 1;
    }
    resize_on_huge_pages(v, std::size_t{3} << 20); // 24 MiB: spans whole 2 MiB pages
    ASSERT_EQ(v.size(), std::size_t{3} << 20);
    for (std::size_t i = 0; i < v.size(); ++i)
        ASSERT_EQ(v[i], i < 1000 ? 3 * i + 1 : 0u) << i;
    const std::uint64_t* storage = v.data();
    resize_on_huge_pages(v, 500); // shrinking: the same storage, the first elements kept
    EXPECT_EQ(v.data(), storage);
    ASSERT_EQ(v.size(), 500u);
    for (std::size_t i = 0; i < v.size(); ++i)
        ASSERT_EQ(v[i], 3 * i + 1) << i;
}

} // namespace
} // namespace roughgas
