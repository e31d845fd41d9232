// The first-Sonine cooling state of rough spheres: observables/sonine_cooling_state.hpp.
#include "roughgas/observables/sonine_cooling_state.hpp"

#include "roughgas/observables/sonine_rates.hpp"
#include "roughgas/observables/theory.hpp"

#include <Eigen/Dense>
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace roughgas {
namespace {

// The linearised cumulant equations at fixed theta, M (a20, a02, a11) = v:
//   R_c4 - 5 R_c2 - 5 R_c2^0 a20 = 0,  R_w4 - 5 R_w2 - 5 R_w2^0 a02 = 0,
//   R_c2w2 - (3/2)(R_c2 + R_w2) - (3/2)(R_c2^0 + R_w2^0) a11 = 0.
struct LinearCumulants {
    Eigen::Matrix3d M;
    Eigen::Vector3d v;
    SonineRates rates;
};

LinearCumulants linear_cumulants(double alpha, double beta, double q, double theta) {
    LinearCumulants s;
    s.rates = sonine_rates(alpha, beta, q, theta);
    const SonineRates& r = s.rates;
    const auto row = [&](int i, const SonineRate& high, const SonineRate& low, double k, double diagonal) {
        // high - k low, with k low^0 more on the row's own cumulant
        s.M(i, 0) = high.a20 - k * low.a20;
        s.M(i, 1) = high.a02 - k * low.a02;
        s.M(i, 2) = high.a11 - k * low.a11;
        s.M(i, i) -= diagonal;
        s.v(i) = -(high.one - k * low.one);
    };
    row(0, r.c4, r.c2, 5.0, 5 * r.c2.one);
    row(1, r.w4, r.w2, 5.0, 5 * r.w2.one);
    const SonineRate sum{r.c2.one + r.w2.one, r.c2.a20 + r.w2.a20, r.c2.a02 + r.w2.a02, r.c2.a11 + r.w2.a11};
    row(2, r.c2w2, sum, 1.5, 1.5 * sum.one);
    return s;
}

struct ThetaCondition {
    double value = 0;       // R_c2 - R_w2 at the linear system's cumulants
    double determinant = 0; // det M
};

ThetaCondition theta_condition(double alpha, double beta, double q, double theta) {
    const LinearCumulants s = linear_cumulants(alpha, beta, q, theta);
    const Eigen::Vector3d a = s.M.partialPivLu().solve(s.v);
    return {s.rates.c2.at(a(0), a(1), a(2)) - s.rates.w2.at(a(0), a(1), a(2)), s.M.determinant()};
}

SonineCoolingState state_at(double alpha, double beta, double q, double theta) {
    const LinearCumulants s = linear_cumulants(alpha, beta, q, theta);
    const Eigen::Vector3d a = s.M.partialPivLu().solve(s.v);
    return {theta, a(0), a(1), a(2), (2.0 / 3.0) * s.rates.c2.at(a(0), a(1), a(2)) / (1 - a(0) / 16)};
}

// The root of the theta condition on the branch of x0 = ln theta*: steps of h in ln theta away
// from x0 on either side, a side ending where det M changes sign (a pole) or after `steps` steps;
// the first sign change of the condition on a side is refined by TOMS 748; the root nearer x0 wins.
std::optional<double> branch_root(double alpha, double beta, double q, double x0) {
    const auto F = [&](double x) { return theta_condition(alpha, beta, q, std::exp(x)); };
    const ThetaCondition f0 = F(x0);
    if (f0.value == 0)
        return x0;
    constexpr double h = 0.01;
    constexpr int steps = 600;
    std::optional<double> best;
    for (const double side : {-1.0, 1.0}) {
        double xa = x0;
        ThetaCondition fa = f0;
        for (int k = 1; k <= steps; ++k) {
            const double xb = x0 + side * k * h;
            const ThetaCondition fb = F(xb);
            if (std::signbit(fb.determinant) != std::signbit(fa.determinant))
                break; // a pole of the linear system: the branch ends
            if (fb.value == 0 || std::signbit(fb.value) != std::signbit(fa.value)) {
                double x = xb;
                if (fb.value != 0) {
                    std::uintmax_t iterations = 200;
                    const auto [lo, hi] = boost::math::tools::toms748_solve(
                        [&](double y) { return F(y).value; }, std::min(xa, xb), std::max(xa, xb),
                        side < 0 ? fb.value : fa.value, side < 0 ? fa.value : fb.value,
                        boost::math::tools::eps_tolerance<double>(52), iterations);
                    x = 0.5 * (lo + hi);
                }
                if (!best || std::abs(x - x0) < std::abs(*best - x0))
                    best = x;
                break;
            }
            xa = xb;
            fa = fb;
        }
    }
    return best;
}

} // namespace

std::optional<SonineCoolingState> sonine_cooling_state(double alpha, double beta, double q) {
    if (!(alpha >= 0 && alpha <= 1) || !(beta >= -1 && beta <= 1) || !(q > 0))
        throw std::invalid_argument("sonine_cooling_state: alpha must be in [0, 1], beta in [-1, 1], q > 0");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (beta == -1) { // smooth: the a20 equation alone (theta does not enter its coefficients)
        const LinearCumulants s = linear_cumulants(alpha, beta, q, 1.0);
        const double a20 = s.v(0) / s.M(0, 0);
        const double zeta = (2.0 / 3.0) * s.rates.c2.at(a20, 0, 0) / (1 - a20 / 16);
        return SonineCoolingState{theta_fixed_point(alpha, beta, q), a20, nan, nan, zeta};
    }
    const std::optional<double> x = branch_root(alpha, beta, q, std::log(theta_fixed_point(alpha, beta, q)));
    if (!x)
        return std::nullopt;
    const SonineCoolingState s = state_at(alpha, beta, q, std::exp(*x));
    if (!(s.a20 >= -0.4 && s.a02 >= -0.4))
        return std::nullopt;
    return s;
}

} // namespace roughgas
