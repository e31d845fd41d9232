// One writer per output directory (src/cli/output_dir_lock.hpp): a second `roughgas run`, `run
// --resume` or `sweep` on a directory another process is writing into is refused with exit status
// 2 and a message naming the option, before it writes anything; the lock goes with the process that
// held it, a SIGKILL included.
#include "../io/io_test_support.hpp"
#include "child_process.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

// A run far too long to end while the test looks at it (it is killed), saving a checkpoint at its
// start: elastic, perfectly rough grains (alpha = beta = 1), which keep their energy, so that no end
// is beyond the reach of a cooling gas's temperature.
std::string long_case() {
    return "[run]\nparticles = 20000\nend = 1.0e6\noutput_every = 1.0\nseed = 4\n\n"
           "[[species]]\nname = \"grain\"\nmass = 1.0\nradius = 0.5\n\n"
           "[collision]\nmodel = \"constant\"\nalpha = 1.0\nbeta = 1.0\n";
}

// A short sweep (two points, one collision per grain each) of `f` into `out`.
std::string sweep_args(const fs::path& f, const fs::path& out) {
    return "sweep '" + f.string() + "' --param collision.alpha=0.7:0.9:2 --quiet --set run.end=1 --out '" +
           out.string() + "'";
}

void expect_refused(const test::CommandResult& r, const std::string& option, const std::string& what) {
    EXPECT_EQ(r.status, 2) << what << "\n" << r.err;
    EXPECT_NE(r.err.find(option), std::string::npos) << what << "\n" << r.err;
    EXPECT_NE(r.err.find("another roughgas process is writing into this directory"), std::string::npos)
        << what << "\n"
        << r.err;
}

TEST(OutputDirLock, ARunningRunKeepsOthersOutUntilItIsKilled) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("long.toml", long_case());
    const fs::path out = dir / "out";
    test::ChildProcess first(
        {"run", f.string(), "--out", out.string(), "--quiet", "--threads", "1", "--checkpoint-every", "1000"},
        dir / "first_out.txt", dir / "first_err.txt");
    ASSERT_TRUE(test::wait_until(first, [&] { return fs::exists(out / "checkpoint" / "run.bin"); }))
        << test::read_file(dir / "first_err.txt");
    ASSERT_TRUE(first.running()) << test::read_file(dir / "first_err.txt");

    // Without --force the existing files would be reported; the lock is checked before them.
    const std::string again = "run '" + f.string() + "' --out '" + out.string() + "' --quiet";
    expect_refused(test::run_roughgas(again, dir), "--out", "a second run");
    expect_refused(test::run_roughgas(again + " --force --set run.end=1", dir), "--out",
                   "a second run, --force");
    expect_refused(test::run_roughgas("run --resume '" + out.string() + "' --quiet", dir), "--resume",
                   "--resume");
    expect_refused(test::run_roughgas(sweep_args(f, out), dir), "--out", "a sweep");
    EXPECT_TRUE(first.running()); // still the only writer
    EXPECT_FALSE(fs::exists(out / "sweep.csv"));

    first.signal(SIGKILL);
    const int status = first.wait();
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << status;
    // The kernel dropped the lock with the process: the directory is free again.
    const test::CommandResult r = test::run_roughgas(again + " --force --set run.end=1", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(out / "moments.csv"));
}

TEST(OutputDirLock, ALockedDirectoryIsLeftAsItWas) {
    // Another process's lock, as roughgas takes it (flock on the directory, from this process: a
    // separate open file description, so the child's flock is refused as it would be by a run).
    const test::ScratchDir dir;
    const fs::path f = dir.write("case.toml", long_case());
    const fs::path out = dir / "out";
    fs::create_directories(out);
    std::ofstream(out / "notes.txt") << "the user's own file\n";
    const auto before = test::file_contents(out);
    const int fd = ::open(out.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);

    expect_refused(test::run_roughgas("run '" + f.string() + "' --out '" + out.string() +
                                          "' --quiet --force --set run.end=1",
                                      dir),
                   "--out", "run");
    expect_refused(test::run_roughgas(sweep_args(f, out), dir), "--out", "sweep");
    EXPECT_EQ(test::file_contents(out), before);

    ::close(fd); // released: the same run goes through
    const test::CommandResult r = test::run_roughgas(
        "run '" + f.string() + "' --out '" + out.string() + "' --quiet --set run.end=1", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(out / "moments.csv"));
}

} // namespace
} // namespace roughgas
