// The late-time summary of a cooling run (DIR/scaled.csv): the scaled homogeneous cooling state
// found by the steady-state detector, which watches the species' temperature ratio, so that its
// window starts only once the ratio has relaxed; its values are the window's averages.
#include "io_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

// A binary mixture of smooth spheres, alpha = 0.9, mass ratio 2, equal sizes and fractions: the
// species' temperature ratio relaxes over ~10 collisions per particle while theta (smooth grains
// keep their spins) grows without end.
TEST(ScaledCli, MixtureTemperatureRatioWithItsErrorAfterItHasRelaxed) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("mix.toml", R"([run]
particles = 20000
replicas = 4
end = 100.0
output_every = 1.0
seed = 11
[[species]]
name = "light"
mass = 1.0
radius = 0.5
fraction = 0.5
[[species]]
name = "heavy"
mass = 2.0
radius = 0.5
fraction = 0.5
[collision]
model = "constant"
alpha = 0.9
beta = -1.0
)");
    const test::CommandResult r = test::run_roughgas("run '" + f.string() + "' --out '" + (dir / "out").string() + "'", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    // The headline numbers on stderr's last line: the ratio, not theta (undefined as a scaled value here).
    const std::string last = r.err.substr(r.err.rfind("roughgas run: scaled state"));
    EXPECT_NE(last.find("T_tr.light/T_tr.heavy = "), std::string::npos) << r.err;
    EXPECT_EQ(last.find("theta"), std::string::npos) << last;

    const auto s = test::read_csv(dir / "out" / "scaled.csv");
    const auto m = test::read_csv(dir / "out" / "moments.csv");
    const std::string ratio = "T_tr.light/T_tr.heavy";
    ASSERT_EQ(s.at("steady").at(0), 1.0);
    const double from = s.at("steady_from").at(0), value = s.at(ratio).at(0), err = s.at(ratio + "_err").at(0);
    ASSERT_GT(err, 0.0);

    // A hand-made late-time average of the same rows: from 40 collisions per particle on, where the
    // ratio is surely relaxed; its error from the rows' scatter (rows 1 collision per particle apart
    // are nearly independent in the ratio, as the batch means assume).
    double sum = 0, sum2 = 0;
    int n = 0;
    const std::vector<double>& cpp = m.at("coll_per_particle");
    const std::vector<double>& x = m.at(ratio);
    for (std::size_t k = 0; k < x.size(); ++k)
        if (cpp[k] >= 40) {
            sum += x[k];
            sum2 += x[k] * x[k];
            ++n;
        }
    ASSERT_GE(n, 50);
    const double hand = sum / n, hand_err = std::sqrt((sum2 / n - hand * hand) / (n - 1));
    EXPECT_LT(std::abs(value - hand), 4 * std::sqrt(err * err + hand_err * hand_err))
        << "scaled " << value << " +- " << err << ", hand " << hand << " +- " << hand_err;
    // The ratio at 1 collision per particle is still far from relaxed (the light grains are hotter
    // by a few per cent more): the window must start later, at a row whose ratio has relaxed.
    EXPECT_GT(from, 1.5) << "the window starts before the ratio has relaxed";
    std::size_t k0 = 0;
    while (k0 < cpp.size() && cpp[k0] < from)
        ++k0;
    ASSERT_LT(k0, cpp.size());
    const double at_start_err = m.at(ratio + "_err").at(k0);
    EXPECT_LT(std::abs(x[k0] - hand), 4 * std::sqrt(at_start_err * at_start_err + hand_err * hand_err))
        << "the ratio at the window's start (" << from << " collisions per particle) " << x[k0] << " +- "
        << at_start_err << " has not relaxed to " << hand;
}

} // namespace
} // namespace roughgas

namespace roughgas {
namespace {

// Restitution that depends on the impact speed has no scaled state: the run says so whatever the
// detector found (the viscoelastic ice case, a short run), and a constant-restitution run does not.
TEST(ScaledCli, SpeedDependentRestitutionHasNoScaledState) {
    const test::ScratchDir dir;
    const std::string ice = std::string(ROUGHGAS_SOURCE_DIR) + "/cases/hcs_viscoelastic_ice.toml";
    const test::CommandResult r = test::run_roughgas(
        "run '" + ice + "' --set run.particles=2000 --set run.end=20 --out '" + (dir / "ice").string() + "'", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("depends on the impact speed"), std::string::npos) << r.err;
    // One calm line: the last row's values, no averages (with errors) of a theta that grows for ever.
    EXPECT_NE(r.err.find("roughgas run: no scaled state: the restitution depends on the impact speed"),
              std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("+-"), std::string::npos) << r.err;
    const std::string rough = std::string(ROUGHGAS_SOURCE_DIR) + "/cases/hcs_rough.toml";
    const test::CommandResult c = test::run_roughgas(
        "run '" + rough + "' --set run.particles=2000 --set run.end=20 --out '" + (dir / "rough").string() + "'", dir);
    ASSERT_EQ(c.status, 0) << c.err;
    EXPECT_EQ(c.err.find("impact speed"), std::string::npos) << c.err;
}

} // namespace
} // namespace roughgas

namespace roughgas {
namespace {

// A mixture with constant restitution carries the theory's temperature ratios beside the measured
// ones: the ratio of the theory's species temperatures in every row, and not among the columns the
// scaled-state detector watches (it is not a measurement).
TEST(ScaledCli, MixtureRatiosHaveTheirTheoryColumns) {
    const test::ScratchDir dir;
    const std::string mix = std::string(ROUGHGAS_SOURCE_DIR) + "/cases/hcs_mixture.toml";
    const test::CommandResult r = test::run_roughgas(
        "run '" + mix + "' --quiet --set run.particles=2000 --set run.end=5 --out '" + (dir / "mix").string() + "'",
        dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto m = test::read_csv(dir / "mix" / "moments.csv");
    const std::vector<double>& ratio = m.at("T_tr.small/T_tr.large_theory");
    const std::vector<double>& rot = m.at("T_rot.small/T_rot.large_theory");
    for (std::size_t k = 0; k < ratio.size(); ++k) {
        EXPECT_NEAR(ratio[k], m.at("T_tr_theory.small")[k] / m.at("T_tr_theory.large")[k], 1e-15 * ratio[k]) << k;
        EXPECT_NEAR(rot[k], m.at("T_rot_theory.small")[k] / m.at("T_rot_theory.large")[k], 1e-15 * rot[k]) << k;
    }
    const std::string scaled = test::read_file(dir / "mix" / "scaled.csv");
    const std::size_t note = scaled.find("drift criterion on");
    ASSERT_NE(note, std::string::npos);
    EXPECT_EQ(scaled.substr(note, scaled.find('\n', note) - note).find("_theory"), std::string::npos);
}

} // namespace
} // namespace roughgas

namespace roughgas {
namespace {

// The reduced cooling rate of the scaled state of smooth spheres at alpha = 0.5, per collision per
// particle: zeta* = ((1 - alpha^2)/3)(1 + 3 a2/16)/(1 - a2/16) to first order in the fourth cumulant
// a2 (the cooling rate gains 3 a2/16, the collision frequency loses a2/16; van Noije & Ernst 1998),
// with the run's own a20, against 0.25 for a Maxwellian: the a2 term (+1.2 %) is 15-20 standard
// errors here. The allowance beyond 4 standard errors, 0.1 % of zeta*, is for the sixth cumulant a3,
// which the first-order form leaves out: its term is 0.029 a3 zeta* (the same Gaussian averages of
// g and g^3 with the third Sonine polynomial), 0.1 % for |a3| = 0.035. The theory column is the
// Maxwellian's (1 - alpha^2)/3 in every row.
TEST(ScaledCli, SmoothGasCoolsAtTheSonineRatePerCollision) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("smooth.toml", R"([run]
particles = 20000
replicas = 4
end = 80.0
output_every = 1.0
seed = 5
[[species]]
name = "grain"
mass = 1.0
radius = 0.5
[collision]
model = "constant"
alpha = 0.5
beta = -1.0
)");
    const test::CommandResult r = test::run_roughgas("run '" + f.string() + "' --out '" + (dir / "out").string() + "'", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string last = r.err.substr(r.err.rfind("roughgas run: scaled state"));
    EXPECT_NE(last.find("zeta_star = "), std::string::npos) << last; // a headline number, and monitored
    const auto s = test::read_csv(dir / "out" / "scaled.csv");
    const auto m = test::read_csv(dir / "out" / "moments.csv");
    ASSERT_EQ(s.at("steady").at(0), 1.0);
    const double zeta = s.at("zeta_star").at(0), zeta_err = s.at("zeta_star_err").at(0);
    const double a2 = s.at("a20").at(0), a2_err = s.at("a20_err").at(0);
    const double maxwell = (1 - 0.25) / 3;
    const double sonine = maxwell * (1 + 3 * a2 / 16) / (1 - a2 / 16);
    const double err = std::hypot(zeta_err, maxwell / 4 * a2_err);
    ASSERT_GT(zeta_err, 0.0);
    EXPECT_LT(std::abs(zeta - sonine), 4 * err + 1e-3 * sonine)
        << "zeta* " << zeta << " +- " << zeta_err << ", first Sonine " << sonine << " (a2 = " << a2 << ")";
    EXPECT_GT(std::abs(zeta - maxwell), 10 * err) << "the a2 term is not resolved: the test cannot tell";
    const std::vector<double>& theory = m.at("zeta_star_theory");
    for (double v : theory)
        EXPECT_NEAR(v, maxwell, 1e-14);
    EXPECT_TRUE(std::isnan(m.at("zeta_star").at(0)));
}

} // namespace
} // namespace roughgas

namespace roughgas {
namespace {

// A cooling box that clusters has no scaled homogeneous state: cases/box_cooling_slab.toml with a
// quarter of its grains (3.5 per cell) to 120 collisions per particle. Its density's longest waves
// grow from the start (the heat mode of the cooling state is unstable in a box this large); the
// structure factor of the smallest |k| leaves a uniform gas's range within the run, and the
// summary says so instead of averaging the drifting zeta_star and a20 as a scaled state.
TEST(ScaledCli, AClusteringBoxHasNoScaledState) {
    const test::ScratchDir dir;
    const std::string slab = std::string(ROUGHGAS_SOURCE_DIR) + "/cases/box_cooling_slab.toml";
    const test::CommandResult r = test::run_roughgas(
        "run '" + slab + "' --set run.particles=50000 --set run.end=120 --set 'domain.cells=[120, 120, 1]' --out '" +
            (dir / "slab").string() + "'",
        dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("no scaled state: the box is not homogeneous from "), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("roughgas run: no scaled state: the box is not homogeneous from "), std::string::npos)
        << r.err;
    const auto scaled = test::read_csv(dir / "slab" / "scaled.csv");
    EXPECT_EQ(scaled.at("steady").at(0), 0.0);
}

// A gas that does not cool (elastic smooth grains in a box with a transverse wave that decays)
// has no scaled state: it relaxes to equilibrium.
TEST(ScaledCli, AnElasticGasHasNoScaledState) {
    const test::ScratchDir dir;
    const std::string wave = std::string(ROUGHGAS_SOURCE_DIR) + "/cases/box_shear_mode.toml";
    const test::CommandResult r = test::run_roughgas(
        "run '" + wave +
            "' --set collision.alpha=1 --set collision.beta=-1 --set run.particles=40000 --set run.end=10 "
            "--set run.replicas=1 --out '" + (dir / "wave").string() + "'",
        dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("no scaled state: elastic: equilibrium"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("scaled state from"), std::string::npos) << r.out;
    EXPECT_EQ(test::read_csv(dir / "wave" / "scaled.csv").at("steady").at(0), 0.0);
}

} // namespace
} // namespace roughgas

namespace roughgas {
namespace {

// The shipped cooling cases report their scaled state: cases/hcs_smooth.toml as shipped (one
// replica, log-spaced rows, whose zeta_star rows are a hundred times noisier early than late), and
// the small periodic box of cases/box_hcs_rough.toml (with a quarter of its grains), whose theta
// equals the homogeneous engine's at the same alpha, beta and grains within the errors: a box
// below the instability length stays homogeneous.
TEST(ScaledCli, TheShippedCoolingCasesReportTheirScaledState) {
    const test::ScratchDir dir;
    const std::string cases = std::string(ROUGHGAS_SOURCE_DIR) + "/cases/";
    const test::CommandResult smooth =
        test::run_roughgas("run '" + cases + "hcs_smooth.toml' --quiet --out '" + (dir / "smooth").string() + "'", dir);
    ASSERT_EQ(smooth.status, 0) << smooth.err;
    EXPECT_NE(smooth.out.find("scaled state from"), std::string::npos) << smooth.out;
    const auto s = test::read_csv(dir / "smooth" / "scaled.csv");
    EXPECT_EQ(s.at("steady").at(0), 1.0);
    EXPECT_LT(s.at("steady_from").at(0), 20.0); // a20 has relaxed within ~10 collisions per particle

    const test::CommandResult box =
        test::run_roughgas("run '" + cases + "box_hcs_rough.toml' --quiet --set run.particles=25000 --out '" +
                               (dir / "box").string() + "'",
                           dir);
    ASSERT_EQ(box.status, 0) << box.err;
    EXPECT_NE(box.out.find("scaled state from"), std::string::npos) << box.out;
    const auto b = test::read_csv(dir / "box" / "scaled.csv");
    ASSERT_EQ(b.at("steady").at(0), 1.0);
    // The box's gas without the box: the same grains, alpha, beta and rows in the homogeneous engine.
    const fs::path f = dir.write("hom.toml", R"([run]
particles = 25000
replicas = 4
end = 300.0
output_every = 0.5
output_spacing = "log"
density = 0.02
seed = 2
[[species]]
name = "grain"
mass = 1.0
radius = 0.5
[collision]
model = "constant"
alpha = 0.9
beta = 0.4
)");
    const test::CommandResult hom =
        test::run_roughgas("run '" + f.string() + "' --quiet --out '" + (dir / "hom").string() + "'", dir);
    ASSERT_EQ(hom.status, 0) << hom.err;
    const auto h = test::read_csv(dir / "hom" / "scaled.csv");
    ASSERT_EQ(h.at("steady").at(0), 1.0);
    const double err = std::hypot(b.at("theta_err").at(0), h.at("theta_err").at(0));
    EXPECT_LT(std::abs(b.at("theta").at(0) - h.at("theta").at(0)), 4 * err)
        << "box " << b.at("theta").at(0) << " homogeneous " << h.at("theta").at(0) << " +- " << err;
}

} // namespace
} // namespace roughgas
