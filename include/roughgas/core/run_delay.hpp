#pragma once
// The time a thread has spent runnable but waiting for a CPU, as the Linux scheduler counts it
// (/proc/<pid>/task/<tid>/schedstat: time on a CPU, time waiting on a run queue, time slices;
// nanoseconds since the thread started). A thread of an idle machine waits microseconds per second;
// one of two runs sharing two cores with two threads each waits about half of its time. WorkerTeam
// reads it to run on fewer threads while the machine has no CPU for all of them.
#include <cstdint>
#include <optional>
#include <string_view>

namespace roughgas {

// The kernel's id of the calling thread (gettid).
int this_thread_id();

// The run-queue wait of thread `tid` of this process, in nanoseconds; none where the kernel does
// not report it (another system, /proc not mounted, a kernel without scheduler statistics).
std::optional<std::int64_t> run_delay_ns(int tid);

// The second field of a schedstat line ("1234 567 89"); none when the text is not such a line or
// its first field (time on a CPU) is 0, as on kernels that keep no scheduler statistics.
std::optional<std::int64_t> run_delay_of_schedstat(std::string_view text);

} // namespace roughgas
