// The real binary: exit statuses, messages on stderr, and that invalid input writes nothing.
#include "io_test_support.hpp"

#include "roughgas/io/case_file.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace roughgas {
namespace {

namespace fs = std::filesystem;
using test::replaced;
using test::small_case;

struct BadInput {
    std::string name;
    std::string case_text; // the case file
    std::string sets;      // extra command-line arguments
    std::string key;       // the message must name it ...
    std::string allowed;   // ... and what is allowed
};

std::string constant_model() {
    return replaced(small_case(), "model = \"brilliantov\"", "model = \"constant\"\nalpha = 0.9\nbeta = 0.0");
}

std::string two_species(double f0, double f1) {
    return replaced(small_case(), "[collision]",
                    "fraction = " + std::to_string(f0) +
                        "\n\n[[species]]\nname = \"b\"\nmass = 1e-3\nradius = 0.005\nfraction = " +
                        std::to_string(f1) + "\n\n[collision]");
}

std::vector<BadInput> bad_inputs() {
    const std::string c = small_case();
    return {
        {"NegativeYoungModulus", c, "--set material.young_modulus=-1e10", "material.young_modulus",
         "must be > 0 (Pa)"},
        {"NegativeYoungModulusInFile", replaced(c, "young_modulus = 1.0e10", "young_modulus = -1e10"), "",
         "material.young_modulus", "must be > 0 (Pa)"},
        {"PoissonRatioTooLarge", c, "--set material.poisson_ratio=0.5", "material.poisson_ratio",
         "must be in (-1, 0.5)"},
        {"PoissonRatioTooSmall", c, "--set material.poisson_ratio=-1", "material.poisson_ratio",
         "must be in (-1, 0.5)"},
        {"NegativeDissipation", c, "--set material.dissipation=-1e-5", "material.dissipation",
         "must be >= 0 (s)"},
        {"NegativeFriction", c, "--set material.friction=-0.1", "material.friction", "must be >= 0"},
        {"ZeroAsperity", c, "--set material.asperity=0", "material.asperity", "must be > 0 (m)"},
        {"NegativeAsperity", c, "--set material.asperity=-1e-6", "material.asperity", "must be > 0 (m)"},
        {"MissingRequiredKey", replaced(c, "radius = 0.01\n", ""), "", "species.0.radius",
         "required key is missing (must be a real number > 0 (length))"},
        {"UnknownKey", replaced(c, "young_modulus", "youngs_modulus"), "", "material.youngs_modulus",
         "unknown key (did you mean material.young_modulus?)"},
        {"NegativeAlpha", constant_model(), "--set collision.alpha=-0.1", "collision.alpha",
         "must be in [0, 1]"},
        {"AlphaAboveOne", constant_model(), "--set collision.alpha=1.01", "collision.alpha",
         "must be in [0, 1]"},
        {"BetaAboveOne", constant_model(), "--set collision.beta=1.5", "collision.beta",
         "must be in [-1, 1]"},
        {"BetaBelowMinusOne", constant_model(), "--set collision.beta=-1.5", "collision.beta",
         "must be in [-1, 1]"},
        {"UnknownModel", c, "--set collision.model=granite", "collision.model",
         "must be one of \"constant\", \"coulomb\", \"viscoelastic\", \"brilliantov\""},
        {"ZeroParticles", c, "--set run.particles=0", "run.particles", "must be >= 2"},
        {"FractionsNotSummingToOne", two_species(0.5, 0.4), "", "species.fraction",
         "must sum to 1 (within 1e-9)"},
        {"MissingMaterialForRestitution", replaced(c, "asperity = 1.0e-6", ""),
         "--set collision.model=viscoelastic", "material.asperity", "required for roughgas restitution"},
    };
}

// gtest prints the parameter of a failing test with this.
void PrintTo(const BadInput& b, std::ostream* os) {
    *os << b.name;
}

class InvalidInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(InvalidInput, ExitsWithStatus2NamingFileKeyAndRangeAndWritesNothing) {
    const BadInput& b = GetParam();
    const test::ScratchDir dir;
    const fs::path case_file = dir.write("bad.toml", b.case_text);
    const fs::path out = dir / "out";

    const test::CommandResult r =
        run_roughgas("restitution '" + case_file.string() + "' --out '" + out.string() + "' " + b.sets, dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(case_file.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(b.key), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(b.allowed), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(fs::exists(out));

    if (b.name != "MissingMaterialForRestitution") { // a valid case for a run
        const test::CommandResult c = run_roughgas("check '" + case_file.string() + "' " + b.sets, dir);
        EXPECT_EQ(c.status, 2) << c.err;
        EXPECT_NE(c.err.find(b.allowed), std::string::npos) << c.err;
    }
}

INSTANTIATE_TEST_SUITE_P(Cli, InvalidInput, ::testing::ValuesIn(bad_inputs()),
                         [](const ::testing::TestParamInfo<BadInput>& info) { return info.param.name; });

// A gas cooling with constant restitution loses a fixed share of T_tr per collision: a run.end past
// the point where the squares of the velocities underflow is refused before any work (exit 2 naming
// run.end and the reach). The reach is where the run fails, not short of it or past it: smooth
// grains at alpha = 0.8, rough ones at alpha = 0.9, beta = 0.4 (the start's theta relaxing to the
// cooling state's) and the rough binary mixture of cases/hcs_mixture.toml (its temperature ratios
// settling) run to 0.95 of it, and their last rows, at the cooling rate of the last interval, put
// the smallest T_tr,s/m_s at 1e-300 after the reach's remaining 5 %, to 3 % of the reach: the
// theory's cooling rate is the Maxwellian one, which the gas's cumulants move by 3 a20/16 and the
// like (a20 up to 0.1 here: 2 %). A box whose
// diffuse walls hold the gas at a steady state may run as long as it likes; with walls that only
// reflect it cools.
TEST(Cli, CoolingRunsPastTheTemperaturesUnderflowAreRefused) {
    const test::ScratchDir dir;
    const fs::path cases = fs::path(ROUGHGAS_SOURCE_DIR) / "cases";
    const std::string walls = "check '" + (cases / "box_thermal_walls.toml").string() + "' --set run.end=1e6";
    EXPECT_EQ(run_roughgas(walls, dir).status, 0) << run_roughgas(walls, dir).err;
    const test::CommandResult closed =
        run_roughgas(walls + " --set wall_lower.kind=specular --set wall_upper.kind=specular", dir);
    EXPECT_EQ(closed.status, 2);
    EXPECT_NE(closed.err.find("run.end = 1000000"), std::string::npos) << closed.err;
    // 1e-300 times the mass, in the case's units: not a length.
    EXPECT_NE(closed.err.find("reaches T_tr/m = 1e-300 (velocities squared underflow) at about"), std::string::npos)
        << closed.err;
    const struct {
        std::string file, sets;
        std::vector<std::pair<std::string, double>> species; // T_tr column, mass
    } gases[] = {
        {"hcs_smooth.toml", "--set collision.alpha=0.8", {{"T_tr", 1.0}}},
        {"hcs_smooth.toml", "--set collision.alpha=0.9 --set collision.beta=0.4", {{"T_tr", 1.0}}},
        {"hcs_mixture.toml", "--set run.replicas=1", {{"T_tr.small", 1.0}, {"T_tr.large", 8.0}}},
    };
    for (const auto& g : gases) {
        const std::string base = "'" + (cases / g.file).string() + "' --set run.particles=2000 " + g.sets;
        const test::CommandResult refused = run_roughgas("run " + base + " --set run.end=1e6 --out '" +
                                                             (dir / "far").string() + "'", dir);
        ASSERT_EQ(refused.status, 2) << refused.err;
        EXPECT_NE(refused.err.find("run.end = 1000000"), std::string::npos) << refused.err;
        EXPECT_FALSE(fs::exists(dir / "far"));
        const std::size_t at = refused.err.find("(run.end < ");
        ASSERT_NE(at, std::string::npos) << refused.err;
        const double reach = std::stod(refused.err.substr(at + 11));
        EXPECT_GT(reach, 2000.0) << g.sets;
        const test::CommandResult near = run_roughgas("run " + base + " --quiet --set run.end=" +
                                                          std::to_string(0.95 * reach) + " --out '" +
                                                          (dir / "near").string() + "' --force", dir);
        ASSERT_EQ(near.status, 0) << g.file << " " << g.sets << "\n" << near.err;
        const auto rows = test::read_csv(dir / "near" / "moments.csv");
        const std::vector<double>&s = rows.at("coll_per_particle"), &T = rows.at("T_tr");
        const std::size_t last = s.size() - 1;
        EXPECT_NEAR(s[last], 0.95 * reach, 1.0) << g.sets;
        const double zeta = std::log(T[last - 1] / T[last]) / (s[last] - s[last - 1]);
        double least = HUGE_VAL;
        for (const auto& [column, mass] : g.species)
            least = std::min(least, rows.at(column)[last] / mass);
        ASSERT_GT(least, 0.0) << g.sets;
        const double measured = s[last] + std::log(least / 1e-300) / zeta;
        std::printf("%s %s: reach %.1f, measured %.1f\n", g.file.c_str(), g.sets.c_str(), reach, measured);
        EXPECT_NEAR(measured / reach, 1.0, 0.03) << g.file << " " << g.sets << ": zeta " << zeta;
    }
}

// The grains fill the solid fraction phi = sum_s x_s n (pi/6) sigma_s^3: at or beyond the densest
// packing of equal spheres, pi/sqrt(18) = 0.74048, check and run refuse the case before any work
// (exit 2 naming run.density, nothing written), just below it they accept it. One species of
// sigma = 1: n = 1.415 is phi = 0.74089, n = 1.413 is 0.73984; half and half of sigma = 1 and 2:
// phi = 2.3562 n, refused at n = 0.3145 (0.74103), accepted at 0.3140 (0.73985), which a sum
// without the fractions (twice as much) or over the radii (an eighth) would not give.
TEST(Cli, SolidFractionAtClosePackingIsRefused) {
    const test::ScratchDir dir;
    const std::string one = "[run]\nparticles = 2000\nend = 1.0\ndensity = 1.0\n\n[[species]]\nname = \"a\"\n"
                            "mass = 1.0\nradius = 0.5\n";
    const std::string two = replaced(one, "radius = 0.5\n", "radius = 0.5\nfraction = 0.5\n") +
                            "\n[[species]]\nname = \"b\"\nmass = 8.0\nradius = 1.0\nfraction = 0.5\n";
    const std::string rule = "\n[collision]\nmodel = \"constant\"\nalpha = 0.9\nbeta = 0.4\n";
    const struct {
        std::string text, refused, accepted, phi;
    } gases[] = {{one + rule, "1.415", "1.413", "phi = 0.7409"}, {two + rule, "0.3145", "0.314", "phi = 0.741"}};
    for (const auto& g : gases) {
        const fs::path f = dir.write("gas.toml", g.text);
        for (const char* command : {"check", "run"}) {
            const std::string args = std::string(command) + " '" + f.string() + "' --set run.density=" + g.refused +
                                     (std::string(command) == "run" ? " --out '" + (dir / "out").string() + "'" : "");
            const test::CommandResult r = run_roughgas(args, dir);
            EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
            EXPECT_NE(r.err.find("run.density = " + g.refused + ": "), std::string::npos) << r.err;
            EXPECT_NE(r.err.find(g.phi), std::string::npos) << r.err;
            EXPECT_NE(r.err.find("pi/sqrt(18) = 0.7405"), std::string::npos) << r.err;
            EXPECT_FALSE(fs::exists(dir / "out")) << args;
        }
        const test::CommandResult ok = run_roughgas("check '" + f.string() + "' --set run.density=" + g.accepted, dir);
        EXPECT_EQ(ok.status, 0) << ok.err;
    }
}

TEST(Cli, FileErrorsCarryLineAndColumn) {
    const test::ScratchDir dir;
    const fs::path f =
        dir.write("bad.toml", replaced(small_case(), "young_modulus = 1.0e10", "young_modulus = -1e10"));
    const test::CommandResult r = run_roughgas("check '" + f.string() + "'", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find(f.string() + ":14:17: material.young_modulus = "), std::string::npos) << r.err;
}

TEST(Cli, CheckAcceptsValidCaseAndOverrides) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("ok.toml", small_case());
    EXPECT_EQ(run_roughgas("check '" + f.string() + "'", dir).status, 0);
    const test::CommandResult r =
        run_roughgas("check '" + f.string() +
                         "' --set species.0.radius=0.5 --set 'collision.model=\"viscoelastic\"' --print",
                     dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("radius = 0.5\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("model = \"viscoelastic\"\n"), std::string::npos) << r.out;
    const test::CommandResult bare = run_roughgas("check '" + f.string() +
                                                      "' --set collision.model=coulomb "
                                                      "--set collision.alpha=0.8 --set collision.beta0=0.4 "
                                                      "--set collision.friction=0.2 --print",
                                                  dir);
    EXPECT_EQ(bare.status, 0) << bare.err;
    EXPECT_NE(bare.out.find("model = \"coulomb\"\n"), std::string::npos) << bare.out;
}

TEST(Cli, EveryShippedCasePassesCheck) {
    const test::ScratchDir dir;
    int n = 0;
    for (const auto& e : fs::directory_iterator(fs::path(ROUGHGAS_SOURCE_DIR) / "cases")) {
        if (e.path().extension() != ".toml")
            continue;
        ++n;
        const std::string f = e.path().string();
        // A case that starts from the grains another shipped case saves (initial.from = "out/NAME", run in
        // the order of docs/running.md): that case runs first, briefly, where the check looks for them.
        const CaseConfig from_case = load_case(f);
        std::string sets;
        if (from_case.initial && !from_case.initial->from.empty()) {
            const std::string from = from_case.initial->from;
            const fs::path saving =
                fs::path(ROUGHGAS_SOURCE_DIR) / "cases" / (fs::path(from).filename().string() + ".toml");
            ASSERT_TRUE(fs::exists(saving)) << f << ": initial.from = \"" << from << "\" names no shipped case";
            const test::CommandResult saved = run_roughgas("run '" + saving.string() + "' --out '" + from +
                                                               "' --force --quiet --set run.particles=2000 --set run.end=1",
                                                           dir);
            ASSERT_EQ(saved.status, 0) << saving << "\n" << saved.err;
            sets = " --set run.particles=2000";
        }
        const test::CommandResult r = run_roughgas("check '" + f + "'" + sets, dir);
        EXPECT_EQ(r.status, 0) << f << "\n" << r.err;
        // A dilute gas, in cells larger than a grain holding grains enough (the shipped boxes' cells of
        // up to a mean free path have their own warning, of the viscosity in gradients).
        for (const char* w : {"solid fraction", "smaller than a grain", "grains per cell on average", "is not used"})
            EXPECT_EQ(r.err.find(w), std::string::npos) << f << "\n" << r.err;
        const CaseConfig c = load_case(f);
        if (c.material) { // cases with a contact model also tabulate it (roughgas restitution)
            EXPECT_EQ(run_roughgas("check '" + f + "' --for restitution", dir).status, 0) << f;
        }
        EXPECT_EQ(parse_case(emit_case(c), "emitted.toml"), c) << f; // the echo in CSV headers reads back
    }
    EXPECT_GE(n, 4);
}

TEST(Cli, MalformedCommandLineIsInvalidInput) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("ok.toml", small_case());
    EXPECT_EQ(run_roughgas("check", dir).status, 2);
    EXPECT_EQ(run_roughgas("check '" + f.string() + "' --no-such-option", dir).status, 2);
    EXPECT_EQ(run_roughgas("restitution '" + f.string() + "'", dir).status, 2); // --out missing
    EXPECT_EQ(run_roughgas("frobnicate", dir).status, 2);
    EXPECT_EQ(run_roughgas("check '" + (dir / "absent.toml").string() + "'", dir).status, 2);
    EXPECT_EQ(run_roughgas("--help", dir).status, 0);
}

// Readable command-line messages: a range in words (not the bound DBL_MAX in 309 digits), a
// "did you mean" for a mistyped option, and every command in --help.
TEST(Cli, CommandLineMessagesAUserCanRead) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("ok.toml", small_case());
    const std::string run = "run '" + f.string() + "' --out '" + (dir / "out").string() + "' ";
    test::CommandResult r = run_roughgas(run + "--checkpoint-every -1", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--checkpoint-every: must be a number > 0, got -1"), std::string::npos) << r.err;
    EXPECT_LT(r.err.size(), 200U) << r.err;
    r = run_roughgas(run + "--threads 0", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--threads: must be a number > 0, got 0"), std::string::npos) << r.err;
    r = run_roughgas(run + "--thread 2", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--thread: did you mean --threads?"), std::string::npos) << r.err;
    r = run_roughgas("sweep '" + f.string() + "' --parm run.end=1:2:2 --out x", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--parm: did you mean --param?"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out"));
    r = run_roughgas("--help", dir);
    for (const char* command : {"run", "sweep", "merge", "restitution", "check", "keys"})
        EXPECT_NE(r.out.find(std::string("  ") + command), std::string::npos) << command << " not in --help";
}

TEST(Cli, ResumeWithoutACheckpointAndBadSweepsFailFirst) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("ok.toml", small_case());
    const std::string out = (dir / "out").string();
    test::CommandResult r = run_roughgas("run --resume '" + out + "'", dir); // tests/io/resume_cli_test.cpp
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("cannot resume: no such directory"), std::string::npos) << r.err;
    r = run_roughgas("run '" + f.string() + "' --out '" + out + "' --checkpoint-every 0", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--checkpoint-every"), std::string::npos) << r.err;
    EXPECT_EQ(run_roughgas("run '" + f.string() + "' --out '" + out + "' --set run.end=-1", dir).status, 2);
    EXPECT_EQ(
        run_roughgas("sweep '" + f.string() + "' --param run.end=-1:100:5 --out '" + out + "'", dir).status,
        2);
    EXPECT_EQ(
        run_roughgas("sweep '" + f.string() + "' --param run.end=1:100 --out '" + out + "'", dir).status, 2);
    EXPECT_FALSE(fs::exists(out));
}

// --- these run the contact integrator (tiny grids) ---

std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// The rows of a CSV file (no '#' lines).
std::vector<std::string> rows(const fs::path& p) {
    std::istringstream in(test::read_file(p));
    std::vector<std::string> r;
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line[0] != '#')
            r.push_back(line);
    }
    return r;
}

// The comma-separated numbers of a CSV row.
std::vector<double> numbers(const std::string& row) {
    std::vector<double> v;
    std::istringstream in(row);
    for (std::string cell; std::getline(in, cell, ',');)
        v.push_back(std::stod(cell));
    return v;
}

TEST(Cli, RestitutionWritesBothTables) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("ok.toml", small_case());
    const fs::path out = dir / "out";
    const test::CommandResult r = run_roughgas(
        "restitution '" + f.string() + "' --out '" + out.string() + "' --set restitution.g_t_points=3", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(entries(out), (std::vector<std::string>{"normal.csv", "tangential.csv"})); // no temporary files
    const std::vector<std::string> normal = rows(out / "normal.csv");
    ASSERT_EQ(normal.size(), 3u);
    // contact.cache = true (the default): the cached tables' values follow the direct ones.
    EXPECT_EQ(normal[0], "g_N,w,eps_N,duration,max_compression,eps_N_table");
    EXPECT_EQ(normal[1].rfind("0.01,", 0), 0u) << normal[1];
    for (std::size_t k = 1; k < normal.size(); ++k) {
        const std::vector<double> v = numbers(normal[k]);
        EXPECT_NEAR(v[5], v[2], 1e-8 * v[2]) << normal[k]; // the eps_N table's bound
    }
    const std::vector<std::string> tangential = rows(out / "tangential.csv");
    ASSERT_EQ(tangential.size(), 1u + 2 * 3);
    EXPECT_EQ(tangential[0], "g_N,g_T,eps_T,beta,breaks,eps_T_table");
    for (std::size_t k = 1; k < tangential.size(); ++k) {
        const std::vector<double> v = numbers(tangential[k]);
        EXPECT_NEAR(v[5], v[2], 1e-4) << tangential[k]; // the eps_T table's bound
    }
    EXPECT_EQ(tangential[1].rfind("0.01,0.01,", 0), 0u) << tangential[1]; // g_N outer, g_T inner
    EXPECT_EQ(tangential[2].rfind("0.01,0.1,", 0), 0u) << tangential[2];
    const std::string text = test::read_file(out / "normal.csv");
    EXPECT_NE(text.find("# case: " + f.string() + "\n"), std::string::npos);
    EXPECT_NE(text.find("# set: restitution.g_t_points=3\n"), std::string::npos);
    EXPECT_NE(text.find("# g_t_points = 3\n"), std::string::npos); // the resolved case
}

TEST(Cli, RestitutionWithoutCacheHasNoTableColumns) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("ok.toml", small_case());
    const fs::path out = dir / "out";
    const test::CommandResult r = run_roughgas(
        "restitution '" + f.string() + "' --out '" + out.string() + "' --set contact.cache=false", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(rows(out / "normal.csv")[0], "g_N,w,eps_N,duration,max_compression");
    EXPECT_EQ(rows(out / "tangential.csv")[0], "g_N,g_T,eps_T,beta,breaks");
}

TEST(Cli, ExistingOutputIsRefusedWithoutForce) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("ok.toml", small_case());
    const fs::path out = dir / "out";
    const std::string cmd = "restitution '" + f.string() + "' --out '" + out.string() + "'";
    ASSERT_EQ(run_roughgas(cmd, dir).status, 0);
    const std::string before = test::read_file(out / "normal.csv");

    const test::CommandResult again = run_roughgas(cmd + " --set material.dissipation=2e-5", dir);
    EXPECT_EQ(again.status, 2);
    EXPECT_NE(again.err.find("normal.csv exists (use --force to overwrite)"), std::string::npos) << again.err;
    EXPECT_EQ(test::read_file(out / "normal.csv"), before);

    ASSERT_EQ(run_roughgas(cmd + " --set material.dissipation=2e-5 --force", dir).status, 0);
    EXPECT_NE(test::read_file(out / "normal.csv"), before);
    EXPECT_EQ(entries(out), (std::vector<std::string>{"normal.csv", "tangential.csv"}));

    const fs::path file = dir.write("plain_file", "x");
    EXPECT_EQ(
        run_roughgas("restitution '" + f.string() + "' --out '" + file.string() + "' --force", dir).status,
        2);
}

TEST(Cli, RestitutionOutputDoesNotDependOnThreads) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("ok.toml", small_case());
    const std::string base = "restitution '" + f.string() + "' --set restitution.g_n_points=3 --out '";
    ASSERT_EQ(run_roughgas(base + (dir / "t1").string() + "' --threads 1", dir).status, 0);
    ASSERT_EQ(run_roughgas(base + (dir / "t2").string() + "' --threads 2", dir).status, 0);
    EXPECT_EQ(rows(dir / "t1" / "normal.csv"), rows(dir / "t2" / "normal.csv"));
    EXPECT_EQ(rows(dir / "t1" / "tangential.csv"), rows(dir / "t2" / "tangential.csv"));
}

} // namespace
} // namespace roughgas
