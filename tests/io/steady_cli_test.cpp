// The steady window of a shear run (DIR/steady.csv): the detector watches theta and a20 beside the
// temperatures and stresses, and the window's first rows against its second half, so that a window
// does not start while the spins are still relaxing.
#include "io_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

// Uniform shear flow of rough spheres at alpha = 0.7, beta = 0, from T = 1: T_tr settles within ~30
// collisions per particle, theta keeps falling until ~45 (0.244 at 35, 0.236 late). The mean of
// theta over the window's first 5 rows must agree with the late value (rows from 100 collisions per
// particle on, batch means over 5 batches) within 4 combined errors, the head's error taken as the
// mean of its rows' X_err (rows a collision apart are correlated: the bound for full correlation).
// A detector watching T_tr, T_rot and the stresses only would start the window at 35 here, theta
// 7.9 errors above its late value.
TEST(SteadyCli, ShearWindowStartsAfterThetaHasRelaxed) {
    const test::ScratchDir dir;
    const std::string usf = std::string(ROUGHGAS_SOURCE_DIR) + "/cases/usf_rough.toml";
    const test::CommandResult r = test::run_roughgas(
        "run '" + usf + "' --set collision.alpha=0.7 --set run.particles=20000 --set run.replicas=4 --set run.seed=1 "
        "--quiet --out '" + (dir / "out").string() + "'", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto s = test::read_csv(dir / "out" / "steady.csv");
    const auto m = test::read_csv(dir / "out" / "moments.csv");
    ASSERT_EQ(s.at("steady").at(0), 1.0);
    const std::vector<double>& cpp = m.at("coll_per_particle");
    const std::vector<double>& theta = m.at("theta");
    const std::vector<double>& theta_err = m.at("theta_err");
    std::size_t k0 = 0;
    while (k0 < cpp.size() && cpp[k0] < s.at("steady_from").at(0))
        ++k0;
    ASSERT_LE(k0 + 5, cpp.size());
    double head = 0, head_err = 0;
    for (std::size_t k = k0; k < k0 + 5; ++k) {
        head += theta[k] / 5;
        head_err += theta_err[k] / 5;
    }
    std::vector<double> late;
    for (std::size_t k = 0; k < cpp.size(); ++k)
        if (cpp[k] >= 100)
            late.push_back(theta[k]);
    ASSERT_GE(late.size(), 50u);
    const std::size_t per = late.size() / 5;
    std::vector<double> batch(5, 0.0);
    for (std::size_t b = 0; b < 5; ++b)
        for (std::size_t k = b * per; k < (b + 1) * per; ++k)
            batch[b] += late[k] / static_cast<double>(per);
    double mean = 0, var = 0;
    for (double x : batch)
        mean += x / 5;
    for (double x : batch)
        var += (x - mean) * (x - mean) / (5 * 4);
    EXPECT_LT(std::abs(head - mean), 4 * std::hypot(head_err, std::sqrt(var)))
        << "theta over the window's first rows (from " << cpp[k0] << " collisions per particle) " << head << " +- "
        << head_err << " has not relaxed to " << mean << " +- " << std::sqrt(var);
}

} // namespace
} // namespace roughgas
