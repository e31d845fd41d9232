// `mpirun -np R roughgas run|sweep` (src/cli/run_command.cpp, sweep_command.cpp, rank_errors.hpp):
// the ranks share the replicas or the sweep points and rank 0 writes the very bytes one process
// writes, for 1, 2 and 3 ranks (a box with walls and saved states too); SIGTERM or SIGINT to the ranks,
// or a Ctrl-C at mpirun, stops them as a signal stops one process, and the job resumes on another
// rank count into the same bytes; a rank killed with SIGKILL, or one
// whose checkpoint cannot be written, ends the job non-zero, naming the rank, with no ensemble file
// written; invalid input is reported once,
// with exit status 2. Built only when CMake found MPI (ROUGHGAS_MPIEXEC).
#ifdef ROUGHGAS_MPIEXEC
#include "../io/io_test_support.hpp"
#include "child_process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

// mpirun as root (CI) and with more ranks than cores; no binding, so ranks share the cores.
class Mpi : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
        ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
        ::setenv("OMPI_MCA_rmaps_base_oversubscribe", "1", 1);
    }
};

std::vector<std::string> mpirun(int ranks, const std::vector<std::string>& args) {
    std::vector<std::string> a = {"--oversubscribe", "--bind-to", "none", "-np", std::to_string(ranks),
                                  ROUGHGAS_BINARY};
    a.insert(a.end(), args.begin(), args.end());
    return a;
}

// Runs mpirun ARGS to the end: its wait status and stderr.
test::Stopped run_mpi(int ranks, const std::vector<std::string>& args, const test::ScratchDir& dir) {
    test::ChildProcess child(ROUGHGAS_MPIEXEC, mpirun(ranks, args), dir / "mpi_out.txt", dir / "mpi_err.txt");
    test::Stopped s;
    s.status = child.wait();
    s.err = test::read_file(dir / "mpi_err.txt");
    return s;
}

int exit_status(int raw) { return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1; }

// The processes of rank `rank` whose command line names `dir` (their environment says the rank).
std::vector<pid_t> rank_pids(int rank, const fs::path& dir) {
    std::vector<pid_t> pids;
    const std::string want = "OMPI_COMM_WORLD_RANK=" + std::to_string(rank);
    for (const auto& e : fs::directory_iterator("/proc")) {
        const std::string name = e.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos)
            continue;
        std::string cmdline = test::read_file(e.path() / "cmdline");
        if (cmdline.find(dir.string()) == std::string::npos || cmdline.find(ROUGHGAS_BINARY) != 0)
            continue;
        std::string env = test::read_file(e.path() / "environ");
        for (std::size_t p = 0; p < env.size();) {
            const std::size_t end = env.find('\0', p);
            if (env.compare(p, (end == std::string::npos ? env.size() : end) - p, want) == 0)
                pids.push_back(static_cast<pid_t>(std::stol(name)));
            if (end == std::string::npos)
                break;
            p = end + 1;
        }
    }
    return pids;
}

// Each of the run's `replicas` has saved its state once (its rank is past the setup and running).
bool every_replica_saved(const fs::path& out, int replicas) {
    for (int r = 0; r < replicas; ++r)
        if (!fs::exists(out / "checkpoint" / ("replica_" + std::to_string(r) + ".bin")))
            return false;
    return true;
}

const std::string elastic = "alpha = 1.0\nbeta = 1.0";

// Rough cooling, 5 replicas (shares of 5, 2 + 3 and 1 + 2 + 2), histograms and log-spaced rows.
// `restitution` = elastic for runs of hours (ended by the test): an elastic gas keeps its energy,
// so no end is beyond the reach of a cooling gas's temperature.
std::string ensemble_case(const std::string& end = "20.0", int replicas = 5, int particles = 3000,
                          const std::string& restitution = "alpha = 0.8\nbeta = 0.4") {
    return "[run]\nparticles = " + std::to_string(particles) + "\nreplicas = " + std::to_string(replicas) +
           "\nend = " + end +
           "\noutput_every = 0.5\noutput_spacing = \"log\"\nhistogram_every = 5.0\nseed = 11\n\n"
           "[[species]]\nmass = 1.0\nradius = 0.5\n\n"
           "[collision]\nmodel = \"constant\"\n" + restitution + "\n";
}

TEST_F(Mpi, RanksWriteTheBytesOfOneProcess) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("hcs.toml", ensemble_case());
    ASSERT_EQ(test::run_roughgas("run '" + f.string() + "' --quiet --out '" + (dir / "one").string() + "'", dir)
                  .status,
              0);
    for (int ranks : {1, 2, 3}) {
        const fs::path out = dir / ("np" + std::to_string(ranks));
        const test::Stopped r =
            run_mpi(ranks, {"run", f.string(), "--quiet", "--threads", "1", "--out", out.string()}, dir);
        ASSERT_EQ(exit_status(r.status), 0) << r.err;
        for (const char* file : {"moments.csv", "histograms.csv", "scaled.csv"})
            EXPECT_EQ(test::read_file(out / file), test::read_file(dir / "one" / file)) << ranks << " " << file;
        for (int r = 0; r < 5; ++r) { // each replica's own rows, written by rank 0 for every rank
            const std::string file = "replicas/moments_" + std::to_string(r) + ".csv";
            ASSERT_TRUE(fs::exists(dir / "one" / file)) << file;
            EXPECT_EQ(test::read_file(out / file), test::read_file(dir / "one" / file)) << ranks << " " << file;
        }
        EXPECT_FALSE(fs::exists(out / "checkpoint")) << "no checkpoint asked for, none left";
    }
}

// A box between a diffuse floor and a moving diffuse lid (walls.csv, profiles.csv and the steady
// files of a driven box), 3 replicas whose final grains are saved (run.save_state): 2 and 3 ranks
// write the bytes of one process, the state files included.
TEST_F(Mpi, BoxRanksWriteTheBytesOfOneProcess) {
    const test::ScratchDir dir;
    const fs::path f = dir.write(
        "box.toml", "[run]\nparticles = 3000\nreplicas = 3\nend = 20.0\noutput_every = 2.0\ndensity = 0.02\nseed = 5\n"
                    "save_state = true\n\n[[species]]\nmass = 1.0\nradius = 0.5\n\n"
                    "[collision]\nmodel = \"constant\"\nalpha = 0.9\nbeta = 0.4\n\n"
                    "[domain]\nsize = [50.0, 50.0, 50.0]\ncells = [5, 5, 5]\n"
                    "boundary = [\"periodic\", \"walls\", \"periodic\"]\n\n"
                    "[wall_lower]\nkind = \"diffuse\"\ntemperature = 1.0\n\n"
                    "[wall_upper]\nkind = \"diffuse\"\ntemperature = 1.0\nvelocity = [0.5, 0.0, 0.0]\n");
    ASSERT_EQ(test::run_roughgas("run '" + f.string() + "' --quiet --out '" + (dir / "one").string() + "'", dir)
                  .status,
              0);
    const std::vector<std::string> files = {"moments.csv",   "walls.csv",           "profiles.csv",
                                            "steady.csv",    "steady_profiles.csv", "state/replica_0.bin",
                                            "state/replica_1.bin", "state/replica_2.bin"};
    for (const std::string& file : files)
        ASSERT_TRUE(fs::exists(dir / "one" / file)) << file;
    for (int ranks : {1, 2, 3}) {
        const fs::path out = dir / ("np" + std::to_string(ranks));
        const test::Stopped r =
            run_mpi(ranks, {"run", f.string(), "--quiet", "--threads", "1", "--out", out.string()}, dir);
        ASSERT_EQ(exit_status(r.status), 0) << r.err;
        for (const std::string& file : files)
            EXPECT_EQ(test::read_file(out / file), test::read_file(dir / "one" / file)) << ranks << " " << file;
    }
}

TEST_F(Mpi, SweepRanksWriteTheBytesOfOneProcess) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("hcs.toml", ensemble_case("10.0", 2, 2000));
    const std::vector<std::string> sweep = {"sweep", f.string(), "--param", "collision.alpha=0.6:0.9:4", "--quiet"};
    ASSERT_EQ(test::run_roughgas("sweep '" + f.string() + "' --param collision.alpha=0.6:0.9:4 --quiet --out '" +
                                     (dir / "one").string() + "'",
                                 dir)
                  .status,
              0);
    for (int ranks : {1, 2, 3}) {
        const fs::path out = dir / ("np" + std::to_string(ranks));
        std::vector<std::string> args = sweep;
        args.insert(args.end(), {"--out", out.string()});
        const test::Stopped r = run_mpi(ranks, args, dir);
        ASSERT_EQ(exit_status(r.status), 0) << r.err;
        EXPECT_EQ(test::read_file(out / "sweep.csv"), test::read_file(dir / "one" / "sweep.csv")) << ranks;
        for (int k = 0; k < 4; ++k) {
            const std::string p = "point_" + std::to_string(k);
            EXPECT_EQ(test::read_file(out / p / "moments.csv"), test::read_file(dir / "one" / p / "moments.csv"))
                << ranks << " " << p;
        }
    }
}

// How a stop reaches the job: a signal to every rank (a batch system's cancel or time limit sends
// SIGTERM, srun passes a Ctrl-C on as SIGINT), or a Ctrl-C at mpirun's terminal: SIGINT to mpirun's
// process group, which holds mpirun alone (Open MPI 4 starts each rank in a group of its own), and
// mpirun passes SIGTERM to the ranks, then SIGKILL: after odls_base_sigkill_timeout seconds each,
// set to 3 here (docs/running.md advises more for large replicas) so that a loaded machine's ranks
// have the time to checkpoint, with replicas large enough to be still running when it ends.
enum class Stop { sigterm_to_ranks, sigint_to_ranks, ctrl_c_to_mpirun };

// Each rank stops at its next boundary with a checkpoint, rank 0 writes the rows complete so far
// and says which signal stopped it, the job ends non-zero; the job resumed on two ranks writes the
// bytes of the run without a stop.
void stop_and_resume(Stop stop, const std::string& said) {
    const test::ScratchDir dir;
    const int particles = stop == Stop::ctrl_c_to_mpirun ? 20000 : 5000;
    const fs::path f = dir.write("hcs.toml", ensemble_case("1000.0", 3, particles));
    ASSERT_EQ(test::run_roughgas("run '" + f.string() + "' --quiet --out '" + (dir / "one").string() + "'", dir)
                  .status,
              0);
    const fs::path out = dir / "stopped";
    {
        ::setenv("OMPI_MCA_odls_base_sigkill_timeout", "3", 1);
        test::ChildProcess job(ROUGHGAS_MPIEXEC,
                               mpirun(3, {"run", f.string(), "--quiet", "--threads", "1", "--checkpoint-every",
                                          "5", "--out", out.string()}),
                               dir / "mpi_out.txt", dir / "mpi_err.txt", /*own_group=*/true);
        ::unsetenv("OMPI_MCA_odls_base_sigkill_timeout");
        // Every replica has saved a state once (each rank is past its setup and running).
        ASSERT_TRUE(test::wait_until(job, [&] { return every_replica_saved(out, 3); }))
            << test::read_file(dir / "mpi_err.txt");
        if (stop == Stop::ctrl_c_to_mpirun) {
            job.signal_group(SIGINT);
        } else {
            for (int rank = 0; rank < 3; ++rank)
                for (pid_t p : rank_pids(rank, out))
                    ::kill(p, stop == Stop::sigterm_to_ranks ? SIGTERM : SIGINT);
        }
        const int status = job.wait();
        const std::string err = test::read_file(dir / "mpi_err.txt");
        EXPECT_NE(exit_status(status), 0) << err;
        ASSERT_NE(err.find("roughgas run: stopped by " + said + ": "), std::string::npos) << err;
        EXPECT_NE(err.find("continue with: roughgas run --resume"), std::string::npos) << err;
    }
    // Every replica's checkpoint is there and no temporary is left.
    EXPECT_TRUE(every_replica_saved(out, 3));
    for (const auto& e : fs::recursive_directory_iterator(out))
        EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
    // The rows so far are the first rows of the whole run.
    const std::string partial = test::read_file(out / "moments.csv");
    const std::string whole = test::read_file(dir / "one" / "moments.csv");
    ASSERT_FALSE(partial.empty());
    EXPECT_LT(partial.size(), whole.size());
    EXPECT_EQ(whole.compare(0, partial.size(), partial), 0) << "the stopped file is not a prefix of the whole";
    const test::Stopped r = run_mpi(2, {"run", "--resume", out.string(), "--quiet", "--threads", "1"}, dir);
    ASSERT_EQ(exit_status(r.status), 0) << r.err;
    for (const char* file : {"moments.csv", "histograms.csv", "scaled.csv"})
        EXPECT_EQ(test::read_file(out / file), test::read_file(dir / "one" / file)) << file;
}

TEST_F(Mpi, SigtermStopsTheRanksAndTheResumeWritesTheSameBytes) {
    stop_and_resume(Stop::sigterm_to_ranks, "SIGTERM");
}

TEST_F(Mpi, SigintStopsTheRanksAndTheResumeWritesTheSameBytes) {
    stop_and_resume(Stop::sigint_to_ranks, "SIGINT");
}

TEST_F(Mpi, CtrlCAtMpirunStopsTheRanksAndTheResumeWritesTheSameBytes) {
    stop_and_resume(Stop::ctrl_c_to_mpirun, "SIGTERM");
}

TEST_F(Mpi, AKilledRankEndsTheJobNamingItAndNoEnsembleFileIsWritten) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("hcs.toml", ensemble_case("1.0e6", 3, 20000, elastic)); // hours: killed mid-run
    const fs::path out = dir / "killed";
    test::ChildProcess job(ROUGHGAS_MPIEXEC,
                           mpirun(3, {"run", f.string(), "--quiet", "--checkpoint-every", "1", "--out", out.string()}),
                           dir / "mpi_out.txt", dir / "mpi_err.txt");
    // Mid-run: every replica has saved a state once.
    ASSERT_TRUE(test::wait_until(job, [&] { return every_replica_saved(out, 3); }))
        << test::read_file(dir / "mpi_err.txt");
    const std::vector<pid_t> victim = rank_pids(1, out);
    ASSERT_FALSE(victim.empty());
    for (pid_t p : victim)
        ::kill(p, SIGKILL);
    const int status = job.wait();
    const std::string err = test::read_file(dir / "mpi_err.txt");
    EXPECT_NE(exit_status(status), 0) << err;
    EXPECT_NE(err.find("rank 1"), std::string::npos) << err;
    for (const char* file : {"moments.csv", "histograms.csv", "scaled.csv"})
        EXPECT_FALSE(fs::exists(out / file)) << file;
    // No temporary but one the killed rank may have been renaming when SIGKILL came (its replica
    // state, NAME.tmp.PID in checkpoint/: written unnamed, it gets that name only once complete, for
    // the instant before its rename; a resume removes it).
    if (fs::exists(out))
        for (const auto& e : fs::recursive_directory_iterator(out)) {
            const std::string name = e.path().filename().string();
            const std::size_t at = name.find(".tmp.");
            if (at == std::string::npos)
                continue;
            const bool victims = e.path().parent_path().filename() == "checkpoint" &&
                                 std::any_of(victim.begin(), victim.end(), [&](pid_t p) {
                                     return name.substr(at + 5) == std::to_string(p);
                                 });
            EXPECT_TRUE(victims) << e.path();
        }
}

// An error on one rank during the run: replica 2's checkpoint (rank 2's) cannot be written, because
// a directory holding a file now stands where it goes. That rank says so, naming itself, and ends
// the job (MPI_Abort): a non-zero exit and no ensemble file.
TEST_F(Mpi, AnErrorOnOneRankEndsTheJobNamingTheRank) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("hcs.toml", ensemble_case("1.0e6", 3, 20000, elastic)); // hours: ended by the error
    const fs::path out = dir / "failed";
    test::ChildProcess job(ROUGHGAS_MPIEXEC,
                           mpirun(3, {"run", f.string(), "--quiet", "--checkpoint-every", "1", "--out", out.string()}),
                           dir / "mpi_out.txt", dir / "mpi_err.txt");
    ASSERT_TRUE(test::wait_until(job, [&] { return every_replica_saved(out, 3); }))
        << test::read_file(dir / "mpi_err.txt");
    // The rank rewrites the file at every checkpoint: replace it until the directory stays.
    const fs::path target = out / "checkpoint" / "replica_2.bin";
    for (int tries = 0; tries < 1000 && !fs::is_directory(target); ++tries) {
        std::error_code ec;
        fs::remove(target, ec);
        fs::create_directory(target, ec);
    }
    ASSERT_TRUE(fs::is_directory(target));
    { std::ofstream(target / "keep") << "a non-empty directory: no rename replaces it\n"; }
    const int status = job.wait();
    const std::string err = test::read_file(dir / "mpi_err.txt");
    EXPECT_NE(exit_status(status), 0) << err;
    EXPECT_NE(err.find("roughgas: rank 2 of 3:"), std::string::npos) << err;
    EXPECT_NE(err.find("replica_2.bin"), std::string::npos) << err;
    for (const char* file : {"moments.csv", "histograms.csv", "scaled.csv"})
        EXPECT_FALSE(fs::exists(out / file)) << file;
}

TEST_F(Mpi, InvalidInputIsReportedOnceWithStatus2) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("bad.toml", test::replaced(ensemble_case(), "alpha = 0.8", "alpha = 1.8"));
    const test::Stopped r = run_mpi(3, {"run", f.string(), "--out", (dir / "out").string()}, dir);
    EXPECT_EQ(exit_status(r.status), 2) << r.err;
    const std::size_t first = r.err.find("collision.alpha");
    ASSERT_NE(first, std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("collision.alpha", first + 1), std::string::npos) << "reported more than once:\n" << r.err;
    EXPECT_FALSE(fs::exists(dir / "out"));
    // A command that runs in one process is refused under several ranks.
    const test::Stopped m = run_mpi(2, {"merge", (dir / "a").string(), "--out", (dir / "m").string()}, dir);
    EXPECT_EQ(exit_status(m.status), 2) << m.err;
    EXPECT_NE(m.err.find("roughgas merge: runs in one process"), std::string::npos) << m.err;
}

} // namespace
} // namespace roughgas
#endif
