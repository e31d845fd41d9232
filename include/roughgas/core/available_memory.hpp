#pragma once
// The memory this process may still use: the smallest of the machine's MemAvailable
// (/proc/meminfo), what its cgroup allows beyond its current use (v2 memory.max - memory.current,
// v1 memory.limit_in_bytes - memory.usage_in_bytes) and what its address-space limit (RLIMIT_AS,
// `ulimit -v`) leaves beyond the address space it maps already (/proc/self/statm). Commands compare a run's estimate against it
// before any work, so that a run too large for the machine is refused with its numbers instead of
// failing in an allocation, or being killed, after minutes of table building.
#include <cstdint>
#include <optional>
#include <string>

namespace roughgas {

struct AvailableMemory {
    std::uint64_t bytes = 0;
    std::string source; // what limited it: "MemAvailable", "cgroup memory.max", "address-space limit (ulimit -v)"
};

// None when neither /proc/meminfo, a cgroup limit nor an address-space limit can be read.
std::optional<AvailableMemory> available_memory();

// MemAvailable in bytes from the text of /proc/meminfo ("MemAvailable:   123456 kB"); none without it.
std::optional<std::uint64_t> mem_available_of(const std::string& meminfo);

} // namespace roughgas
