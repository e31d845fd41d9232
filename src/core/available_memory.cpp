#include "roughgas/core/available_memory.hpp"

#include "roughgas/core/text_file.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

namespace roughgas {
namespace {

std::optional<std::uint64_t> number(const std::string& text) {
    std::istringstream in(text);
    std::uint64_t x = 0;
    if (!(in >> x))
        return std::nullopt;
    return x;
}

} // namespace

std::optional<std::uint64_t> mem_available_of(const std::string& meminfo) {
    std::istringstream in(meminfo);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("MemAvailable:", 0) != 0)
            continue;
        std::istringstream f(line.substr(13));
        std::uint64_t kb = 0;
        std::string unit;
        if (f >> kb >> unit && unit == "kB")
            return kb * 1024;
    }
    return std::nullopt;
}

std::optional<AvailableMemory> available_memory() {
    std::optional<AvailableMemory> a;
    if (const auto m = mem_available_of(read_text_file("/proc/meminfo")))
        a = AvailableMemory{*m, "MemAvailable"};
    const auto limit = [&](const char* max_path, const char* use_path, const char* name) {
        const auto max = number(read_text_file(max_path)), use = number(read_text_file(use_path));
        if (!max || !use || *max >= (std::uint64_t{1} << 60)) // "max" (no number) or the v1 "unlimited" value
            return;
        const std::uint64_t left = *max > *use ? *max - *use : 0;
        if (!a || left < a->bytes)
            a = AvailableMemory{left, name};
    };
    limit("/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory.current", "cgroup memory.max");
    limit("/sys/fs/cgroup/memory/memory.limit_in_bytes", "/sys/fs/cgroup/memory/memory.usage_in_bytes",
          "cgroup memory.limit_in_bytes");
    // An address-space limit counts mapped, not resident, memory: the grains' arrays are mapped in
    // full at once, so it refuses them however little of the machine's memory is in use.
    struct rlimit rl {};
    const auto mapped_pages = number(read_text_file("/proc/self/statm")); // its first field: pages mapped
    if (::getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && mapped_pages) {
        const std::uint64_t mapped = *mapped_pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
        const std::uint64_t left = rl.rlim_cur > mapped ? rl.rlim_cur - mapped : 0;
        if (!a || left < a->bytes)
            a = AvailableMemory{left, "address-space limit (ulimit -v)"};
    }
    return a;
}

} // namespace roughgas
