// initial.from of a homogeneous run (no [domain]; io/run_states.cpp, dsmc/init.hpp init_from_state):
// a run that saved its grains (run.save_state) starts a second run whose row at t = 0 is the saved
// gas's last row (the same grains, the mean velocity removed: equal to round-off); replica r takes
// the file of replica r modulo the files; a box's state starts a homogeneous run with its velocities
// and spins; what does not fit is refused before any work (exit 2, naming initial.from), and so is
// a cooling run past the state's own reach of the floating-point floor; and a cooling gas continued
// from its own state cools on as the run that never stopped. Box runs from
// saved states: tests/io/box_cli_test.cpp.
#include "io_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace roughgas {
namespace {

namespace fs = std::filesystem;
using test::replaced;

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

// Rough grains, alpha = 0.8, beta = 0.4, n = 1, T0 = 1: about 7 collisions per particle per unit
// time at the start.
std::string cooling_case(int particles, int replicas, double end_time) {
    return "[run]\nparticles = " + std::to_string(particles) + "\nend_time = " + std::to_string(end_time) +
           "\noutput_every_time = " + std::to_string(end_time / 10) + "\nreplicas = " + std::to_string(replicas) +
           "\nseed = 7\n\n[[species]]\nname = \"grain\"\nmass = 1.0\nradius = 0.5\n\n[collision]\n"
           "model = \"constant\"\nalpha = 0.8\nbeta = 0.4\n";
}

std::string saving(const std::string& c) { return replaced(c, "seed = 7\n", "seed = 7\nsave_state = true\n"); }
std::string from(const std::string& c, const fs::path& dir) {
    return replaced(c, "seed = 7\n", "seed = 9\n") + "\n[initial]\nfrom = " + q(dir) + "\n";
}

// The first row of `started` is the last row of `saved`, column by column, to round-off.
void expect_starts_where_it_ended(const fs::path& saved, const fs::path& started, const std::string& what) {
    const auto s = test::read_csv(saved), b = test::read_csv(started);
    EXPECT_EQ(b.at("t").front(), 0.0) << what;
    EXPECT_EQ(b.at("coll_per_particle").front(), 0.0) << what;
    for (const char* col : {"T_tr", "T_rot", "theta", "a20", "a02", "a11"})
        EXPECT_NEAR(b.at(col).front() / s.at(col).back(), 1.0, 1e-12) << what << ": " << col;
}

TEST(InitialState, AHomogeneousRunStartsFromTheSavedGas) {
    const test::ScratchDir dir;
    const std::string c = cooling_case(3000, 1, 0.5);
    const fs::path prepare = dir.write("prepare.toml", saving(c));
    ASSERT_EQ(test::run_roughgas("run " + q(prepare) + " --quiet --out " + q(dir / "hot"), dir).status, 0);
    ASSERT_TRUE(fs::exists(dir / "hot" / "state" / "replica_0.bin"));
    const fs::path start = dir.write("start.toml", from(c, dir / "hot"));
    const test::CommandResult r = test::run_roughgas("run " + q(start) + " --out " + q(dir / "run"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("initial state: the grains of"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("time and collisions count from 0"), std::string::npos) << r.err;
    // The provenance of the rows says so too.
    EXPECT_NE(test::read_file(dir / "run" / "moments.csv").find("# initial state: the grains of"), std::string::npos);
    expect_starts_where_it_ended(dir / "hot" / "moments.csv", dir / "run" / "moments.csv", "homogeneous");
    const auto m = test::read_csv(dir / "run" / "moments.csv");
    EXPECT_LT(m.at("T_tr").back(), 0.8 * m.at("T_tr").front()); // and it cools on
    // `check` plans the same start.
    EXPECT_EQ(test::run_roughgas("check " + q(start), dir).status, 0);
}

// Replica r of the new run starts from the file of replica r modulo the files: 3 replicas from 2.
TEST(InitialState, ReplicaRTakesFileRModuloTheFiles) {
    const test::ScratchDir dir;
    const std::string two = cooling_case(2000, 2, 0.3);
    const fs::path prepare = dir.write("prepare.toml", saving(two));
    ASSERT_EQ(test::run_roughgas("run " + q(prepare) + " --quiet --out " + q(dir / "two"), dir).status, 0);
    const fs::path start = dir.write("start.toml", from(replaced(two, "replicas = 2", "replicas = 3"), dir / "two"));
    const test::CommandResult r = test::run_roughgas("run " + q(start) + " --out " + q(dir / "three"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("2 files, replica r takes file r mod 2"), std::string::npos) << r.err;
    for (const int k : {0, 1, 2}) {
        const std::string saved = "moments_" + std::to_string(k % 2) + ".csv";
        const std::string started = "moments_" + std::to_string(k) + ".csv";
        expect_starts_where_it_ended(dir / "two" / "replicas" / saved, dir / "three" / "replicas" / started,
                                     "replica " + std::to_string(k));
    }
    // Replicas 0 and 2 start from the same grains and go on with their own streams.
    const auto a = test::read_csv(dir / "three" / "replicas" / "moments_0.csv");
    const auto b = test::read_csv(dir / "three" / "replicas" / "moments_2.csv");
    EXPECT_EQ(a.at("T_tr").front(), b.at("T_tr").front());
    EXPECT_NE(a.at("T_tr").back(), b.at("T_tr").back());
}

// A box's state starts a homogeneous run: its velocities and spins, its positions not used.
TEST(InitialState, ABoxsStateStartsAHomogeneousRun) {
    const test::ScratchDir dir;
    const std::string box = saving(cooling_case(3000, 1, 20.0)) +
                            "\n[domain]\nsize = [50.0, 50.0, 50.0]\ncells = [5, 5, 5]\n";
    const fs::path prepare = dir.write("box.toml", replaced(box, "[run]\n", "[run]\ndensity = 0.02\n"));
    const test::CommandResult b = test::run_roughgas("run " + q(prepare) + " --quiet --out " + q(dir / "box"), dir);
    ASSERT_EQ(b.status, 0) << b.err;
    const fs::path start = dir.write("start.toml", from(cooling_case(3000, 1, 0.5), dir / "box"));
    const test::CommandResult r = test::run_roughgas("run " + q(start) + " --out " + q(dir / "run"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("velocities and spins only (the homogeneous gas has no positions)"), std::string::npos)
        << r.err;
    expect_starts_where_it_ended(dir / "box" / "moments.csv", dir / "run" / "moments.csv", "from a box");
}

// Refused before any work (exit 2, nothing written), by `run` and `check`: another grain count,
// a directory without states, the Maxwell kernel (its rates come from the species' temperatures).
TEST(InitialState, WhatDoesNotFitIsRefused) {
    const test::ScratchDir dir;
    const std::string c = cooling_case(2000, 1, 0.3);
    const fs::path prepare = dir.write("prepare.toml", saving(c));
    ASSERT_EQ(test::run_roughgas("run " + q(prepare) + " --quiet --out " + q(dir / "saved"), dir).status, 0);
    const struct {
        std::string text, says;
    } bad[] = {
        {from(replaced(c, "particles = 2000", "particles = 2001"), dir / "saved"), "2000 grains"},
        {from(c, dir / "nowhere"), "no "},
        {replaced(from(c, dir / "saved"), "seed = 9\n", "seed = 9\nkernel = \"maxwell\"\n"),
         "run.kernel = \"maxwell\""},
    };
    for (const auto& x : bad) {
        const fs::path f = dir.write("bad.toml", x.text);
        for (const std::string& cmd : {"run " + q(f) + " --out " + q(dir / "out"), "check " + q(f)}) {
            const test::CommandResult e = test::run_roughgas(cmd, dir);
            EXPECT_EQ(e.status, 2) << cmd << "\n" << e.err;
            EXPECT_NE(e.err.find("initial.from"), std::string::npos) << e.err;
            EXPECT_NE(e.err.find(x.says), std::string::npos) << e.err;
            EXPECT_FALSE(fs::exists(dir / "out"));
        }
    }
}

// A cooling gas started from a state cools from the state's temperatures: its end is checked against
// the state's own reach of T_tr/m = 1e-300 (replica 0's), before any work, by `run` and `check`.
TEST(InitialState, ACoolingRunFromAStateIsRefusedPastTheStatesReach) {
    const test::ScratchDir dir;
    const std::string c = replaced(cooling_case(2000, 1, 0.3), "alpha = 0.8", "alpha = 0.5");
    const fs::path prepare = dir.write("prepare.toml", saving(c));
    ASSERT_EQ(test::run_roughgas("run " + q(prepare) + " --quiet --out " + q(dir / "saved"), dir).status, 0);
    const fs::path f = dir.write("from.toml", from(c, dir / "saved"));
    const std::string far = " --set run.end_time=1e200 --set run.output_spacing=log";
    for (const std::string& cmd : {"check " + q(f) + far, "run " + q(f) + far + " --out " + q(dir / "out")}) {
        const test::CommandResult r = test::run_roughgas(cmd, dir);
        EXPECT_EQ(r.status, 2) << cmd << "\n" << r.err;
        EXPECT_NE(r.err.find("the state of initial.from"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("reaches T_tr/m = 1e-300"), std::string::npos) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "out"));
}

// A cooling gas saved at t = 0.5 and continued to t = 1 cools on as one run to t = 1: T_tr and
// theta at the end agree within 4.5 combined errors of 16 replicas of 1250 grains each way
// (Student's t of 15 degrees of freedom: a false alarm about one time in 2500 per column).
TEST(InitialState, ACoolingGasContinuedFromItsStateCoolsOnAsOneRun) {
    const test::ScratchDir dir;
    const std::string half = cooling_case(1250, 16, 0.5);
    const fs::path prepare = dir.write("prepare.toml", saving(half));
    ASSERT_EQ(test::run_roughgas("run " + q(prepare) + " --quiet --out " + q(dir / "first"), dir).status, 0);
    const fs::path start = dir.write("start.toml", from(half, dir / "first"));
    ASSERT_EQ(test::run_roughgas("run " + q(start) + " --quiet --out " + q(dir / "second"), dir).status, 0);
    const fs::path whole = dir.write(
        "whole.toml", replaced(replaced(half, "end_time = 0.500000", "end_time = 1.000000"), "seed = 7", "seed = 11"));
    ASSERT_EQ(test::run_roughgas("run " + q(whole) + " --quiet --out " + q(dir / "whole"), dir).status, 0);
    const auto s = test::read_csv(dir / "second" / "moments.csv"), w = test::read_csv(dir / "whole" / "moments.csv");
    EXPECT_NEAR(w.at("t").back(), 1.0, 1e-12);
    EXPECT_NEAR(s.at("t").back(), 0.5, 1e-12);
    for (const char* col : {"T_tr", "theta"}) {
        const double err = std::hypot(s.at(std::string(col) + "_err").back(), w.at(std::string(col) + "_err").back());
        EXPECT_NEAR(s.at(col).back(), w.at(col).back(), 4.5 * err) << col;
    }
}

} // namespace
} // namespace roughgas
