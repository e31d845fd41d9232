// The time clock (run.end_time, run.output_every_time, run.histogram_every_time): rows of every
// replica, and of runs started at other temperatures, at the requested times t; homogeneous, shear
// and box runs; checkpoints that change no byte; the switch of a case's clock with --set; and the
// refusals of a case with both clocks, neither, or the other clock's output keys (run and check).
// Killed and resumed time-clocked runs: tests/e2e/kill_resume_test.cpp.
#include "io_test_support.hpp"

#include "roughgas/observables/theory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace roughgas {
namespace {

namespace fs = std::filesystem;
using test::replaced;

// Rough grains, alpha = 0.8, beta = 0.4, n = 1, sigma = 1, T0 = 1: about 7 collisions per particle
// per unit time at the start, so end_time = 0.5 is some 3 collisions per particle.
std::string cooling_case(int replicas = 3) {
    return "[run]\nparticles = 2000\nend_time = 0.5\noutput_every_time = 0.05\noutput_spacing = \"log\"\n"
           "replicas = " + std::to_string(replicas) + "\nseed = 7\n\n[[species]]\nname = \"grain\"\nmass = 1.0\n"
           "radius = 0.5\n\n[collision]\nmodel = \"constant\"\nalpha = 0.8\nbeta = 0.4\n";
}

std::string shear_case() {
    return "[run]\nkind = \"shear\"\nparticles = 2000\nend_time = 0.5\noutput_every_time = 0.1\nreplicas = 2\n"
           "seed = 3\n\n[[species]]\nname = \"grain\"\nmass = 1.0\nradius = 0.5\n\n[collision]\n"
           "model = \"constant\"\nalpha = 0.9\nbeta = 0.0\n\n[shear]\nrate = 1.0\n";
}

// A box of 8 cells of 10 (the mean free path at n = 0.02 is 11): ~0.14 collisions per particle per
// unit time.
std::string box_case() {
    return "[run]\nparticles = 4000\nend_time = 20.0\noutput_every_time = 4.0\nreplicas = 2\ndensity = 0.02\n"
           "seed = 5\n\n[[species]]\nmass = 1.0\nradius = 0.5\n\n[collision]\nmodel = \"constant\"\n"
           "alpha = 0.8\nbeta = 0.3\n\n[domain]\nsize = [20.0, 20.0, 20.0]\ncells = [2, 2, 2]\n";
}

std::string run_args(const fs::path& f, const fs::path& out, const std::string& extra = "") {
    return "run '" + f.string() + "' --out '" + out.string() + "' --quiet " + extra;
}

// 0, then every * 10^(k/10) below the end (log) or every * (k + 1) (linear), then the end.
std::vector<double> times(double every, double end, bool log) {
    std::vector<double> t{0.0};
    for (int k = 0;; ++k) {
        const double x = log ? every * std::pow(10.0, k / 10.0) : every * (k + 1);
        if (!(x < end * (1 - 1e-9)))
            break;
        t.push_back(x);
    }
    t.push_back(end);
    return t;
}

void expect_times(const std::vector<double>& got, const std::vector<double>& want, const std::string& what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (std::size_t k = 0; k < want.size(); ++k)
        EXPECT_NEAR(got[k], want[k], 1e-12 * want.back()) << what << ", row " << k;
}

TEST(TimeClock, RowsFallAtTheRequestedTimesInEveryReplica) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("case.toml", cooling_case()), out = dir / "out";
    const test::CommandResult r = run_roughgas(run_args(f, out), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::vector<double> want = times(0.05, 0.5, true);
    const auto m = test::read_csv(out / "moments.csv");
    expect_times(m.at("t"), want, "moments.csv");
    EXPECT_EQ(m.at("t").back(), 0.5);
    // Each replica's rows at the same t, each with its own collision count.
    std::vector<std::vector<double>> counts;
    for (int k = 0; k < 3; ++k) {
        const auto rep = test::read_csv(out / "replicas" / ("moments_" + std::to_string(k) + ".csv"));
        ASSERT_EQ(rep.at("t").size(), want.size());
        for (std::size_t j = 0; j < want.size(); ++j)
            EXPECT_EQ(rep.at("t")[j], m.at("t")[j]) << "replica " << k << ", row " << j;
        counts.push_back(rep.at("coll_per_particle"));
    }
    EXPECT_NE(counts[0].back(), counts[1].back());
    EXPECT_GT(m.at("coll_per_particle").back(), 2.0); // about 3.5 collisions per particle by t = 0.5
    EXPECT_LT(m.at("coll_per_particle").back(), 5.0);
    // The resolved case's [run] in the header keeps the time clock's keys, and none of the other's.
    const std::string text = test::read_file(out / "moments.csv");
    const std::size_t from = text.find("# [run]\n");
    ASSERT_NE(from, std::string::npos) << text.substr(0, 2000);
    const std::string run = text.substr(from, text.find("#\n", from) - from);
    EXPECT_NE(run.find("# end_time = 0.5\n"), std::string::npos) << run;
    EXPECT_NE(run.find("# output_every_time = 0.05\n"), std::string::npos) << run;
    for (const char* key : {"# end = ", "# output_every = ", "# histogram_every = "})
        EXPECT_EQ(run.find(key), std::string::npos) << key << "\n" << run;
    EXPECT_NE(text.find("time clock (run.end_time)"), std::string::npos);
}

// Where the run pauses for its rows does not change its trajectory: the collisions stop at a row's t
// and go on with the same pending candidate, in the grouped engine (4 groups) as in the plain one,
// so the row at t = 0.5 is the same with rows every 0.1 or every 0.25.
TEST(TimeClock, OutputTimesDoNotChangeTheTrajectory) {
    const test::ScratchDir dir;
    for (const char* groups : {"0", "4"}) {
        const fs::path f = dir.write(std::string("g") + groups + ".toml",
                                     replaced(replaced(cooling_case(1), "particles = 2000\n",
                                                       std::string("particles = 20000\ngroups = ") + groups + "\n"),
                                              "output_spacing = \"log\"\n", ""));
        const fs::path a = dir / (std::string("a") + groups), b = dir / (std::string("b") + groups);
        ASSERT_EQ(run_roughgas(run_args(f, a, "--set run.output_every_time=0.1"), dir).status, 0);
        ASSERT_EQ(run_roughgas(run_args(f, b, "--set run.output_every_time=0.25"), dir).status, 0);
        const auto ma = test::read_csv(a / "moments.csv"), mb = test::read_csv(b / "moments.csv");
        ASSERT_EQ(ma.at("t").size(), 6u) << groups;
        ASSERT_EQ(mb.at("t").size(), 3u) << groups;
        for (const char* c : {"t", "coll_per_particle", "T_tr", "T_rot", "a20", "a02", "a11"}) {
            EXPECT_EQ(ma.at(c).back(), mb.at(c).back()) << c << ", groups = " << groups;
            EXPECT_NE(ma.at(c)[3], mb.at(c)[1]) << c << ", groups = " << groups; // t = 0.3 is not t = 0.25
        }
    }
}

// A hot and a cold start of the same gas: rows at the same t, the hot gas colliding more often.
TEST(TimeClock, HotAndColdStartsShareTheirRowTimes) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("case.toml", cooling_case(1));
    ASSERT_EQ(run_roughgas(run_args(f, dir / "cold"), dir).status, 0);
    const test::CommandResult hot =
        run_roughgas(run_args(f, dir / "hot", "--set species.0.temperature=4.0"), dir);
    ASSERT_EQ(hot.status, 0) << hot.err;
    const auto c = test::read_csv(dir / "cold" / "moments.csv"), h = test::read_csv(dir / "hot" / "moments.csv");
    ASSERT_EQ(c.at("t").size(), h.at("t").size());
    for (std::size_t k = 0; k < c.at("t").size(); ++k)
        EXPECT_EQ(c.at("t")[k], h.at("t")[k]) << "row " << k;
    // The collision rate grows as sqrt(T): the hot gas (T = 4) collides more often by t = 0.5.
    EXPECT_GT(h.at("coll_per_particle").back(), 1.3 * c.at("coll_per_particle").back());
    EXPECT_GT(h.at("T_tr").back(), c.at("T_tr").back());
}

// The theory columns are the integrated Maxwellian theory from each run's own start, taken at the
// rows' t, which the time clock makes the requested times: the hot start's theory is the cold one's
// shifted along Haff's curve, not the same numbers; the measured T_tr follows its own.
TEST(TimeClock, TheoryColumnsAtTheRequestedTimes) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("case.toml", replaced(cooling_case(4), "particles = 2000\n", "particles = 5000\n"));
    ASSERT_EQ(run_roughgas(run_args(f, dir / "cold"), dir).status, 0);
    ASSERT_EQ(run_roughgas(run_args(f, dir / "hot", "--set species.0.temperature=4.0"), dir).status, 0);
    const std::vector<double> want = times(0.05, 0.5, true);
    for (const auto& [name, T0] : {std::pair{"cold", 1.0}, std::pair{"hot", 4.0}}) {
        const auto m = test::read_csv(dir / name / "moments.csv");
        expect_times(m.at("t"), want, name);
        // mass, radius, inertia, fraction; alpha, beta; n = 1; T_rot = 1 in both.
        HcsTrajectory th(HcsTheory({{1.0, 0.5, 0.4, 1.0}}, {{0.8, 0.4}}, 1.0), {{T0}, {1.0}});
        for (std::size_t k = 0; k < want.size(); ++k) {
            const HcsTemperatures T = th.at(want[k]);
            EXPECT_NEAR(m.at("T_tr_theory")[k], T.T_tr[0], 1e-12 * T.T_tr[0]) << name << ", row " << k;
            EXPECT_NEAR(m.at("T_rot_theory")[k], T.T_rot[0], 1e-12 * T.T_rot[0]) << name << ", row " << k;
            EXPECT_NEAR(m.at("theta_theory")[k], T.T_rot[0] / T.T_tr[0], 1e-12) << name << ", row " << k;
            // The DSMC against it: 4 x 5000 grains, T_tr within 5 standard errors.
            EXPECT_NEAR(m.at("T_tr")[k], T.T_tr[0], 5 * m.at("T_tr_err")[k] + 1e-12) << name << ", row " << k;
        }
        EXPECT_LT(m.at("T_tr_theory").back(), 0.7 * T0); // the gas has cooled by the end
    }
    EXPECT_GT(test::read_csv(dir / "hot" / "moments.csv").at("T_tr_theory").back(),
              1.5 * test::read_csv(dir / "cold" / "moments.csv").at("T_tr_theory").back());
}

TEST(TimeClock, ShearAndBoxRowsFallAtTheRequestedTimes) {
    const test::ScratchDir dir;
    for (const auto& [name, text, every, end] :
         {std::tuple{"shear", shear_case(), 0.1, 0.5}, std::tuple{"box", box_case(), 4.0, 20.0}}) {
        const fs::path f = dir.write(std::string(name) + ".toml", text), out = dir / name;
        const test::CommandResult r = run_roughgas(run_args(f, out), dir);
        ASSERT_EQ(r.status, 0) << name << "\n" << r.err;
        const auto m = test::read_csv(out / "moments.csv");
        expect_times(m.at("t"), times(every, end, false), name);
        for (int k = 0; k < 2; ++k)
            EXPECT_EQ(test::read_csv(out / "replicas" / ("moments_" + std::to_string(k) + ".csv")).at("t").back(),
                      end)
                << name << " replica " << k;
        EXPECT_GT(m.at("coll_per_particle").back(), 0.5) << name;
    }
}

// Checkpoints taken every 0.3 collisions per particle (the work, whatever the clock) and a resume
// of the finished run change no byte; histograms at times included.
TEST(TimeClock, CheckpointsChangeNoOutputByte) {
    const test::ScratchDir dir;
    const std::string cooling = cooling_case(2) + "\n";
    for (const auto& [name, text] :
         {std::pair{"cooling", replaced(cooling, "seed = 7\n", "seed = 7\nhistogram_every_time = 0.25\n"
                                                               "histogram_bins = 10\n")},
          std::pair{"shear", shear_case()}, std::pair{"box", box_case()}}) {
        const fs::path f = dir.write(std::string(name) + ".toml", text);
        const fs::path plain = dir / (std::string(name) + "_plain"), ck = dir / (std::string(name) + "_ck");
        ASSERT_EQ(run_roughgas(run_args(f, plain), dir).status, 0) << name;
        const test::CommandResult r = run_roughgas(run_args(f, ck, "--checkpoint-every 0.3 --threads 2"), dir);
        ASSERT_EQ(r.status, 0) << r.err;
        for (const char* file : {"moments.csv", "histograms.csv"}) {
            ASSERT_EQ(fs::exists(plain / file), fs::exists(ck / file)) << name << " " << file;
            if (fs::exists(plain / file))
                EXPECT_TRUE(test::read_file(plain / file) == test::read_file(ck / file)) << name << " " << file;
        }
        if (std::string(name) == "cooling") {
            const auto h = test::read_csv(plain / "histograms.csv");
            EXPECT_EQ(h.at("t").front(), 0.25);
            EXPECT_EQ(h.at("t").back(), 0.5);
            // Each replica's own count at t = 0.5: their mean, as moments.csv's last row has it.
            const auto m = test::read_csv(plain / "moments.csv");
            EXPECT_EQ(h.at("coll_per_particle").back(), m.at("coll_per_particle").back());
            const double c0 = test::read_csv(plain / "replicas" / "moments_0.csv").at("coll_per_particle").back();
            const double c1 = test::read_csv(plain / "replicas" / "moments_1.csv").at("coll_per_particle").back();
            EXPECT_NE(c0, c1);
            EXPECT_DOUBLE_EQ(h.at("coll_per_particle").back(), (c0 + c1) / 2);
        }
    }
}

// --set run.end_time on a case written for run.end runs it by time: the file's run.end,
// run.output_every and run.histogram_every are left out.
TEST(TimeClock, SettingEndTimeSwitchesACaseClockedByCollisions) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("case.toml", replaced(cooling_case(1), "end_time = 0.5\noutput_every_time = 0.05\n",
                                                      "end = 3.0\noutput_every = 1.0\nhistogram_every = 1.5\n"));
    const test::CommandResult r = run_roughgas(
        run_args(f, dir / "out", "--set run.end_time=0.3 --set run.output_every_time=0.1"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    // The file's output_spacing = "log" applies to output_every_time as to output_every.
    expect_times(test::read_csv(dir / "out" / "moments.csv").at("t"), times(0.1, 0.3, true), "switched");
    // Back again: run.end on the time-clocked case.
    const fs::path g = dir.write("timed.toml", cooling_case(1));
    const test::CommandResult back =
        run_roughgas(run_args(g, dir / "back", "--set run.end=1.0 --set run.output_every=0.5"), dir);
    ASSERT_EQ(back.status, 0) << back.err;
    const auto m = test::read_csv(dir / "back" / "moments.csv");
    EXPECT_EQ(m.at("coll_per_particle").back(), 1.0);
    EXPECT_FALSE(fs::exists(dir / "out" / "histograms.csv")); // the file's histogram_every left out
}

// A key of the other clock given with --set beside the switch is refused (exit 2, file and key),
// not left out as the file's are.
TEST(TimeClock, OtherClocksKeySetBesideTheSwitchIsRefused) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("case.toml", replaced(cooling_case(1), "end_time = 0.5\noutput_every_time = 0.05\n",
                                                      "end = 3.0\noutput_every = 1.0\n"));
    const test::CommandResult r =
        run_roughgas(run_args(f, dir / "out", "--set run.end_time=0.3 --set run.output_every=0.5"), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find(f.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("run.output_every: in collisions per particle, but this run is clocked by run.end_time "
                         "(time): use run.output_every_time instead"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "moments.csv"));
}

// `roughgas check` reports the clock's errors as `run` does: file, key and what is allowed.
TEST(TimeClock, CheckReportsBothClocksAndTheOtherClocksKeys) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("both.toml", replaced(cooling_case(1), "end_time = 0.5\n",
                                                      "end_time = 0.5\nend = 3.0\noutput_every = 1.0\n"));
    const test::CommandResult r = run_roughgas("check '" + f.string() + "'", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find(f.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("run.end_time = 0.5: give either run.end (collisions per particle) or run.end_time "
                         "(time), not both"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("run.output_every: in collisions per particle, but this run is clocked by run.end_time"),
              std::string::npos)
        << r.err;
    const fs::path g = dir.write("ok.toml", cooling_case(1));
    EXPECT_EQ(run_roughgas("check '" + g.string() + "'", dir).status, 0);
}

} // namespace
} // namespace roughgas
