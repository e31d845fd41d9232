#include "roughgas/core/run_delay.hpp"

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <charconv>
#include <cstdio>

namespace roughgas {

// The system call rather than glibc's gettid(), which needs glibc 2.30 (clusters run older ones).
int this_thread_id() { return static_cast<int>(::syscall(SYS_gettid)); }

std::optional<std::int64_t> run_delay_of_schedstat(std::string_view text) {
    std::int64_t field[3] = {0, 0, 0};
    const char* p = text.data();
    const char* const end = text.data() + text.size();
    for (std::int64_t& f : field) {
        while (p < end && *p == ' ')
            ++p;
        const auto [next, ec] = std::from_chars(p, end, f);
        if (ec != std::errc() || f < 0)
            return std::nullopt;
        p = next;
    }
    if (field[0] == 0) // no time on a CPU: a kernel that keeps no scheduler statistics reports zeros
        return std::nullopt;
    return field[1];
}

std::optional<std::int64_t> run_delay_ns(int tid) {
    // open/read rather than a stream: read about 20 times a second per thread, and the file is
    // one short line.
    char path[64];
    std::snprintf(path, sizeof path, "/proc/self/task/%d/schedstat", tid);
    const int fd = ::open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return std::nullopt;
    char text[128];
    const ssize_t n = ::read(fd, text, sizeof text);
    ::close(fd);
    if (n <= 0)
        return std::nullopt;
    return run_delay_of_schedstat(std::string_view(text, static_cast<std::size_t>(n)));
}

} // namespace roughgas
