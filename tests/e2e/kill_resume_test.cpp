// End to end: real `roughgas run` processes killed with SIGKILL at random moments, or
// stopped with SIGTERM/SIGINT, then continued with `roughgas run --resume DIR` (on another thread
// count) give moments.csv, histograms.csv and steady.csv byte for byte as the run that was never
// interrupted. Cases: a rough cooling run with 3 replicas on 2 threads (one replica waits for a
// thread) and histograms, a shear run, a rough binary mixture with histograms, a spatially
// resolved box (with its cell fields: every HDF5 file and XDMF sidecar the same bytes), the box
// between walls, the box of smooth grains with its spectra.csv and modes.csv, a sheared box, and a
// cooling run, a shear run and a box clocked by time (run.end_time). The
// kill moments come from a seeded generator (printed on failure); no result depends on them.
#include "../io/io_test_support.hpp"
#include "child_process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

struct Scenario {
    std::string name;
    std::string case_text;
    std::string checkpoint_every;
};

std::string rough_cooling(int particles, double end) {
    std::ostringstream s;
    s << "[run]\nparticles = " << particles << "\nend = " << end
      << "\noutput_every = 1.0\nreplicas = 3\nseed = 11\nhistogram_every = " << end / 3
      << "\nhistogram_bins = 20\n\n[[species]]\nname = \"grain\"\nmass = 1.0\nradius = 0.5\n\n"
         "[collision]\nmodel = \"constant\"\nalpha = 0.8\nbeta = 0.3\n";
    return s.str();
}

// A spatially resolved box (positions in the checkpoint): rough grains, 2 replicas, 512 cells.
std::string box() {
    return "[run]\nparticles = 40000\nend = 30.0\noutput_every = 1.0\nreplicas = 2\ndensity = 0.02\nseed = 13\n\n"
           "[[species]]\nmass = 1.0\nradius = 0.5\n\n[collision]\nmodel = \"constant\"\nalpha = 0.8\nbeta = 0.3\n\n"
           "[domain]\nsize = [40.0, 40.0, 40.0]\ncells = [8, 8, 8]\n";
}

// The same with cell fields of both replicas at every third row.
std::string box_fields() { return box() + "\n[fields]\nevery = 3\nreplicas = 2\n"; }

// Between a diffuse wall at rest (below) and a rough one moving along x (above), under gravity: the
// flight's random emission and the walls' tallies (walls.csv) in the checkpoint too.
std::string box_walls() {
    return test::replaced(box(), "cells = [8, 8, 8]\n",
                        "cells = [8, 8, 8]\nboundary = [\"periodic\", \"walls\", \"periodic\"]\n"
                        "gravity = [0.0, -0.01, 0.0]\n\n"
                        "[wall_lower]\nkind = \"diffuse\"\ntemperature = 2.0\n\n"
                        "[wall_upper]\nkind = \"rough\"\nvelocity = [0.5, 0.0, 0.0]\nalpha = 0.9\nbeta = 0.5\n");
}

// Smooth grains in the box (spins that never change but move with their grains), with the spectra
// and modes (T_rot's amplitudes from the spins of each cell).
std::string box_smooth_spectra() {
    return test::replaced(box(), "beta = 0.3", "beta = -1.0") + "\n[spectra]\nmodes = 2\n";
}

// A sheared box (Lees-Edwards along y): the images' offset follows the time in the checkpoint.
std::string box_shear() {
    return "[run]\nkind = \"shear\"\nparticles = 40000\nend = 30.0\noutput_every = 1.0\nreplicas = 2\n"
           "density = 0.02\nseed = 13\n\n[[species]]\nmass = 1.0\nradius = 0.5\ntemperature = 0.01\n"
           "rotational_temperature = 0.002\n\n[collision]\nmodel = \"constant\"\nalpha = 0.9\nbeta = 0.0\n\n"
           "[shear]\nrate = 0.01\n\n[domain]\nsize = [45.0, 45.0, 45.0]\ncells = [4, 16, 4]\n";
}

std::string shear() {
    return "[run]\nkind = \"shear\"\nparticles = 10000\nend = 30.0\noutput_every = 1.0\nreplicas = 2\nseed = "
           "5\n\n"
           "[[species]]\nname = \"grain\"\nmass = 1.0\nradius = 0.5\n\n[collision]\nmodel = \"constant\"\n"
           "alpha = 0.9\nbeta = 0.0\n\n[shear]\nrate = 1.0\n";
}

std::string rough_mixture() {
    return "[run]\nparticles = 10000\nend = 30.0\noutput_every = 0.5\noutput_spacing = \"log\"\nreplicas = "
           "2\n"
           "seed = 2\ndensity = 0.002\nhistogram_every = 10.0\nhistogram_bins = 16\n\n"
           "[[species]]\nname = \"small\"\nmass = 1.0\nradius = 0.5\nfraction = 0.5\n\n"
           "[[species]]\nname = \"large\"\nmass = 8.0\nradius = 1.0\nfraction = 0.5\n\n"
           "[collision]\nmodel = \"constant\"\nalpha = 0.9\nbeta = 0.5\n\n"
           "[[pair]]\nspecies = [\"large\", \"large\"]\nalpha = 0.8\nbeta = 0.0\n";
}

// The time clock (run.end_time): rows at times, the stretches between them run towards a time; 4
// groups, so that the grouped engine's time stops are in the checkpoints too.
std::string rough_cooling_time_clock() {
    return "[run]\nparticles = 20000\ngroups = 4\nend_time = 5.0\noutput_every_time = 0.1\nreplicas = 3\n"
           "seed = 11\nhistogram_every_time = 2.5\nhistogram_bins = 20\n\n[[species]]\nname = \"grain\"\n"
           "mass = 1.0\nradius = 0.5\n\n[collision]\nmodel = \"constant\"\nalpha = 0.8\nbeta = 0.3\n";
}

// The shear flow by time: Strang steps, the last before each row shortened to end at its t (about
// 30 collisions per particle by t = 8).
std::string shear_time_clock() {
    return test::replaced(shear(), "end = 30.0\noutput_every = 1.0\n", "end_time = 8.0\noutput_every_time = 0.25\n");
}

// The box by time: steps that end at the rows' times.
std::string box_time_clock() {
    return test::replaced(box(), "end = 30.0\noutput_every = 1.0\n", "end_time = 200.0\noutput_every_time = 8.0\n");
}

// `roughgas run ...` to completion (stdout and stderr in `dir`).
void run_to_end(const std::string& args, const test::ScratchDir& dir) {
    const test::CommandResult r = test::run_roughgas(args + " --quiet", dir);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.err;
}

void expect_same_outputs(const fs::path& reference, const fs::path& out, const std::string& context) {
    for (const char* f : {"moments.csv", "histograms.csv", "steady.csv", "walls.csv", "profiles.csv", "spectra.csv",
                          "modes.csv"}) {
        ASSERT_EQ(fs::exists(reference / f), fs::exists(out / f)) << f << ", " << context;
        if (!fs::exists(reference / f))
            continue;
        const std::string a = test::read_file(reference / f), b = test::read_file(out / f);
        EXPECT_FALSE(a.empty());
        EXPECT_TRUE(a == b) << f << " differs from the uninterrupted run, " << context;
    }
    for (const auto& e : fs::recursive_directory_iterator(out)) // no temporary left behind
        EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
    // Each replica's own rows (replicas > 1): the same files, the same bytes.
    ASSERT_EQ(fs::exists(reference / "replicas"), fs::exists(out / "replicas")) << context;
    if (fs::exists(reference / "replicas")) {
        const auto names = [](const fs::path& d) {
            std::vector<std::string> v;
            for (const auto& e : fs::directory_iterator(d))
                v.push_back(e.path().filename().string());
            std::sort(v.begin(), v.end());
            return v;
        };
        const std::vector<std::string> files = names(reference / "replicas");
        ASSERT_EQ(files, names(out / "replicas")) << context;
        for (const std::string& f : files)
            EXPECT_TRUE(test::read_file(reference / "replicas" / f) == test::read_file(out / "replicas" / f))
                << f << " differs from the uninterrupted run, " << context;
    }
    // The cell fields: the same files, the same bytes.
    if (fs::exists(reference / "fields") || fs::exists(out / "fields")) {
        const auto files = [](const fs::path& root) {
            std::vector<std::string> names;
            for (const auto& e : fs::recursive_directory_iterator(root / "fields"))
                if (e.is_regular_file())
                    names.push_back(fs::relative(e.path(), root).string());
            std::sort(names.begin(), names.end());
            return names;
        };
        const std::vector<std::string> names = files(reference);
        ASSERT_EQ(names, files(out)) << context;
        for (const std::string& n : names)
            EXPECT_TRUE(test::read_file(reference / n) == test::read_file(out / n))
                << n << " differs from the uninterrupted run, " << context;
    }
}

bool any_replica_file(const fs::path& out) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(out / "checkpoint", ec))
        if (e.path().filename().string().starts_with("replica_"))
            return true;
    return false;
}

void sleep_ms(int ms) {
    struct timespec t {
        ms / 1000, (ms % 1000) * 1000000L
    };
    nanosleep(&t, nullptr);
}

// A SIGKILL at a moment that depends on `when`: 0 as soon as the run exists (run.bin: before any
// replica state, or about then), else `when` ms after the first replica state. Returns the status.
int start_and_kill(const std::vector<std::string>& args, const fs::path& out, int when,
                   const test::ScratchDir& dir) {
    test::ChildProcess child(args, dir / "child_out.txt", dir / "child_err.txt");
    const bool started = test::wait_until(child, [&] {
        return when == 0 ? fs::exists(out / "checkpoint" / "run.bin") : any_replica_file(out);
    });
    EXPECT_TRUE(started) << test::read_file(dir / "child_err.txt");
    if (when > 0)
        sleep_ms(when);
    child.signal(SIGKILL);
    return child.wait();
}

class KillAndResume : public ::testing::TestWithParam<Scenario> {};

TEST_P(KillAndResume, ResumedRunIsByteIdenticalToTheUninterruptedOne) {
    const Scenario& s = GetParam();
    const test::ScratchDir dir;
    const fs::path f = dir.write("case.toml", s.case_text);
    const fs::path reference = dir / "reference";
    run_to_end("run '" + f.string() + "' --out '" + reference.string() + "' --threads 2", dir);

    const unsigned seed = 20261122u + static_cast<unsigned>(s.name.size());
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> delay(1, 400);
    for (int k = 0; k < 4; ++k) {
        const fs::path out = dir / ("kill" + std::to_string(k));
        const int when = k == 0 ? 0 : delay(rng);
        const std::string context = "kill " + std::to_string(k) + " at " + std::to_string(when) +
                                    " ms (seed " + std::to_string(seed) + ")";
        const int status = start_and_kill({"run", f.string(), "--out", out.string(), "--quiet", "--threads",
                                           "2", "--checkpoint-every", s.checkpoint_every},
                                          out, when, dir);
        // Killed, or (on a fast machine) finished just before the kill.
        EXPECT_TRUE((WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) ||
                    (WIFEXITED(status) && WEXITSTATUS(status) == 0))
            << context;
        if (k == 1) { // the resumed run killed too, at a random moment of its own
            test::ChildProcess again({"run", "--resume", out.string(), "--quiet", "--threads", "1"},
                                     dir / "child_out.txt", dir / "child_err.txt");
            sleep_ms(delay(rng));
            again.signal(SIGKILL);
            again.wait();
        }
        run_to_end("run --resume '" + out.string() + "' --threads 1", dir);
        expect_same_outputs(reference, out, context);
    }
}

INSTANTIATE_TEST_SUITE_P(
    E2e, KillAndResume,
    ::testing::Values(Scenario{"RoughCooling3Replicas", rough_cooling(20000, 40.0), "1.5"},
                      Scenario{"Shear", shear(), "1"}, Scenario{"RoughMixture", rough_mixture(), "2"},
                      Scenario{"Box", box_fields(), "2"}, Scenario{"BoxWalls", box_walls(), "2"},
                      Scenario{"BoxSmoothSpectra", box_smooth_spectra(), "2"},
                      Scenario{"BoxShear", box_shear(), "2"},
                      Scenario{"RoughCoolingTimeClock", rough_cooling_time_clock(), "1.5"},
                      Scenario{"ShearTimeClock", shear_time_clock(), "1"},
                      Scenario{"BoxTimeClock", box_time_clock(), "2"}),
    [](const ::testing::TestParamInfo<Scenario>& info) { return info.param.name; });

// Every line after the '#' lines has as many cells as the header: a CSV that a reader takes as is.
std::size_t valid_rows(const fs::path& csv) {
    std::istringstream in(test::read_file(csv));
    std::size_t header = 0, rows = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with("#"))
            continue;
        const std::size_t cells = static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1;
        if (header == 0)
            header = cells;
        else {
            EXPECT_EQ(cells, header) << line;
            ++rows;
        }
    }
    EXPECT_GT(header, 1u) << csv;
    return rows;
}

// A file of a stopped run holds whole lines of the uninterrupted run's file, from its start: the
// same header and the first rows. Returns its rows (lines after the '#' lines and the header).
std::size_t expect_prefix(const fs::path& reference, const fs::path& file) {
    const std::string a = test::read_file(reference), b = test::read_file(file);
    EXPECT_TRUE(!b.empty() && b.back() == '\n' && a.compare(0, b.size(), b) == 0)
        << file << " is not a beginning of " << reference;
    return valid_rows(file);
}

TEST(Signals, SigtermAndSigintCheckpointWriteTheCsvSoFarAndExitNonZero) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("case.toml", rough_cooling(10000, 150.0));
    const fs::path reference = dir / "reference";
    run_to_end("run '" + f.string() + "' --out '" + reference.string() + "' --threads 2", dir);
    const auto run_args = [&](const fs::path& out, bool checkpoints) {
        std::vector<std::string> a{"run", f.string(), "--out", out.string(), "--quiet", "--threads", "2"};
        if (checkpoints)
            a.insert(a.end(), {"--checkpoint-every", "1.5"});
        return a;
    };

    { // SIGTERM with --checkpoint-every: replicas 0 and 1 run, replica 2 waits for a thread. The
      // signal waits for a state of both running replicas: on a loaded machine the second thread
      // may start its replica late, and a replica the signal finds not yet started is skipped
      // (it starts afresh on resume, as replica 2 does).
        const fs::path out = dir / "sigterm";
        const test::Stopped s = test::start_and_stop(
            run_args(out, true), SIGTERM,
            [&] {
                return fs::exists(out / "checkpoint" / "replica_0.bin") &&
                       fs::exists(out / "checkpoint" / "replica_1.bin");
            },
            dir);
        ASSERT_TRUE(WIFEXITED(s.status)) << s.err;
        EXPECT_EQ(WEXITSTATUS(s.status), 143) << s.err;
        EXPECT_NE(s.err.find("stopped by SIGTERM"), std::string::npos) << s.err;
        EXPECT_NE(s.err.find("continue with: roughgas run --resume " + out.string()), std::string::npos)
            << s.err;
        EXPECT_EQ(valid_rows(out / "moments.csv"), 0u); // no row is complete without replica 2
        // ... but the running replicas' own files show their rows so far.
        for (const char* file : {"moments_0.csv", "moments_1.csv"})
            EXPECT_GE(expect_prefix(reference / "replicas" / file, out / "replicas" / file), 1u) << file;
        for (const char* file : {"run.bin", "replica_0.bin", "replica_1.bin"})
            EXPECT_TRUE(fs::exists(out / "checkpoint" / file)) << file;
        EXPECT_FALSE(fs::exists(out / "checkpoint" / "replica_2.bin")); // never started: starts afresh
        run_to_end("run --resume '" + out.string() + "' --threads 1", dir);
        expect_same_outputs(reference, out, "SIGTERM");
    }
    { // SIGINT without --checkpoint-every: a checkpoint all the same, and the complete rows
        const fs::path out = dir / "sigint";
        const test::Stopped s = test::start_and_stop(
            run_args(out, false), SIGINT, [&] { return fs::exists(out / "moments.csv"); }, dir);
        ASSERT_TRUE(WIFEXITED(s.status)) << s.err;
        EXPECT_EQ(WEXITSTATUS(s.status), 130) << s.err;
        EXPECT_NE(s.err.find("stopped by SIGINT"), std::string::npos) << s.err;
        EXPECT_TRUE(fs::exists(out / "checkpoint" / "run.bin"));
        EXPECT_TRUE(any_replica_file(out));
        const std::size_t rows = valid_rows(out / "moments.csv");
        EXPECT_GE(rows, 1u);   // t = 0 at least: the signal came once the file existed
        EXPECT_LT(rows, 151u); // not all: the run stopped
        run_to_end("run --resume '" + out.string() + "' --threads 2", dir);
        expect_same_outputs(reference, out, "SIGINT");
    }
    { // SIGKILL: no chance to write anything more; the replicas' files hold what they had reached
        const fs::path out = dir / "sigkill";
        test::ChildProcess child(run_args(out, true), dir / "child_out.txt", dir / "child_err.txt");
        const fs::path first = out / "replicas" / "moments_0.csv";
        ASSERT_TRUE(test::wait_until(child, [&] { return fs::exists(first) && valid_rows(first) >= 3; }))
            << test::read_file(dir / "child_err.txt");
        child.signal(SIGKILL);
        child.wait();
        EXPECT_GE(expect_prefix(reference / "replicas" / "moments_0.csv", first), 3u);
        run_to_end("run --resume '" + out.string() + "' --threads 2", dir);
        expect_same_outputs(reference, out, "SIGKILL");
    }
    { // SIGTERM twice: the second ends the process at once (or it had already stopped): resumable
        const fs::path out = dir / "twice";
        const test::Stopped s = test::start_and_stop(
            run_args(out, true), SIGTERM, [&] { return any_replica_file(out); }, dir, true);
        EXPECT_TRUE((WIFSIGNALED(s.status) && WTERMSIG(s.status) == SIGTERM) ||
                    (WIFEXITED(s.status) && WEXITSTATUS(s.status) == 143))
            << s.err;
        run_to_end("run --resume '" + out.string() + "' --threads 2", dir);
        expect_same_outputs(reference, out, "SIGTERM twice");
    }
}

} // namespace
} // namespace roughgas
