// MPI when built with it (ROUGHGAS_MPI), a world of one otherwise (parallel/communicator.hpp).
#include "roughgas/parallel/communicator.hpp"

#include <chrono>
#include <limits>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>

#if ROUGHGAS_MPI
#include <mpi.h>
#endif

namespace roughgas {
namespace {

int env_int(const char* name, int otherwise) {
    const char* v = std::getenv(name);
    if (v == nullptr || *v == '\0')
        return otherwise;
    char* end = nullptr;
    const long n = std::strtol(v, &end, 10);
    return (*end == '\0' && n >= 0 && n < (1L << 30)) ? static_cast<int>(n) : otherwise;
}

#if ROUGHGAS_MPI
void check(int code, const char* what) {
    if (code != MPI_SUCCESS) {
        char text[MPI_MAX_ERROR_STRING];
        int n = 0;
        MPI_Error_string(code, text, &n);
        throw std::runtime_error(std::string(what) + ": " + std::string(text, static_cast<std::size_t>(n)));
    }
}

// Completes a nonblocking operation by polling: a rank that waits for others still computing sleeps
// (50 us, growing to 2 ms) instead of spinning in a blocking call, which with Open MPI's default
// busy-polling would take a core from a rank or thread that shares it.
void wait(MPI_Request& request, const char* what) {
    auto pause = std::chrono::microseconds(50);
    for (;;) {
        int done = 0;
        check(MPI_Test(&request, &done, MPI_STATUS_IGNORE), what);
        if (done)
            return;
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::microseconds(2000));
    }
}
#endif

} // namespace

Launch launch_from_environment() {
    Launch l;
    if (const int size = env_int("OMPI_COMM_WORLD_SIZE", 0); size > 0) { // Open MPI's mpirun
        l.by_mpi_launcher = true;
        l.size = size;
        l.rank = env_int("OMPI_COMM_WORLD_RANK", 0);
        l.ranks_on_this_node = env_int("OMPI_COMM_WORLD_LOCAL_SIZE", 1);
    } else if (const int size = env_int("PMI_SIZE", 0); size > 0) { // MPICH's Hydra, srun --mpi=pmi2
        l.by_mpi_launcher = true;
        l.size = size;
        l.rank = env_int("PMI_RANK", 0);
        l.ranks_on_this_node = env_int("MPI_LOCALNRANKS", env_int("SLURM_NTASKS_PER_NODE", 1));
    } else if (std::getenv("PMIX_RANK") != nullptr) { // srun --mpi=pmix: the size comes from MPI_Init
        l.by_mpi_launcher = true;
        l.rank = env_int("PMIX_RANK", 0);
        l.size = env_int("SLURM_NTASKS", 1);
        l.ranks_on_this_node = env_int("SLURM_NTASKS_PER_NODE", 1);
    }
    if (l.ranks_on_this_node < 1)
        l.ranks_on_this_node = 1;
    return l;
}

bool built_with_mpi() { return ROUGHGAS_MPI != 0; }

Share share_of(long long count, int rank, int size) {
    return {count * rank / size, count * (rank + 1) / size};
}

#if ROUGHGAS_MPI

Communicator::Communicator(const Launch& launch) {
    if (!launch.by_mpi_launcher)
        return;
    int provided = 0;
    check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    initialised_ = true;
    if (provided < MPI_THREAD_FUNNELED)
        throw std::runtime_error("this MPI library does not support threads (MPI_THREAD_FUNNELED)");
    check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
    check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
}

Communicator::~Communicator() {
    if (initialised_)
        MPI_Finalize();
}

std::vector<std::string> Communicator::gather(std::string_view bytes) const {
    if (size_ == 1)
        return {std::string(bytes)};
    // The sizes first, then the bytes (MPI counts are int: more than 2 GB per rank is refused).
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw std::runtime_error("Communicator::gather: more than 2 GiB from one rank");
    int n = static_cast<int>(bytes.size());
    std::vector<int> sizes(is_root() ? static_cast<std::size_t>(size_) : 0);
    MPI_Request r;
    check(MPI_Igather(&n, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD, &r), "MPI_Igather");
    wait(r, "MPI_Igather");
    std::vector<int> offsets(sizes.size());
    long long total = 0;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        offsets[i] = static_cast<int>(total);
        total += sizes[i];
    }
    if (total > std::numeric_limits<int>::max())
        throw std::runtime_error("Communicator::gather: more than 2 GiB in all");
    std::string all(static_cast<std::size_t>(total), '\0');
    check(MPI_Igatherv(bytes.data(), n, MPI_BYTE, all.data(), sizes.data(), offsets.data(), MPI_BYTE, 0,
                       MPI_COMM_WORLD, &r),
          "MPI_Igatherv");
    wait(r, "MPI_Igatherv");
    std::vector<std::string> out;
    for (std::size_t i = 0; i < sizes.size(); ++i)
        out.push_back(all.substr(static_cast<std::size_t>(offsets[i]), static_cast<std::size_t>(sizes[i])));
    return out;
}

long long Communicator::max(long long value) const {
    if (size_ == 1)
        return value;
    long long out = 0;
    MPI_Request r;
    check(MPI_Iallreduce(&value, &out, 1, MPI_LONG_LONG, MPI_MAX, MPI_COMM_WORLD, &r), "MPI_Iallreduce");
    wait(r, "MPI_Iallreduce");
    return out;
}

void Communicator::abort(int status) const {
    if (initialised_)
        MPI_Abort(MPI_COMM_WORLD, status);
    std::_Exit(status);
}

#else // a world of one process

Communicator::Communicator(const Launch& launch) {
    if (launch.size > 1)
        throw std::runtime_error(
            "started as rank " + std::to_string(launch.rank) + " of " + std::to_string(launch.size) +
            " by an MPI launcher, but this roughgas was built without MPI (each copy would run the whole "
            "job): install libopenmpi-dev and build again, or run it without the launcher");
}

Communicator::~Communicator() = default;

std::vector<std::string> Communicator::gather(std::string_view bytes) const { return {std::string(bytes)}; }
long long Communicator::max(long long value) const { return value; }
void Communicator::abort(int status) const { std::_Exit(status); }

#endif

} // namespace roughgas
