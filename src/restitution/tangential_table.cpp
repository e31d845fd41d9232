// Builds the eps^T table of one pair (see tangential_table.hpp).
#include "roughgas/restitution/tangential_table.hpp"

#include <chrono>
#include <sstream>
#include <stdexcept>

namespace roughgas {
namespace {

// Runs f(i) for every point of a batch on all threads: each is an independent contact integration.
template <class F> void parallel_points(std::size_t n, F&& f) {
#pragma omp parallel for schedule(dynamic, 1)
    for (std::size_t i = 0; i < n; ++i) f(i);
}

AdaptiveOptions per_binade(AdaptiveOptions o, double x_lo, double x_hi) {
    o.root_cells_x = std::max(1, static_cast<int>(std::ceil((x_hi - x_lo) * o.root_cells_x)));
    return o;
}

} // namespace

TangentialTable TangentialTable::build(const ContactPair& pair, TangentialTableOptions opt) {
    if (!(opt.g_min > 0) || !(opt.g_max > opt.g_min)) throw std::invalid_argument("TangentialTable: bad g range");
    const auto start = std::chrono::steady_clock::now();
    TangentialTable t;
    t.opt_ = opt;
    t.set_band();
    t.direct_ = DirectTangential{pair, opt.tol};
    // Whole binades: pseudo_log2 has a kink at every power of two, and cells that never straddle
    // one see a smooth function. The table so covers at least [g_min, g_max].
    const double x_lo = std::floor(pseudo_log2(opt.g_min)), x_hi = std::ceil(pseudo_log2(opt.g_max));
    auto params = [&pair](double x) { return tangential_parameters(pair, pseudo_exp2(x)); };

    t.critical_ = AdaptiveTable1D::build(
        x_lo, x_hi, per_binade(opt.critical, x_lo, x_hi),
        [&](std::span<const double> xs, std::span<const double>, std::span<double> out) {
            parallel_points(xs.size(), [&](std::size_t i) { out[i] = critical_ratio(params(xs[i]), opt.tol); });
        });
    t.unbroken_ = AdaptiveTable1D::build(
        x_lo, x_hi, per_binade(opt.unbroken, x_lo, x_hi),
        [&](std::span<const double> xs, std::span<const double>, std::span<double> out) {
            parallel_points(xs.size(), [&](std::size_t i) { out[i] = integrate_tangential(params(xs[i]), 0.0, opt.tol).eps_t; });
        });
    // Above the onset: ratio = c/y. The edge y = 1 holds the limit from the breaking side, taken at
    // the edge of the direct band; y = 0 is g_T -> inf, where eps^T -> 1 (the asperities no longer act).
    const double y_edge = t.y_direct_; // 1/(1 + band), where the look-up's direct band begins
    t.breaking_ = AdaptiveTable2D::build(
        x_lo, x_hi, 0.0, 1.0, per_binade(opt.breaking, x_lo, x_hi),
        [&](std::span<const double> xs, std::span<const double> ys, std::span<double> out) {
            parallel_points(xs.size(), [&](std::size_t i) {
                if (ys[i] <= 0.0) { out[i] = 1.0; return; }
                const TangentialParameters p = params(xs[i]);
                double c = t.critical_(xs[i]);
                if (std::isnan(c)) c = critical_ratio(p, opt.tol);
                out[i] = integrate_tangential(p, c / std::min(ys[i], y_edge), opt.tol).eps_t;
            });
        });
    t.stats_ = {t.critical_.stats(), t.unbroken_.stats(), t.breaking_.stats(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
    return t;
}

std::string TangentialTable::key_for(const ContactPair& p, const TangentialTableOptions& opt) {
    std::ostringstream s;
    s.precision(17);
    s << "roughgas " << ROUGHGAS_VERSION << " tangential_table form=" << name(p.model.form) << " end=" << name(p.model.end)
      << " m_eff=" << p.m_eff << " R_eff=" << p.R_eff << " kappa=" << p.kappa << " rho=" << p.rho << " A=" << p.A
      << " mu=" << p.mu << " zeta0=" << p.zeta0 << " g_min=" << opt.g_min << " g_max=" << opt.g_max;
    for (const AdaptiveOptions* o : {&opt.critical, &opt.unbroken, &opt.breaking})
        s << " grid=" << o->root_cells_x << "," << o->root_cells_y << "," << o->max_depth << "," << o->tol << ","
          << o->relative;
    s << " band=" << opt.onset_band << " rel=" << opt.tol.rel << " abs=" << opt.tol.abs;
    return s.str();
}

std::vector<double> TangentialTable::serialize() const {
    std::vector<double> out{stats_.build_seconds};
    for (const auto& part : {critical_.serialize(), unbroken_.serialize(), breaking_.serialize()})
        out.insert(out.end(), part.begin(), part.end());
    return out;
}

TangentialTable TangentialTable::deserialize(const ContactPair& pair, TangentialTableOptions opt,
                                             const std::vector<double>& data) {
    if (data.empty()) throw std::runtime_error("TangentialTable: empty payload");
    TangentialTable t;
    t.opt_ = opt;
    t.set_band();
    t.direct_ = DirectTangential{pair, opt.tol};
    std::size_t pos = 1;
    t.critical_ = AdaptiveTable1D::deserialize(data, pos);
    t.unbroken_ = AdaptiveTable1D::deserialize(data, pos);
    t.breaking_ = AdaptiveTable2D::deserialize(data, pos);
    if (pos != data.size()) throw std::runtime_error("TangentialTable: payload size does not match");
    t.stats_ = {t.critical_.stats(), t.unbroken_.stats(), t.breaking_.stats(), data[0]};
    return t;
}

} // namespace roughgas
