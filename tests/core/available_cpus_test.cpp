// The default thread count: what the process may use (its affinity mask, the CPU quotas of its
// cgroup and those above it, SLURM_CPUS_PER_TASK), or OMP_NUM_THREADS when that is smaller.
#include "roughgas/core/available_cpus.hpp"

#include <gtest/gtest.h>

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

namespace roughgas {
namespace {

// Sets (or unsets, for nullptr) an environment variable for one scope.
class ScopedEnv {
  public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name))
            old_ = old;
        if (value)
            ::setenv(name, value, 1);
        else
            ::unsetenv(name);
    }
    ~ScopedEnv() {
        if (old_)
            ::setenv(name_, old_->c_str(), 1);
        else
            ::unsetenv(name_);
    }

  private:
    const char* name_;
    std::optional<std::string> old_;
};

// default_threads() with this thread's affinity set to the first CPU of `all`, then `all` again.
int default_threads_on_one_cpu(const cpu_set_t& all) {
    int first = 0;
    while (!CPU_ISSET(first, &all))
        ++first;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(first, &one);
    EXPECT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
    const int n = default_threads();
    EXPECT_EQ(sched_setaffinity(0, sizeof all, &all), 0);
    return n;
}

TEST(AvailableCpus, CgroupQuota) {
    EXPECT_EQ(cpus_of_cpu_max("max 100000\n"), std::nullopt);
    EXPECT_EQ(cpus_of_cpu_max("100000 100000\n"), 1);
    EXPECT_EQ(cpus_of_cpu_max("150000 100000\n"), 2); // 1.5 CPUs: two threads, each busy part of the time
    EXPECT_EQ(cpus_of_cpu_max("50000 100000"), 1);
    EXPECT_EQ(cpus_of_cpu_max("800000 100000"), 8);
    EXPECT_EQ(cpus_of_cpu_max(""), std::nullopt);
    EXPECT_EQ(cpus_of_cpu_max("12x 100000"), std::nullopt);
}

// A cgroup tree under a temporary root, with a file's text at a relative path.
class CgroupTree {
  public:
    CgroupTree() : root_(std::filesystem::temp_directory_path() / ("roughgas_cgroup_" + std::to_string(::getpid()))) {
        std::filesystem::remove_all(root_);
    }
    ~CgroupTree() { std::filesystem::remove_all(root_); }
    void put(const std::string& rel, const std::string& text) const {
        const std::filesystem::path p = root_ / rel;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p) << text;
    }
    const std::filesystem::path& root() const { return root_; }

  private:
    std::filesystem::path root_;
};

TEST(AvailableCpus, CgroupV2QuotaOfTheProcesssCgroupOrOneAboveIt) {
    // A systemd service with CPUQuota=150% inside a slice limited to 4 CPUs, on cgroup v2.
    CgroupTree t;
    t.put("cgroup.controllers", "cpu memory\n");
    t.put("system.slice/cpu.max", "400000 100000\n");
    t.put("system.slice/run.service/cpu.max", "150000 100000\n");
    EXPECT_EQ(cgroup_quota_cpus("0::/system.slice/run.service\n", t.root()), 2);
    // The slice's quota binds a job below it that has none of its own.
    t.put("system.slice/job/cpu.max", "max 100000\n");
    EXPECT_EQ(cgroup_quota_cpus("0::/system.slice/job\n", t.root()), 4);
    // No quota anywhere on the way up: none.
    t.put("user.slice/cpu.max", "max 100000\n");
    EXPECT_EQ(cgroup_quota_cpus("0::/user.slice/session-1.scope\n", t.root()), std::nullopt);
    // The root's quota (a container's own cgroup namespace shows "/").
    t.put("cpu.max", "300000 100000\n");
    EXPECT_EQ(cgroup_quota_cpus("0::/\n", t.root()), 3);
    EXPECT_EQ(cgroup_quota_cpus("", t.root()), 3); // /proc/self/cgroup unreadable: the roots
}

TEST(AvailableCpus, CgroupV1QuotaOfTheCpuControllersHierarchy) {
    // A hybrid system: v1's cpu controller (mounted as cpu,cpuacct) and an empty v2 tree in unified.
    CgroupTree t;
    t.put("unified/cgroup.procs", "");
    t.put("cpu,cpuacct/slurm/uid_1/job_7/cpu.cfs_quota_us", "200000\n");
    t.put("cpu,cpuacct/slurm/uid_1/job_7/cpu.cfs_period_us", "100000\n");
    t.put("cpu,cpuacct/slurm/cpu.cfs_quota_us", "-1\n");
    t.put("cpu,cpuacct/slurm/cpu.cfs_period_us", "100000\n");
    const std::string self = "12:memory:/slurm/uid_1/job_7\n4:cpu,cpuacct:/slurm/uid_1/job_7\n0::/slurm/uid_1/job_7\n";
    EXPECT_EQ(cgroup_quota_cpus(self, t.root()), 2);
    // Only the cpu controller's hierarchy counts: a quota-like file elsewhere is not read.
    EXPECT_EQ(cgroup_quota_cpus("12:memory:/slurm/uid_1/job_7\n", t.root()), std::nullopt);
}

TEST(AvailableCpus, OmpNumThreadsLowersTheDefaultButNeverRaisesIt) {
    const ScopedEnv slurm("SLURM_CPUS_PER_TASK", nullptr);
    int available = 0;
    {
        const ScopedEnv omp("OMP_NUM_THREADS", nullptr);
        available = default_threads();
    }
    {
        const ScopedEnv omp("OMP_NUM_THREADS", "1");
        EXPECT_EQ(default_threads(), 1);
    }
    const ScopedEnv omp("OMP_NUM_THREADS", "4096");
    EXPECT_EQ(default_threads(), available);
}

TEST(AvailableCpus, NeverMoreThanTheAffinityMaskOrSlurmsCpusPerTask) {
    const ScopedEnv omp("OMP_NUM_THREADS", nullptr);
    cpu_set_t all;
    ASSERT_EQ(sched_getaffinity(0, sizeof all, &all), 0);
    EXPECT_GE(default_threads(), 1);
    EXPECT_LE(default_threads(), CPU_COUNT(&all));
    {
        const ScopedEnv slurm("SLURM_CPUS_PER_TASK", "1");
        EXPECT_EQ(default_threads(), 1);
    }
    // As under `taskset -c CPU`: one CPU of the mask.
    const int under_taskset = default_threads_on_one_cpu(all);
    EXPECT_EQ(under_taskset, 1);
}

// MPI ranks on one node sharing an unbound mask (mpirun --bind-to none) take a share each; the
// launcher's variables are only read here (no MPI call).
TEST(AvailableCpus, RanksOnOneNodeShareTheirMask) {
    const ScopedEnv omp("OMP_NUM_THREADS", nullptr);
    const ScopedEnv slurm("SLURM_CPUS_PER_TASK", nullptr);
    cpu_set_t all;
    ASSERT_EQ(sched_getaffinity(0, sizeof all, &all), 0);
    const int alone = default_threads();
    const ScopedEnv size("OMPI_COMM_WORLD_SIZE", "4");
    const ScopedEnv local("OMPI_COMM_WORLD_LOCAL_SIZE", "2");
    if (CPU_COUNT(&all) >= sysconf(_SC_NPROCESSORS_ONLN))
        EXPECT_EQ(default_threads(), std::max(1, alone / 2));
    // Bound to one CPU by the launcher: that CPU, not a share of it.
    const int bound = default_threads_on_one_cpu(all);
    EXPECT_EQ(bound, 1);
}

} // namespace
} // namespace roughgas

