#include "roughgas/core/available_cpus.hpp"

#include "roughgas/core/text_file.hpp"

#include "roughgas/parallel/communicator.hpp"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
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

std::optional<int> cgroup_quota_cpus(const std::string& self_cgroup, const std::filesystem::path& root) {
    namespace fs = std::filesystem;
    std::optional<int> least;
    const auto take = [&](std::optional<int> q) {
        if (q && (!least || *q < *least))
            least = q;
    };
    // From the process's cgroup up to its hierarchy's root: a quota anywhere above binds too.
    const auto up_from = [](std::string path, const auto& visit) {
        if (path.empty() || path.front() != '/' || path.find("..") != std::string::npos)
            path = "/"; // outside this cgroup namespace's view: its root is what can be read
        while (!path.empty() && path.back() == '\n')
            path.pop_back();
        for (;;) {
            visit(fs::path(path).relative_path());
            if (path == "/")
                return;
            const std::size_t slash = path.find_last_of('/');
            path = slash == 0 ? "/" : path.substr(0, slash);
        }
    };
    std::istringstream in(self_cgroup.empty() ? std::string("0::/\n1:cpu:/\n") : self_cgroup);
    std::string line;
    while (std::getline(in, line)) {
        // hierarchy-ID:controller-list:cgroup-path
        const std::size_t a = line.find(':'), b = a == std::string::npos ? a : line.find(':', a + 1);
        if (b == std::string::npos)
            continue;
        const std::string controllers = "," + line.substr(a + 1, b - a - 1) + ",";
        const std::string path = line.substr(b + 1);
        if (line.compare(0, a, "0") == 0 && controllers == ",,") { // cgroup v2 (unified)
            std::error_code ec; // an unreadable tree is no quota, never an error
            const fs::path base = fs::exists(root / "cgroup.controllers", ec) || !fs::exists(root / "unified", ec)
                                      ? root
                                      : root / "unified"; // a hybrid system's v2 hierarchy
            up_from(path, [&](const fs::path& rel) {
                take(cpus_of_cpu_max(read_text_file((base / rel / "cpu.max").c_str())));
            });
        } else if (controllers.find(",cpu,") != std::string::npos) { // cgroup v1, the cpu controller
            for (const char* mount : {"cpu", "cpu,cpuacct", "cpuacct,cpu"}) {
                std::error_code ec;
                if (!fs::exists(root / mount, ec))
                    continue;
                up_from(path, [&](const fs::path& rel) {
                    const fs::path dir = root / mount / rel;
                    const std::string quota = read_text_file((dir / "cpu.cfs_quota_us").c_str());
                    const std::string period = read_text_file((dir / "cpu.cfs_period_us").c_str());
                    if (!quota.empty() && !period.empty())
                        take(quota_cpus(std::atof(quota.c_str()), std::atof(period.c_str())));
                });
                break;
            }
        }
    }
    return least;
}

int default_threads() {
    int n = 4096;
    cpu_set_t set;
    bool whole_machine = false; // the mask is every online CPU: not bound by a launcher
    if (sched_getaffinity(0, sizeof set, &set) == 0) {
        n = std::min(n, std::max(1, CPU_COUNT(&set)));
        whole_machine = CPU_COUNT(&set) >= sysconf(_SC_NPROCESSORS_ONLN);
    }
    if (const std::optional<int> q = cgroup_quota_cpus(read_text_file("/proc/self/cgroup"), "/sys/fs/cgroup"))
        n = std::min(n, *q);
    if (const std::optional<int> s = positive_int(std::getenv("SLURM_CPUS_PER_TASK")))
        n = std::min(n, *s);
    if (n == 4096)
        n = 1;
    // MPI ranks on this node that share one unbound mask (mpirun --bind-to none): a share each.
    if (const int ranks = launch_from_environment().ranks_on_this_node; ranks > 1 && whole_machine)
        n = std::max(1, n / ranks);
    // The user's choice, within what the process may use (more threads than its CPUs would wait
    // for each other's time slices).
    if (const std::optional<int> omp = positive_int(std::getenv("OMP_NUM_THREADS")))
        n = std::min(n, *omp);
    return n;
}

} // namespace roughgas
