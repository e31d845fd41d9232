// `roughgas sweep` (src/cli/sweep_command.cpp): every point validated before any work, one
// summary row per point, and the same files whatever the thread count.
#include "io_test_support.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

// A small shear case (reduced units) started near its steady state (alpha = 0.9, beta = 0, a = 1).
std::string shear_case() {
    return R"([run]
kind = "shear"
particles = 2000
end = 30.0
seed = 3

[[species]]
name = "grain"
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
)";
}

std::vector<std::string> data_lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] != '#')
            out.push_back(line);
    return out;
}

// At the end, a compact table on stderr: per point the swept value, where the steady window
// starts and the headline quantities (shear: a*, eta*, theta, N1*) with their errors.
TEST(SweepCli, EndsWithACompactTableOfThePoints) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("usf.toml", shear_case());
    const test::CommandResult r = run_roughgas(
        "sweep '" + f.string() + "' --param collision.alpha=0.8:0.9:2 --out '" + (dir / "s").string() + "'", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::size_t head = r.err.find("collision.alpha");
    ASSERT_NE(head, std::string::npos) << r.err;
    const std::string table = r.err.substr(r.err.rfind('\n', head) + 1);
    for (const char* column : {"from", "a_star", "eta_star", "theta", "N1_star"})
        EXPECT_NE(table.find(column), std::string::npos) << column << " not in\n" << table;
    for (const char* value : {"roughgas sweep:          0.8 ", "roughgas sweep:          0.9 "})
        EXPECT_NE(table.find(value), std::string::npos) << value << " not in\n" << table;
    EXPECT_NE(table.find(" +- "), std::string::npos) << table;
}

TEST(SweepCli, OneRowPerPointIdenticalWhateverTheThreads) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("usf.toml", shear_case());
    const std::string args = "sweep '" + f.string() + "' --param collision.alpha=0.7:0.9:3 --quiet --out ";
    const test::CommandResult one = run_roughgas(args + "'" + (dir / "t1").string() + "' --threads 1", dir);
    ASSERT_EQ(one.status, 0) << one.err;
    const test::CommandResult two = run_roughgas(args + "'" + (dir / "t2").string() + "' --threads 2", dir);
    ASSERT_EQ(two.status, 0) << two.err;
    const std::string a = test::read_file(dir / "t1" / "sweep.csv");
    EXPECT_EQ(a, test::read_file(dir / "t2" / "sweep.csv"));
    for (int k = 0; k < 3; ++k) {
        const std::string p = "point_" + std::to_string(k);
        EXPECT_EQ(test::read_file(dir / "t1" / p / "moments.csv"),
                  test::read_file(dir / "t2" / p / "moments.csv"));
    }
    const std::vector<std::string> lines = data_lines(a);
    ASSERT_EQ(lines.size(), 4u); // header + 3 points
    EXPECT_EQ(lines[0].rfind("collision.alpha,steady,steady_from,steady_rows,", 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find(",P_xy_star,P_xy_star_err,"), std::string::npos);
    EXPECT_EQ(lines[1].rfind("0.7,", 0), 0u) << lines[1];
    EXPECT_EQ(lines[3].rfind("0.9,", 0), 0u) << lines[3];
    // Each point's summary beside its rows: the same values as its row of sweep.csv (after the
    // swept value), in a file with a unit per column, as the run writes steady.csv.
    for (int k = 0; k < 3; ++k) {
        const std::string point = test::read_file(dir / "t1" / ("point_" + std::to_string(k)) / "steady.csv");
        const std::vector<std::string> p = data_lines(point);
        ASSERT_EQ(p.size(), 2u) << point;
        EXPECT_EQ(lines[0], "collision.alpha," + p[0]);
        EXPECT_EQ(lines[static_cast<std::size_t>(k) + 1].substr(lines[static_cast<std::size_t>(k) + 1].find(',') + 1),
                  p[1]);
        EXPECT_NE(point.find("\n# units: -,-,-,"), std::string::npos) << point;
        EXPECT_NE(point.find("# unit system: the case's own"), std::string::npos) << point;
    }
    // sweep.csv's units: the swept key's (dimensionless alpha), then the summary's (T_tr in energy).
    EXPECT_NE(a.find("\n# units: -,-,-,-,"), std::string::npos) << a;
    EXPECT_NE(a.find(",energy,energy,"), std::string::npos) << a;
    // an existing sweep is not overwritten without --force
    EXPECT_EQ(run_roughgas(args + "'" + (dir / "t1").string() + "'", dir).status, 2);
}

TEST(SweepCli, CoolingCasesSweepToo) {
    const test::ScratchDir dir;
    std::string c = shear_case();
    c = test::replaced(c, "kind = \"shear\"", "kind = \"cooling\"");
    const fs::path f = dir.write("hcs.toml", c);
    const test::CommandResult r =
        run_roughgas("sweep '" + f.string() + "' --param collision.beta=0:1:2 --quiet --out '" +
                         (dir / "o").string() + "'",
                     dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::vector<std::string> lines = data_lines(test::read_file(dir / "o" / "sweep.csv"));
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_NE(lines[0].find(",theta,theta_err,"), std::string::npos);
    EXPECT_EQ(lines[0].find("P_xy"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "o" / "point_1" / "scaled.csv")); // a cooling point's summary
    EXPECT_FALSE(fs::exists(dir / "o" / "point_1" / "steady.csv"));
}

// A box whose walls heat the gas reaches a steady state, as a sheared gas does: its points'
// summaries are steady.csv (the steady window), as `roughgas run` writes for the same case.
TEST(SweepCli, WallHeatedBoxesSweepToTheirSteadyStates) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("walls.toml", R"([run]
particles = 2000
end = 40.0
output_every = 2.0
density = 0.02
seed = 2

[[species]]
mass = 1.0
radius = 0.5

[collision]
model = "constant"
alpha = 0.9
beta = 0.4

[domain]
size = [11.25, 112.5, 11.25]
cells = [1, 20, 1]
boundary = ["periodic", "walls", "periodic"]

[wall_lower]
kind = "diffuse"
temperature = 1.0

[wall_upper]
kind = "diffuse"
temperature = 1.0
)");
    const test::CommandResult r =
        run_roughgas("sweep '" + f.string() + "' --param wall_upper.temperature=1:2:2 --quiet --out '" +
                         (dir / "o").string() + "'",
                     dir);
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* point : {"point_0", "point_1"}) {
        EXPECT_TRUE(fs::exists(dir / "o" / point / "steady.csv")) << point;
        EXPECT_FALSE(fs::exists(dir / "o" / point / "scaled.csv")) << point;
    }
    EXPECT_NE(test::read_file(dir / "o" / "sweep.csv").find("the steady state"), std::string::npos);
}

// A point inside the range that is invalid fails the whole sweep before any work: exit 2, the
// message names the file, the key and its range, nothing is written.
TEST(SweepCli, InvalidPointFailsBeforeAnyWork) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("usf.toml", shear_case());
    const fs::path out = dir / "o";
    test::CommandResult r = run_roughgas(
        "sweep '" + f.string() + "' --param shear.rate=1:-1:3 --out '" + out.string() + "'", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("shear.rate"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("must be > 0"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(f.string()), std::string::npos) << r.err;
    // The value came from --param, and the message says which point: not "set with --set".
    EXPECT_NE(r.err.find("(point 2 of --param shear.rate=1:-1:3)"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("set with --set"), std::string::npos) << r.err;
    r = run_roughgas(
        "sweep '" + f.string() + "' --param collision.alpha=0.5:x:3 --out '" + out.string() + "'", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_FALSE(fs::exists(out));
}

} // namespace
} // namespace roughgas
