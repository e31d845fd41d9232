// The default thread count: OMP_NUM_THREADS when set, else what the process may use (its affinity
// mask, the cgroup's CPU quota, SLURM_CPUS_PER_TASK).
#include "roughgas/core/available_cpus.hpp"

#include <gtest/gtest.h>

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
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

TEST(AvailableCpus, OmpNumThreadsIsTheUsersChoice) {
    const ScopedEnv omp("OMP_NUM_THREADS", "3");
    EXPECT_EQ(default_threads(), 3);
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

