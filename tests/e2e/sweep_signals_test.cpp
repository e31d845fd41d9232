// `roughgas sweep` stopped by SIGINT or SIGTERM (src/cli/sweep_command.cpp): the running points stop
// at their next step and are dropped, the finished ones keep DIR/point_K/moments.csv, no sweep.csv
// is written, the exit status is 128 + the signal's number and stderr says which points finished.
// Without the handling the signal's default action kills the sweep (WIFSIGNALED), which fails both.
#include "../io/io_test_support.hpp"
#include "child_process.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <string>
#include <vector>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

// Elastic, perfectly rough grains (alpha = beta = 1): they keep their energy, so a point of 1e6
// collisions per particle is not beyond the reach of a cooling gas's temperature.
std::string cooling_case() {
    return "[run]\nparticles = 2000\nend = 1.0\noutput_every = 1.0\nseed = 9\n\n"
           "[[species]]\nname = \"grain\"\nmass = 1.0\nradius = 0.5\n\n"
           "[collision]\nmodel = \"constant\"\nalpha = 1.0\nbeta = 1.0\n";
}

// A sweep over run.end from `from` to 1e6 collisions per particle (two points, two threads: both
// run at once; a point of 1e6 takes minutes), signalled with `sig` once `ready()` holds.
template <class Ready>
test::Stopped sweep_and_signal(const test::ScratchDir& dir, const fs::path& out, const std::string& from,
                               int sig, Ready&& ready) {
    const fs::path f = dir.write("case.toml", cooling_case());
    return test::start_and_stop({"sweep", f.string(), "--param", "run.end=" + from + ":1.0e6:2", "--out",
                                 out.string(), "--threads", "2"},
                                sig, ready, dir);
}

TEST(SweepSignals, SigintKeepsTheFinishedPointsAndWritesNoSummary) {
    const test::ScratchDir dir;
    const fs::path out = dir / "out";
    // Point 0 (one collision per grain) ends at once; point 1 is still running when the signal comes.
    const test::Stopped e = sweep_and_signal(dir, out, "1.0", SIGINT,
                                             [&] { return fs::exists(out / "point_0" / "moments.csv"); });
    ASSERT_TRUE(WIFEXITED(e.status)) << e.status << "\n" << e.err;
    EXPECT_EQ(WEXITSTATUS(e.status), 128 + SIGINT) << e.err;
    EXPECT_NE(e.err.find("stopped by SIGINT: 1 of 2 points finished (point_K/moments.csv for K = 0)"),
              std::string::npos)
        << e.err;
    EXPECT_FALSE(fs::exists(out / "sweep.csv"));
    EXPECT_FALSE(fs::exists(out / "point_1"));
    // The finished point's file is whole: its header and both rows (t = 0 and one collision per grain).
    const std::string csv = test::read_file(out / "point_0" / "moments.csv");
    std::size_t rows = 0;
    for (std::size_t p = 0; (p = csv.find('\n', p)) != std::string::npos; ++p)
        if (p + 1 < csv.size() && csv[p + 1] != '#')
            ++rows;
    EXPECT_EQ(rows, 3u) << csv; // the column names and two rows
    // Nothing half-written is left behind (the CSV writer's temporary files).
    for (const auto& entry : fs::recursive_directory_iterator(out))
        EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST(SweepSignals, SigtermBeforeAnyPointEndsStopsThemAll) {
    const test::ScratchDir dir;
    const fs::path out = dir / "out";
    // The output directory exists once every point is validated, after the signals are taken over.
    const test::Stopped e = sweep_and_signal(dir, out, "1.0e6", SIGTERM, [&] { return fs::exists(out); });
    ASSERT_TRUE(WIFEXITED(e.status)) << e.status << "\n" << e.err;
    EXPECT_EQ(WEXITSTATUS(e.status), 128 + SIGTERM) << e.err;
    EXPECT_NE(e.err.find("stopped by SIGTERM: 0 of 2 points finished; no"), std::string::npos) << e.err;
    EXPECT_FALSE(fs::exists(out / "sweep.csv"));
    EXPECT_FALSE(fs::exists(out / "point_0"));
    EXPECT_FALSE(fs::exists(out / "point_1"));
}

} // namespace
} // namespace roughgas
