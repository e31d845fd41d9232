// Builds the universal eps^N(w) table (see normal_table.hpp for the grid and the interpolant).
#include "roughgas/restitution/normal_table.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <stdexcept>

namespace roughgas {
namespace {

// Node j of the pseudo-log grid: binade e_min + j / K, mantissa 1 + (j mod K)/K.
double node_w(const NormalTableOptions& opt, std::size_t j) {
    const std::size_t K = std::size_t{1} << opt.mantissa_bits;
    const int e = opt.e_min + static_cast<int>(j / K);
    return std::ldexp(1.0 + static_cast<double>(j % K) / static_cast<double>(K), e);
}

// Derivative at x[c] of the polynomial interpolating (x[i], f[i]) over the 5 nodes i0..i0+4
// (Lagrange form): fourth-order accurate on any spacing, so binade edges need no special case.
double five_point_slope(const std::vector<double>& x, const std::vector<double>& f, std::size_t i0,
                        std::size_t c) {
    double d = 0;
    for (std::size_t i = i0; i < i0 + 5; ++i) {
        double li = 0; // L_i'(x_c)
        for (std::size_t m = i0; m < i0 + 5; ++m) {
            if (m == i) continue;
            double prod = 1.0 / (x[i] - x[m]);
            for (std::size_t l = i0; l < i0 + 5; ++l) {
                if (l == i || l == m) continue;
                prod *= (x[c] - x[l]) / (x[i] - x[l]);
            }
            li += prod;
        }
        d += li * f[i];
    }
    return d;
}

// Least-squares fit of (1 - eps)/u = s0 + s1 u^{1/2} + s2 u + s3 u^{3/2} + s4 u^2 on small u.
std::array<double, 5> fit_series(const DirectNormal& direct) {
    constexpr int n = 40;
    const double lo = 1e-4, hi = 1e-2;
    Eigen::MatrixXd M(n, 5);
    Eigen::VectorXd y(n);
    for (int i = 0; i < n; ++i) {
        const double u = lo * std::pow(hi / lo, i / double(n - 1));
        const double eps = direct.eps_n(std::pow(u, 5.0));
        const double r = std::sqrt(u);
        M.row(i) << 1.0, r, u, u * r, u * u;
        y(i) = (1.0 - eps) / u;
    }
    const Eigen::VectorXd s = M.colPivHouseholderQr().solve(y);
    return {s(0), s(1), s(2), s(3), s(4)};
}

} // namespace

NormalTable NormalTable::build(ContactModel model, NormalTableOptions opt) {
    if (opt.mantissa_bits < 1 || opt.mantissa_bits > 20 || opt.e_max <= opt.e_min || opt.e_min < -1000 ||
        opt.e_max > 1000)
        throw std::invalid_argument("NormalTable: invalid grid options");
    const auto start = std::chrono::steady_clock::now();
    NormalTable t;
    t.model_ = model;
    t.opt_ = opt;
    const DirectNormal direct{model, opt.tol};

    const std::size_t K = std::size_t{1} << opt.mantissa_bits;
    const std::size_t n_int = static_cast<std::size_t>(opt.e_max - opt.e_min) * K;
    const std::size_t n_nodes = n_int + 1;
    std::vector<double> w(n_nodes), x(n_nodes), f(n_nodes), d(n_nodes);
    for (std::size_t j = 0; j < n_nodes; ++j) {
        w[j] = node_w(opt, j);
        x[j] = std::log(w[j]);
    }
    // The expensive part: one contact integration per node, independent, so spread over threads.
#pragma omp parallel for schedule(dynamic, 16)
    for (std::size_t j = 0; j < n_nodes; ++j) f[j] = direct.eps_n(w[j]);

    for (std::size_t j = 1; j < n_nodes; ++j)
        if (!(f[j] <= f[j - 1]))
            throw std::runtime_error("NormalTable: eps_n not monotone in w at w = " + std::to_string(w[j]));

    // Slopes d eps / d ln w (5 nearest nodes, centred where possible).
    for (std::size_t j = 0; j < n_nodes; ++j) {
        const std::size_t i0 = std::min(j < 2 ? 0 : j - 2, n_nodes - 5);
        d[j] = five_point_slope(x, f, i0, j);
    }

    t.coef_.resize(n_int);
    for (std::size_t k = 0; k < n_int; ++k) {
        const double h = w[k + 1] - w[k];
        const double delta = f[k + 1] - f[k]; // secant in local t units (<= 0)
        double m0 = d[k] / w[k] * h, m1 = d[k + 1] / w[k + 1] * h;
        // Fritsch-Carlson: slopes of the secant's sign and alpha^2 + beta^2 <= 9 keep the cubic monotone.
        bool limited = false;
        if (delta == 0.0) {
            limited = m0 != 0.0 || m1 != 0.0;
            m0 = m1 = 0.0;
        } else {
            double a = m0 / delta, b = m1 / delta;
            if (a < 0) { a = 0; limited = true; }
            if (b < 0) { b = 0; limited = true; }
            if (a * a + b * b > 9.0) {
                const double s = 3.0 / std::sqrt(a * a + b * b);
                a *= s;
                b *= s;
                limited = true;
            }
            m0 = a * delta;
            m1 = b * delta;
        }
        t.limited_ += limited;
        t.coef_[k] = {f[k], m0, 3 * delta - 2 * m0 - m1, m0 + m1 - 2 * delta};
    }
    t.series_ = fit_series(direct);
    t.w_max_ = w[n_int];
    t.eps_max_ = f[n_int];
    t.slope_max_ = f[n_int] > 0 ? d[n_int] / f[n_int] : 0.0;
    t.finish_layout();
    t.build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return t;
}

void NormalTable::finish_layout() {
    const int shift = 52 - opt_.mantissa_bits;
    // Bits of w_min >> shift: biased exponent and the top mantissa bits, i.e. the index of interval 0.
    index_base_ = static_cast<std::uint64_t>(opt_.e_min + 1023) << opt_.mantissa_bits;
    t_scale_ = std::ldexp(1.0, -shift); // low mantissa bits -> local coordinate t in [0, 1)
    w_min_ = std::ldexp(1.0, opt_.e_min);
    w_max_ = std::ldexp(1.0, opt_.e_max);
}

double NormalTable::below(double w) const {
    if (w <= 0) return 1.0;
    const double u = std::pow(w, 0.2), r = std::sqrt(u);
    const auto& s = series_;
    return 1.0 - u * (s[0] + r * (s[1] + r * (s[2] + r * (s[3] + r * s[4]))));
}

double NormalTable::above(double w) const {
    if (std::isinf(w)) return slope_max_ < 0 ? 0.0 : eps_max_;
    return eps_max_ * std::pow(w / w_max_, slope_max_);
}

std::string NormalTable::key_for(ContactModel model, const NormalTableOptions& opt) {
    std::ostringstream s;
    s.precision(17);
    s << "roughgas " << ROUGHGAS_VERSION << " normal_table form=" << name(model.form) << " end=" << name(model.end)
      << " e_min=" << opt.e_min << " e_max=" << opt.e_max << " mantissa_bits=" << opt.mantissa_bits
      << " rel=" << opt.tol.rel << " abs=" << opt.tol.abs;
    return s.str();
}

std::vector<double> NormalTable::serialize() const {
    std::vector<double> out;
    out.reserve(coef_.size() * 4 + 9);
    for (const auto& c : coef_) out.insert(out.end(), c.begin(), c.end());
    out.insert(out.end(), series_.begin(), series_.end());
    out.push_back(eps_max_);
    out.push_back(slope_max_);
    out.push_back(static_cast<double>(limited_));
    out.push_back(build_seconds_);
    return out;
}

NormalTable NormalTable::deserialize(ContactModel model, NormalTableOptions opt, const std::vector<double>& data) {
    const std::size_t n_int = static_cast<std::size_t>(opt.e_max - opt.e_min) << opt.mantissa_bits;
    if (data.size() != n_int * 4 + 9) throw std::runtime_error("NormalTable: payload size does not match the grid");
    NormalTable t;
    t.model_ = model;
    t.opt_ = opt;
    t.coef_.resize(n_int);
    std::size_t i = 0;
    for (auto& c : t.coef_)
        for (auto& v : c) v = data[i++];
    for (auto& v : t.series_) v = data[i++];
    t.eps_max_ = data[i++];
    t.slope_max_ = data[i++];
    t.limited_ = static_cast<int>(data[i++]);
    t.build_seconds_ = data[i++];
    t.finish_layout();
    return t;
}

} // namespace roughgas
