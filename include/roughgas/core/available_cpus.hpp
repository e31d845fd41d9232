#pragma once
// The number of threads a command uses when --threads is not given: what this process may use,
// never more, so that a run on a shared machine, under taskset or in a batch job does not start
// more threads than it has cores (a thread beyond them waits for time slices of the others).
#include <filesystem>
#include <optional>
#include <string>

namespace roughgas {

// The smallest of the CPUs in this process's affinity mask (taskset, Slurm's cpuset), the CPU
// quota of its cgroup and of the cgroups above it, rounded up (cgroup v2 cpu.max or v1
// cpu.cfs_quota_us / cpu.cfs_period_us: containers, systemd's CPUQuota, Slurm's cgroups) and
// SLURM_CPUS_PER_TASK; divided by the MPI ranks on this node when they share an unbound mask
// (mpirun --bind-to none: OMPI_COMM_WORLD_LOCAL_SIZE, MPI_LOCALNRANKS); then OMP_NUM_THREADS when
// it is set and smaller (the user's choice, within what the process may use); at least 1.
int default_threads();

// The parts of default_threads(), for tests: the quota in CPUs from the text of cpu.max ("max
// 100000" or "150000 100000"), none when unlimited or unreadable.
std::optional<int> cpus_of_cpu_max(const std::string& text);
// The least quota in CPUs of the process's cgroup and those above it, from the text of
// /proc/self/cgroup ("0::/a/b" for cgroup v2, "4:cpu,cpuacct:/a/b" for v1's cpu controller) and
// the hierarchies mounted under `root` (/sys/fs/cgroup: v2 there or, on a hybrid system, in
// root/unified; v1's cpu controller in root/cpu or root/cpu,cpuacct); none when no quota is set
// or readable. An empty text reads the hierarchies' roots.
std::optional<int> cgroup_quota_cpus(const std::string& self_cgroup, const std::filesystem::path& root);

} // namespace roughgas
