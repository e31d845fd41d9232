// A sheared box with Lees-Edwards boundaries against the homogeneous uniform shear flow of the same
// grains: the box's steady theta, a*, eta* and reduced pressure tensor P*_ij are the homogeneous
// engine's once the DSMC's cell-size and time-step errors of the viscosity are put in.
// CPU: about 20 s (Release; the box 3e5 grains to 80 collisions per particle, the homogeneous gas 4
// replicas of 1e5 to 130).
#include "../io/io_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

// The DSMC raises the viscosity by the factor 1 + eps,
//   eps = 16/(45 pi) (dy/lambda)^2 + 16/(75 pi) (c0 dt/lambda)^2,
// dy the cell's edge along the gradient (Alexander, Garcia & Alder 1998) and dt the step, c0 =
// sqrt(2T/m) (Hadjiconstantinou 2000). A step of s mean free times 1/nu, nu = 4 n sigma^2 sqrt(pi T/m),
// has c0 dt/lambda = s sqrt(pi)/2; the box's steps are s = 0.2 mean free times of its densest slab,
// at most 0.2 of the box's mean. The laws are the elastic gas's; the rough inelastic gas of these
// runs follows them too (docs/validation.md).
//
// In the steady state the viscous heating -P_xy a balances the collisional loss, which at given
// alpha, beta is a fixed multiple of n T nu: eta* a*^2 is fixed. A viscosity raised by 1 + eps
// therefore gives eta* (1 + eps), a* / sqrt(1 + eps), P*_xy sqrt(1 + eps), and theta unchanged;
// the diagonal P*_ii are compared unchanged.
//
// Allowed beyond 4 combined standard errors: 0.5 % for eta*, half of it for a* and P*_xy, which move
// as the square root of the viscosity, and 0.5 % for theta and the diagonal P*_ii, which move by its
// next orders. With the laws put in, the box of these runs (104 grains per cell) is 0.35 % above the
// homogeneous eta* (0.28 % with 347 grains per cell and the laws' terms measured away): the laws'
// next orders, and fewer grains per cell (0.4 % more with 35 per cell, 1.5 % with 12); a* is 0.27 %
// below, P*_xy 0.08 % above, the diagonal within 0.2 %. Without the laws eta* is 1.2 % above, a*
// 0.7 % below and P*_xy 0.5 % above: those checks fail.
TEST(BoxShearRheology, LeesEdwardsBoxReproducesTheHomogeneousShearFlowAfterTheCellSizeCorrection) {
    const test::ScratchDir dir;
    const fs::path root = ROUGHGAS_SOURCE_DIR;
    // The box: cases/box_usf.toml (alpha = 0.9, beta = 0; a cube of 5 mean free paths, 12 x 20 x
    // 12 cells, steps of 0.2 mean free times), started near its steady temperature.
    const test::CommandResult b = test::run_roughgas(
        "run " + q(root / "cases" / "box_usf.toml") + " --quiet --threads 2 --out " + q(dir / "box") +
            " --set run.particles=300000 --set run.end=80",
        dir);
    ASSERT_EQ(b.status, 0) << b.err;
    // The homogeneous gas with the same grains, started at its steady temperatures, with Strang steps
    // of 0.0625 mean free times (their error in eta* is 0.03 %: tests/data/usf_rough_reference.csv).
    const test::CommandResult h = test::run_roughgas(
        "run " + q(root / "tests" / "data" / "usf_rough_reference.toml") + " --quiet --threads 2 --out " +
            q(dir / "hom") + " --set run.end=130 --set shear.time_step=0.0625",
        dir);
    ASSERT_EQ(h.status, 0) << h.err;
    const auto bs = test::read_csv(dir / "box" / "steady.csv");
    const auto hs = test::read_csv(dir / "hom" / "steady.csv");
    ASSERT_EQ(bs.at("steady").at(0), 1.0) << "the box reached no steady state";
    ASSERT_EQ(hs.at("steady").at(0), 1.0) << "the homogeneous gas reached no steady state";

    const double lambda = 1.0 / (std::sqrt(2.0) * std::numbers::pi * 0.02);
    const double dy = 56.25 / 20, step = 0.2 * std::sqrt(std::numbers::pi) / 2;
    const double eps = 16.0 / (45.0 * std::numbers::pi) * (dy / lambda) * (dy / lambda) +
                       16.0 / (75.0 * std::numbers::pi) * step * step;
    const struct {
        const char* col;
        double factor, allowed;
    } expected[] = {
        {"eta_star", 1 + eps, 0.005},
        {"a_star", 1 / std::sqrt(1 + eps), 0.0025},
        {"P_xy_star", std::sqrt(1 + eps), 0.0025},
        {"theta", 1.0, 0.005},
        {"P_xx_star", 1.0, 0.005},
        {"P_yy_star", 1.0, 0.005},
        {"P_zz_star", 1.0, 0.005},
    };
    for (const auto& e : expected) {
        const std::string err = std::string(e.col) + "_err";
        const double box = bs.at(e.col).at(0), hom = hs.at(e.col).at(0);
        const double ratio = box / (hom * e.factor);
        const double se = std::hypot(bs.at(err).at(0) / box, hs.at(err).at(0) / hom);
        EXPECT_NEAR(ratio, 1.0, 4 * se + e.allowed) << e.col << ": box " << box << ", homogeneous " << hom;
    }
    // The correction is there to be seen: the box's eta* is above the homogeneous one by more than
    // its errors.
    const double box = bs.at("eta_star").at(0), hom = hs.at("eta_star").at(0);
    EXPECT_GT(box - hom, 4 * std::hypot(bs.at("eta_star_err").at(0), hs.at("eta_star_err").at(0)));
}

}  // namespace
}  // namespace roughgas
