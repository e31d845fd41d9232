// `roughgas run --replicas FROM:TO` and `roughgas merge` (src/cli/merge_command.cpp): an ensemble
// split into replica ranges, run as separate processes on any thread counts, merges into the very
// bytes one run of all replicas writes; a split that is not one whole run is refused.
#include "io_test_support.hpp"

#include <gtest/gtest.h>

#include <string>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

// Rough cooling, 4 replicas, histograms and log-spaced rows: every file of a cooling run.
std::string cooling_case(int seed = 5) {
    return R"([run]
particles = 3000
replicas = 4
end = 20.0
output_every = 0.5
output_spacing = "log"
histogram_every = 5.0
seed = )" + std::to_string(seed) +
           R"(

[[species]]
mass = 1.0
radius = 0.5

[collision]
model = "constant"
alpha = 0.8
beta = 0.4
)";
}

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

TEST(MergeCli, RangesMergeIntoTheFilesOfOneRun) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("hcs.toml", cooling_case());
    const std::string run = "run " + q(f) + " --quiet --out ";
    ASSERT_EQ(test::run_roughgas(run + q(dir / "whole") + " --threads 2", dir).status, 0);
    // Three ranges, on different thread counts, listed out of order.
    for (const auto& [range, threads] : {std::pair{"0:1", "1"}, {"1:3", "2"}, {"3:4", "1"}}) {
        const test::CommandResult r =
            test::run_roughgas(run + q(dir / range) + " --replicas " + range + " --threads " + threads, dir);
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_FALSE(fs::exists(dir / range / "moments.csv")) << "a range writes no ensemble file";
        EXPECT_TRUE(fs::exists(dir / range / "checkpoint" / "run.bin"));
    }
    const test::CommandResult m =
        test::run_roughgas("merge " + q(dir / "3:4") + " " + q(dir / "0:1") + " " + q(dir / "1:3") +
                               " --quiet --out " + q(dir / "merged"),
                           dir);
    ASSERT_EQ(m.status, 0) << m.err;
    for (const char* file : {"moments.csv", "histograms.csv"})
        EXPECT_EQ(test::read_file(dir / "merged" / file), test::read_file(dir / "whole" / file)) << file;
}

TEST(MergeCli, ShearRangesGiveTheSameSteadyState) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("usf.toml", R"([run]
kind = "shear"
particles = 2000
replicas = 2
end = 40.0
[[species]]
mass = 1.0
radius = 0.5
temperature = 0.05
rotational_temperature = 0.012
[collision]
model = "constant"
alpha = 0.9
beta = 0.0
[shear]
rate = 1.0
)");
    const std::string run = "run " + q(f) + " --quiet --out ";
    ASSERT_EQ(test::run_roughgas(run + q(dir / "whole"), dir).status, 0);
    ASSERT_EQ(test::run_roughgas(run + q(dir / "a") + " --replicas 0:1", dir).status, 0);
    ASSERT_EQ(test::run_roughgas(run + q(dir / "b") + " --replicas 1:2", dir).status, 0);
    ASSERT_EQ(test::run_roughgas("merge " + q(dir / "a") + " " + q(dir / "b") + " --quiet --out " + q(dir / "m"), dir)
                  .status,
              0);
    for (const char* file : {"moments.csv", "steady.csv"})
        EXPECT_EQ(test::read_file(dir / "m" / file), test::read_file(dir / "whole" / file)) << file;
}

TEST(MergeCli, ABoxRunsStatesAndFieldsMergeToo) {
    // Every file a box run with run.save_state and [fields] writes: each replica's final state and
    // cell fields, the same bytes (the sidecar names its HDF5 files relative to its own folder).
    const test::ScratchDir dir;
    const fs::path f = dir.write("box.toml", R"([run]
particles = 2000
replicas = 3
end = 2.0
output_every = 1.0
density = 0.02
seed = 4
save_state = true

[[species]]
mass = 1.0
radius = 0.5

[collision]
model = "constant"
alpha = 0.9
beta = 0.5

[domain]
size = [30.0, 30.0, 30.0]
cells = [4, 4, 4]
allow_coarse = true

[fields]
quantities = ["n", "P"]
replicas = 3
)");
    const std::string run = "run " + q(f) + " --quiet --out ";
    ASSERT_EQ(test::run_roughgas(run + q(dir / "whole"), dir).status, 0);
    ASSERT_EQ(test::run_roughgas(run + q(dir / "a") + " --replicas 0:2", dir).status, 0);
    ASSERT_EQ(test::run_roughgas(run + q(dir / "b") + " --replicas 2:3", dir).status, 0);
    const test::CommandResult m =
        test::run_roughgas("merge " + q(dir / "b") + " " + q(dir / "a") + " --quiet --out " + q(dir / "m"), dir);
    ASSERT_EQ(m.status, 0) << m.err;
    for (int r = 0; r < 3; ++r) {
        const std::string R = std::to_string(r);
        for (const std::string file : {"state/replica_" + R + ".bin", "fields/replica_" + R + "/row_000000.h5",
                                       "fields/replica_" + R + "/row_000002.h5"})
            EXPECT_EQ(test::read_file(dir / "m" / file), test::read_file(dir / "whole" / file)) << file;
        const std::string xmf = "fields/replica_" + R + ".xmf";
        EXPECT_EQ(test::read_file(dir / "m" / xmf), test::read_file(dir / "whole" / xmf)) << xmf;
    }
    for (const char* file : {"moments.csv", "profiles.csv"})
        EXPECT_EQ(test::read_file(dir / "m" / file), test::read_file(dir / "whole" / file)) << file;
    // Merging into a range's own directory would clear what it reads from: refused.
    const test::CommandResult into =
        test::run_roughgas("merge " + q(dir / "a") + " " + q(dir / "b") + " --quiet --force --out " + q(dir / "a"), dir);
    EXPECT_EQ(into.status, 2);
    EXPECT_NE(into.err.find("one of the ranges"), std::string::npos) << into.err;
}

TEST(MergeCli, RefusesWhatIsNotOneWholeRun) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("hcs.toml", cooling_case());
    const fs::path g = dir.write("other.toml", cooling_case(6));
    const std::string run = "run " + q(f) + " --quiet --out ";
    ASSERT_EQ(test::run_roughgas(run + q(dir / "a") + " --replicas 0:2", dir).status, 0);
    ASSERT_EQ(test::run_roughgas(run + q(dir / "b") + " --replicas 1:4", dir).status, 0);
    ASSERT_EQ(test::run_roughgas(run + q(dir / "c") + " --replicas 2:4", dir).status, 0);
    ASSERT_EQ(test::run_roughgas("run " + q(g) + " --quiet --out " + q(dir / "d") + " --replicas 2:4", dir).status,
              0);
    const auto refused = [&](const std::string& dirs, const std::string& words) {
        const test::CommandResult r = test::run_roughgas("merge " + dirs + " --quiet --out " + q(dir / "m"), dir);
        EXPECT_EQ(r.status, 2) << dirs;
        EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir / "m")) << "nothing written";
    };
    refused(q(dir / "a"), "replicas 2, 3 of 4 in none");
    refused(q(dir / "a") + " " + q(dir / "b"), "replica 1 is in both");
    refused(q(dir / "a") + " " + q(dir / "d"), "another run");
    refused(q(dir / "nothing"), "cannot merge");
    // --replicas outside 0 <= FROM < TO <= run.replicas, or not FROM:TO.
    for (const std::string bad : {"2:2", "3:5", "x:2", "1", "-1:2"}) {
        const test::CommandResult r = test::run_roughgas(run + q(dir / "e") + " --replicas " + bad, dir);
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_NE(r.err.find("--replicas"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir / "e")) << bad;
    }
    // The ranges that do form the run merge.
    EXPECT_EQ(test::run_roughgas("merge " + q(dir / "a") + " " + q(dir / "c") + " --quiet --out " + q(dir / "m"), dir)
                  .status,
              0);
}

} // namespace
} // namespace roughgas
