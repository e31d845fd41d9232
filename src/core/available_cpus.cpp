#include "roughgas/core/available_cpus.hpp"

#include "roughgas/core/text_file.hpp"

#include "roughgas/parallel/communicator.hpp"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace roughgas {

namespace {

std::optional<int> positive_int(const char* text) {
    if (!text || !*text)
        return std::nullopt;
    char* end = nullptr;
    const long v = std::strtol(text, &end, 10);
    if (*end != '\0' && *end != '\n' && *end != ',')
        return std::nullopt;
    if (v < 1)
        return std::nullopt;
    return static_cast<int>(std::min(v, 4096L));
}

std::optional<int> quota_cpus(double quota, double period) {
    if (!(quota > 0) || !(period > 0))
        return std::nullopt;
    return std::max(1, static_cast<int>(std::ceil(quota / period - 1e-9)));
}

} // namespace

std::optional<int> cpus_of_cpu_max(const std::string& text) {
    std::istringstream in(text);
    std::string quota;
    double period = 0;
    if (!(in >> quota >> period) || quota == "max")
        return std::nullopt;
    char* end = nullptr;
    const double q = std::strtod(quota.c_str(), &end);
    if (*end != '\0')
        return std::nullopt;
    return quota_cpus(q, period);
}

int default_threads() {
    if (const std::optional<int> n = positive_int(std::getenv("OMP_NUM_THREADS")))
        return *n;
    int n = 4096;
    cpu_set_t set;
    bool whole_machine = false; // the mask is every online CPU: not bound by a launcher
    if (sched_getaffinity(0, sizeof set, &set) == 0) {
        n = std::min(n, std::max(1, CPU_COUNT(&set)));
        whole_machine = CPU_COUNT(&set) >= sysconf(_SC_NPROCESSORS_ONLN);
    }
    if (const std::optional<int> q = cpus_of_cpu_max(read_text_file("/sys/fs/cgroup/cpu.max")))
        n = std::min(n, *q);
    const std::string v1_quota = read_text_file("/sys/fs/cgroup/cpu/cpu.cfs_quota_us");
    const std::string v1_period = read_text_file("/sys/fs/cgroup/cpu/cpu.cfs_period_us");
    if (!v1_quota.empty() && !v1_period.empty())
        if (const std::optional<int> q = quota_cpus(std::atof(v1_quota.c_str()), std::atof(v1_period.c_str())))
            n = std::min(n, *q);
    if (const std::optional<int> s = positive_int(std::getenv("SLURM_CPUS_PER_TASK")))
        n = std::min(n, *s);
    if (n == 4096)
        return 1;
    // MPI ranks on this node that share one unbound mask (mpirun --bind-to none): a share each.
    if (const int ranks = launch_from_environment().ranks_on_this_node; ranks > 1 && whole_machine)
        n = std::max(1, n / ranks);
    return n;
}

} // namespace roughgas
