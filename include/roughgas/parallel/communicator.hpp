#pragma once
// The processes of one job: MPI ranks when an MPI launcher (mpirun, mpiexec, Slurm's srun) started
// this program and it was built with MPI, else a world of one process. Commands spread independent
// work units over the ranks (the replicas of a run, the points of a sweep) and gather the results
// on rank 0, which alone writes the files; the spatially resolved solver decomposes its domain
// over the same ranks.
//
// Only the thread that created the Communicator calls it (MPI_THREAD_FUNNELED): the worker threads
// of a rank never communicate. A rank waiting for the others (a gather while they still compute)
// sleeps between polls instead of spinning, so it does not take a core from a rank or thread that
// shares it.
#include <string>
#include <string_view>
#include <vector>

namespace roughgas {

// What the launcher announces in the environment before any MPI call: Open MPI (OMPI_COMM_WORLD_*),
// MPICH and Slurm (PMI_RANK / PMI_SIZE, MPI_LOCALNRANKS), PMIx (PMIX_RANK). Not launched by one:
// rank 0 of 1.
struct Launch {
    bool by_mpi_launcher = false;
    int rank = 0, size = 1;
    int ranks_on_this_node = 1;
};
Launch launch_from_environment();

// True when this build has MPI (CMake found it; ROUGHGAS_MPI).
bool built_with_mpi();

class Communicator {
  public:
    // Initialises MPI when `launch` says an MPI launcher started this process and the build has MPI;
    // otherwise a world of one. Launched as several ranks by a build without MPI: throws
    // std::runtime_error (each copy would run the whole job and write the same files).
    explicit Communicator(const Launch& launch);
    ~Communicator(); // MPI_Finalize, when initialised here
    Communicator(const Communicator&) = delete;
    Communicator& operator=(const Communicator&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool is_root() const { return rank_ == 0; }
    // Started by an MPI launcher, which may signal the ranks more than once (mpirun passes a Ctrl-C
    // on as SIGTERM after the SIGINT the terminal sent to every rank).
    bool under_launcher() const { return initialised_; }

    // Every rank's bytes, in rank order, on rank 0; an empty vector on the others.
    std::vector<std::string> gather(std::string_view bytes) const;
    // The largest of the ranks' values, on every rank.
    long long max(long long value) const;

    // Ends every rank of the job at once with `status` (MPI_Abort; a world of one: std::_Exit).
    [[noreturn]] void abort(int status) const;

  private:
    int rank_ = 0, size_ = 1;
    bool initialised_ = false;
};

// The contiguous share of `count` work units of rank `rank` of `size`: [first, last), the shares in
// rank order covering 0 .. count - 1 once, their sizes differing by at most one.
struct Share {
    long long first = 0, last = 0;
};
Share share_of(long long count, int rank, int size);

} // namespace roughgas
