#pragma once
// The number of threads a command uses when --threads is not given: what this process may use,
// never more, so that a run on a shared machine, under taskset or in a batch job does not start
// more threads than it has cores (a thread beyond them waits for time slices of the others).
#include <optional>
#include <string>

namespace roughgas {

// OMP_NUM_THREADS when set (the user's explicit choice); else the smallest of the CPUs in this
// process's affinity mask (taskset, Slurm's cpuset), the cgroup's CPU quota rounded up
// (cgroup v2 cpu.max or v1 cpu.cfs_quota_us / cpu.cfs_period_us: containers, Slurm) and
// SLURM_CPUS_PER_TASK; divided by the MPI ranks on this node when they share an unbound mask
// (mpirun --bind-to none: OMPI_COMM_WORLD_LOCAL_SIZE, MPI_LOCALNRANKS); at least 1.
int default_threads();

// The parts of default_threads(), for tests: the quota in CPUs from the text of cpu.max ("max
// 100000" or "150000 100000"), none when unlimited or unreadable.
std::optional<int> cpus_of_cpu_max(const std::string& text);

} // namespace roughgas
