// run.equation, run.pair_correlation and run.chi: what they accept and refuse, the echo, and the
// RunSpec's EnskogSpec; and the dense-gas warnings of run and check.
#include "case_errors.hpp"
#include "io_test_support.hpp"

#include "roughgas/io/case_file.hpp"
#include "roughgas/io/run_spec_from_case.hpp"

#include <gtest/gtest.h>

namespace roughgas {
namespace {

using test::replaced;

// Rough grains of unit diameter at phi = 0.2 (n = 0.382) in the Enskog equation.
std::string dense_case() {
    return R"([run]
particles = 2000
end = 1.0
density = 0.382
equation = "enskog"

[[species]]
mass = 1.0
radius = 0.5

[collision]
model = "constant"
alpha = 0.9
beta = 0.4
)";
}

using test::error_of;
using test::refused;

TEST(EnskogCase, CarnahanStarlingByDefaultAConstantOnRequest) {
    const CaseConfig c = parse_case(dense_case(), "case.toml");
    EXPECT_EQ(c.run.equation, KineticEquation::enskog);
    EXPECT_EQ(c.run.pair_correlation, PairCorrelationModel::carnahan_starling);
    const RunSpec s = run_spec_from_case(c);
    ASSERT_TRUE(s.enskog.has_value());
    EXPECT_EQ(s.enskog->model, PairCorrelationModel::carnahan_starling);
    EXPECT_EQ(parse_case(emit_case(c), "echo.toml"), c);
    const CaseConfig k = parse_case(
        replaced(dense_case(), "equation = \"enskog\"", "equation = \"enskog\"\npair_correlation = \"constant\"\nchi = 1.5"),
        "case.toml");
    const RunSpec t = run_spec_from_case(k);
    ASSERT_TRUE(t.enskog.has_value());
    EXPECT_EQ(t.enskog->model, PairCorrelationModel::constant);
    EXPECT_EQ(t.enskog->chi, 1.5);
    EXPECT_EQ(parse_case(emit_case(k), "echo.toml"), k);
    // The Boltzmann equation by default: no EnskogSpec.
    const CaseConfig b = parse_case(replaced(dense_case(), "equation = \"enskog\"\n", ""), "case.toml");
    EXPECT_EQ(b.run.equation, KineticEquation::boltzmann);
    EXPECT_FALSE(run_spec_from_case(b).enskog.has_value());
}

TEST(EnskogCase, RefusesWhatHasNoMeaning) {
    const std::string e = "equation = \"enskog\"";
    EXPECT_TRUE(refused(replaced(dense_case(), e, "equation = \"dense\""), {}, "run.equation"));
    EXPECT_TRUE(refused(replaced(dense_case(), e, e + "\npair_correlation = \"constant\""), {}, "run.chi: required"));
    EXPECT_TRUE(refused(replaced(dense_case(), e, e + "\npair_correlation = \"constant\"\nchi = 0.0"), {}, "run.chi"));
    EXPECT_TRUE(refused(replaced(dense_case(), e, e + "\npair_correlation = \"constant\"\nchi = -2.0"), {}, "run.chi"));
    EXPECT_TRUE(refused(replaced(dense_case(), e, e + "\nchi = 2.0"), {}, "run.chi = 2: a constant chi"));
    // The Boltzmann equation keeps the Enskog keys without reading them: a warning each.
    const CaseConfig kept = parse_case(replaced(dense_case(), e, "chi = 2.0\npair_correlation = \"constant\""), "case.toml");
    ASSERT_EQ(kept.unused.size(), 2u);
    EXPECT_NE(kept.unused[0].find("run.pair_correlation is not used by run.equation = \"boltzmann\""), std::string::npos);
    EXPECT_NE(kept.unused[1].find("run.chi is not used"), std::string::npos);
    // At or beyond the densest packing: no gas.
    EXPECT_TRUE(refused(replaced(dense_case(), "density = 0.382", "density = 1.5"), {}, "run.density = 1.5"));
    // Sheared only with the hard-sphere kernel.
    const std::string sheared = replaced(dense_case(), "[run]", "[run]\nkind = \"shear\"") + "\n[shear]\nrate = 0.1\n";
    EXPECT_EQ(error_of(sheared), "");
    EXPECT_TRUE(refused(replaced(sheared, "[run]", "[run]\nkernel = \"maxwell\""), {},
                        "run.kernel = \"maxwell\" with run.equation = \"enskog\""));
}

// In a box (Lees-Edwards shear too): hard spheres, random partners, an odd smoothing cube, periodic
// sides of at least two diameters; domain.chi_cells is echoed, and a Boltzmann run warns of it.
TEST(EnskogCase, BoxesAndWhatTheyRefuse) {
    const std::string box = dense_case() + "\n[domain]\nsize = [10.0, 10.0, 10.0]\ncells = [20, 20, 20]\n";
    EXPECT_EQ(error_of(box), "");
    const CaseConfig c = parse_case(box + "chi_cells = 5\n", "case.toml");
    EXPECT_EQ(c.domain->chi_cells, 5);
    EXPECT_EQ(run_spec_from_case(c).domain->chi_cells, 5);
    EXPECT_EQ(parse_case(emit_case(c), "echo.toml"), c);
    EXPECT_TRUE(refused(box + "chi_cells = 4\n", {}, "domain.chi_cells = 4: the smoothing cube is centred"));
    EXPECT_TRUE(refused(box + "chi_cells = -1\n", {}, "domain.chi_cells"));
    EXPECT_TRUE(refused(box + "partners = \"nearest\"\n", {}, "domain.partners = \"nearest\" with run.equation"));
    EXPECT_TRUE(refused(replaced(box, "size = [10.0, 10.0, 10.0]", "size = [10.0, 1.5, 10.0]"), {},
                        "domain.size[1] = 1.5: a periodic side of an Enskog box"));
    // A walled axis may be short: no image across a wall.
    EXPECT_EQ(error_of(replaced(replaced(box, "size = [10.0, 10.0, 10.0]", "size = [10.0, 1.5, 10.0]"),
                                "cells = [20, 20, 20]", "cells = [20, 3, 20]\nboundary = [\"periodic\", \"walls\", \"periodic\"]") +
                       "\n[wall_lower]\nkind = \"specular\"\n\n[wall_upper]\nkind = \"specular\"\n"),
              "");
    // Sheared by Lees-Edwards boundaries.
    const std::string sheared = replaced(box, "[run]", "[run]\nkind = \"shear\"") + "\n[shear]\nrate = 0.1\n";
    EXPECT_EQ(error_of(sheared), "");
    EXPECT_TRUE(refused(replaced(box, "[run]", "[run]\nkernel = \"maxwell\""), {},
                        "run.kernel = \"maxwell\" with run.equation = \"enskog\" and [domain]"));
    const CaseConfig b = parse_case(replaced(box, "equation = \"enskog\"\n", "") + "chi_cells = 5\n", "case.toml");
    ASSERT_EQ(b.unused.size(), 1u);
    EXPECT_NE(b.unused[0].find("domain.chi_cells is not used by run.equation = \"boltzmann\""), std::string::npos);
}

} // namespace
} // namespace roughgas
