// Bisection refinement of the adaptive tables (see adaptive_table.hpp).
#include "roughgas/restitution/adaptive_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <unordered_map>

namespace roughgas {
namespace {

constexpr double nan_v = std::numeric_limits<double>::quiet_NaN();

// Sample points live on an integer lattice 2 levels finer than the deepest cell, so the quarter
// points of the deepest cells are lattice points too. Samples are memoised: a parent's check
// points are its children's corners.
struct Lattice {
    double lo_x, step_x, lo_y, step_y;
    std::unordered_map<std::uint64_t, double> memo;
    static std::uint64_t key(std::int64_t i, std::int64_t j) { return (std::uint64_t(i) << 32) | std::uint64_t(j); }

    void evaluate_missing(const std::vector<std::pair<std::int64_t, std::int64_t>>& pts, bool two_d,
                          const BatchFunction& f) {
        std::vector<std::pair<std::int64_t, std::int64_t>> todo;
        for (const auto& p : pts)
            if (!memo.count(key(p.first, p.second))) todo.push_back(p);
        std::sort(todo.begin(), todo.end());
        todo.erase(std::unique(todo.begin(), todo.end()), todo.end());
        std::vector<double> xs(todo.size()), ys(two_d ? todo.size() : 0), out(todo.size(), nan_v);
        for (std::size_t k = 0; k < todo.size(); ++k) {
            xs[k] = lo_x + step_x * double(todo[k].first);
            if (two_d) ys[k] = lo_y + step_y * double(todo[k].second);
        }
        if (!todo.empty()) f(xs, ys, out);
        for (std::size_t k = 0; k < todo.size(); ++k) memo[key(todo[k].first, todo[k].second)] = out[k];
    }
    double at(std::int64_t i, std::int64_t j = 0) const { return memo.at(key(i, j)); }
};

void check_options(const AdaptiveOptions& opt) {
    if (opt.root_cells_x < 1 || opt.root_cells_y < 1 || opt.max_depth < 0 || opt.max_depth > 24 || !(opt.tol > 0))
        throw std::invalid_argument("adaptive table: invalid options");
}

void put(std::vector<double>& out, const AdaptiveStats& s) {
    out.insert(out.end(), {double(s.samples), double(s.leaves), double(s.direct_leaves), s.max_leaf_error});
}
AdaptiveStats get_stats(std::span<const double> d, std::size_t& pos) {
    AdaptiveStats s;
    s.samples = std::size_t(d[pos]);
    s.leaves = std::size_t(d[pos + 1]);
    s.direct_leaves = std::size_t(d[pos + 2]);
    s.max_leaf_error = d[pos + 3];
    pos += 4;
    return s;
}
void need(std::span<const double> d, std::size_t pos, std::size_t n) {
    if (pos + n > d.size()) throw std::runtime_error("adaptive table: truncated payload");
}

} // namespace

// Power-basis coefficients of the quartic through f[k] at t = k/4, k = 0..4 (Lagrange, expanded).
std::array<double, 5> quartic_through(const std::array<double, 5>& f) {
    std::array<double, 5> c{};
    for (int k = 0; k < 5; ++k) {
        std::array<double, 5> basis{1, 0, 0, 0, 0}; // prod_{m != k} (t - m/4)/(k/4 - m/4)
        int degree = 0;
        for (int m = 0; m < 5; ++m) {
            if (m == k) continue;
            const double scale = 1.0 / ((k - m) / 4.0), root = m / 4.0;
            for (int d = degree + 1; d >= 0; --d)
                basis[d] = ((d > 0 ? basis[d - 1] : 0.0) - root * basis[d]) * scale;
            ++degree;
        }
        for (int d = 0; d < 5; ++d) c[d] += f[k] * basis[d];
    }
    return c;
}

AdaptiveTable1D AdaptiveTable1D::build(double x_lo, double x_hi, const AdaptiveOptions& opt, const BatchFunction& f) {
    check_options(opt);
    if (!(x_hi > x_lo)) throw std::invalid_argument("adaptive table: empty range");
    AdaptiveTable1D t;
    t.x_lo_ = x_lo;
    t.n_root_ = opt.root_cells_x;
    t.inv_root_ = t.n_root_ / (x_hi - x_lo);
    // A leaf interpolates its samples at eighths 0, 2, 4, 6, 8 and is checked at 1, 3, 5, 7.
    const int bits = opt.max_depth + 3;
    Lattice lat{x_lo, (x_hi - x_lo) / double(std::int64_t(t.n_root_) << bits), 0, 0, {}};

    struct Pending { std::int64_t i0; int depth; std::int32_t node; };
    std::vector<Pending> pending;
    const Node empty{{nan_v, nan_v, nan_v, nan_v, nan_v}, -1};
    t.nodes_.assign(t.n_root_, empty);
    for (int r = 0; r < t.n_root_; ++r) pending.push_back({std::int64_t(r) << bits, 0, r});

    while (!pending.empty()) {
        std::vector<std::pair<std::int64_t, std::int64_t>> pts;
        for (const auto& p : pending) {
            const std::int64_t L = std::int64_t(1) << (bits - p.depth);
            for (int q = 0; q <= 8; ++q) pts.push_back({p.i0 + q * L / 8, 0});
        }
        lat.evaluate_missing(pts, false, f);
        std::vector<Pending> next;
        for (const auto& p : pending) {
            const std::int64_t L = std::int64_t(1) << (bits - p.depth);
            std::array<double, 5> samples;
            for (int k = 0; k < 5; ++k) samples[k] = lat.at(p.i0 + 2 * k * L / 8);
            const std::array<double, 5> c = quartic_through(samples);
            double err = 0;
            for (int q = 1; q < 8; q += 2) {
                const double fq = lat.at(p.i0 + q * L / 8);
                err = std::max(err, std::abs(quartic_at(c.data(), q / 8.0) - fq) / (opt.relative ? std::abs(fq) : 1.0));
            }
            for (double v : samples)
                if (!std::isfinite(v)) err = nan_v;
            if (err <= opt.tol) {
                t.nodes_[p.node] = Node{{c[0], c[1], c[2], c[3], c[4]}, -1};
                ++t.stats_.leaves;
                t.stats_.max_leaf_error = std::max(t.stats_.max_leaf_error, err);
            } else if (p.depth == opt.max_depth) {
                t.nodes_[p.node] = empty;
                ++t.stats_.direct_leaves;
            } else {
                const auto child = static_cast<std::int32_t>(t.nodes_.size());
                t.nodes_[p.node].child = child;
                t.nodes_.push_back(empty);
                t.nodes_.push_back(empty);
                next.push_back({p.i0, p.depth + 1, child});
                next.push_back({p.i0 + L / 2, p.depth + 1, child + 1});
            }
        }
        pending.swap(next);
    }
    t.stats_.samples = lat.memo.size();
    t.build_flat_index();
    return t;
}

// The quartic p(t) of a leaf on the part t in [a, a + h) of it, in that part's own coordinate s:
// q(s) = p(a + h s), expanded (b_k = h^k sum_{i >= k} C(i, k) c_i a^(i - k)).
static std::array<double, 5> shifted_quartic(const double (&c)[5], double a, double h) {
    static constexpr double binom[5][5] = {{1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};
    std::array<double, 5> b{};
    double hk = 1;
    for (int k = 0; k < 5; ++k) {
        double sum = 0, ap = 1;
        for (int i = k; i < 5; ++i) {
            sum += binom[i][k] * c[i] * ap;
            ap *= a;
        }
        b[k] = hk * sum;
        hk *= h;
    }
    return b;
}

void AdaptiveTable1D::build_flat_index() {
    if (nodes_.size() > std::size_t(FlatEntry::max_node) + 1) throw std::runtime_error("adaptive table: too many nodes");
    const std::size_t per_root = std::size_t{1} << flat_bits;
    flat_.resize(std::size_t(n_root_) * per_root);
    cells_.resize(flat_.size());
    flat_scale_ = double(per_root);
    flat_inv_ = inv_root_ * flat_scale_;
    flat_n_ = double(flat_.size());
    for (std::size_t i = 0; i < flat_.size(); ++i) {
        std::int32_t k = std::int32_t(i / per_root);
        int depth = 0;
        for (; depth < flat_bits && nodes_[k].child >= 0; ++depth)
            k = nodes_[k].child + int((i >> (flat_bits - 1 - depth)) & 1);
        flat_[i] = FlatEntry::make(k, depth);
        Cell& cell = cells_[i];
        std::fill(std::begin(cell.c), std::end(cell.c), nan_v);
        if (nodes_[k].child < 0) { // a leaf covers the cell: its quartic on the cell (NaN stays NaN)
            const std::size_t span = std::size_t{1} << (flat_bits - depth);
            const std::array<double, 5> b =
                shifted_quartic(nodes_[k].c, double(i & (span - 1)) / double(span), 1.0 / double(span));
            std::copy(b.begin(), b.end(), cell.c);
        }
    }
    // Whole binades of x = pseudo_log2(g), each cut into 2^b flat cells: the cell index and its
    // coordinate are bit fields of g (at_speed).
    binade_bits_ = -1;
    const double per_binade = flat_inv_;
    const int b = int(std::lround(std::log2(per_binade)));
    if (x_lo_ == std::floor(x_lo_) && b >= 0 && b <= 40 && std::ldexp(1.0, b) == per_binade && x_lo_ + 1023 >= 1 &&
        x_lo_ + 1023 + flat_n_ / per_binade <= 2047) {
        binade_bits_ = b;
        cell_shift_ = unsigned(52 - b);
        cell_base_ = std::uint64_t(x_lo_ + 1023) << b;
        cell_mask_ = (std::uint64_t{1} << cell_shift_) - 1;
        cell_t_scale_ = std::ldexp(1.0, -int(cell_shift_));
    }
}

void AdaptiveTable2D::build_flat_index() {
    if (nodes_.size() > std::size_t(FlatEntry::max_node) + 1) throw std::runtime_error("adaptive table: too many nodes");
    const std::size_t per_root = std::size_t{1} << flat_bits;
    flat_nx_ = std::size_t(nx_) * per_root;
    flat_ny_ = std::size_t(ny_) * per_root;
    flat_scale_ = double(per_root);
    flat_inv_x_ = inv_x_ * flat_scale_;
    flat_inv_y_ = inv_y_ * flat_scale_;
    fy_offset_ = -y_lo_ * flat_inv_y_;
    flat_nx_d_ = double(flat_nx_);
    flat_ny_d_ = double(flat_ny_);
    flat_.resize(flat_nx_ * flat_ny_);
    cells_.resize(flat_.size());
    for (std::size_t iy = 0; iy < flat_ny_; ++iy)
        for (std::size_t ix = 0; ix < flat_nx_; ++ix) {
            std::int32_t k = std::int32_t((iy / per_root) * nx_ + ix / per_root);
            int depth = 0;
            for (; depth < flat_bits && nodes_[k].child >= 0; ++depth) {
                const int shift = flat_bits - 1 - depth;
                k = nodes_[k].child + 2 * int((iy >> shift) & 1) + int((ix >> shift) & 1);
            }
            flat_[iy * flat_nx_ + ix] = FlatEntry::make(k, depth);
            Cell& cell = cells_[iy * flat_nx_ + ix];
            const double nan = std::numeric_limits<double>::quiet_NaN();
            cell = {nan, nan, nan, nan};
            if (nodes_[k].child < 0) { // a leaf covers the cell: its interpolant in the cell's coordinates
                const std::size_t span = std::size_t{1} << (flat_bits - depth);
                const double* v = nodes_[k].v;
                const double x0 = double(ix & (span - 1)) / double(span), y0 = double(iy & (span - 1)) / double(span);
                const double h = 1.0 / double(span);
                const double v00 = bilinear_at(v[0], v[1], v[2], v[3], x0, y0);
                const double v10 = bilinear_at(v[0], v[1], v[2], v[3], x0 + h, y0);
                const double v01 = bilinear_at(v[0], v[1], v[2], v[3], x0, y0 + h);
                const double v11 = bilinear_at(v[0], v[1], v[2], v[3], x0 + h, y0 + h);
                cell = {v00, v10 - v00, v01 - v00, (v11 - v01) - (v10 - v00)};
            }
        }
}

AdaptiveTable2D AdaptiveTable2D::build(double x_lo, double x_hi, double y_lo, double y_hi, const AdaptiveOptions& opt,
                                       const BatchFunction& f) {
    check_options(opt);
    if (!(x_hi > x_lo) || !(y_hi > y_lo)) throw std::invalid_argument("adaptive table: empty range");
    AdaptiveTable2D t;
    t.x_lo_ = x_lo;
    t.y_lo_ = y_lo;
    t.nx_ = opt.root_cells_x;
    t.ny_ = opt.root_cells_y;
    t.inv_x_ = t.nx_ / (x_hi - x_lo);
    t.inv_y_ = t.ny_ / (y_hi - y_lo);
    const int bits = opt.max_depth + 2;
    Lattice lat{x_lo, (x_hi - x_lo) / double(std::int64_t(t.nx_) << bits), y_lo,
                (y_hi - y_lo) / double(std::int64_t(t.ny_) << bits), {}};

    struct Pending { std::int64_t i0, j0; int depth; std::int32_t node; };
    std::vector<Pending> pending;
    const Node empty{{nan_v, nan_v, nan_v, nan_v}, -1};
    t.nodes_.assign(std::size_t(t.nx_) * t.ny_, empty);
    for (int iy = 0; iy < t.ny_; ++iy)
        for (int ix = 0; ix < t.nx_; ++ix)
            pending.push_back({std::int64_t(ix) << bits, std::int64_t(iy) << bits, 0, iy * t.nx_ + ix});

    while (!pending.empty()) {
        std::vector<std::pair<std::int64_t, std::int64_t>> pts;
        for (const auto& p : pending) {
            const std::int64_t L = std::int64_t(1) << (bits - p.depth);
            for (int a = 0; a <= 4; ++a)
                for (int b = 0; b <= 4; ++b)
                    if ((a % 2 == 0 && b % 2 == 0) || (a % 2 == 1 && b % 2 == 1))
                        pts.push_back({p.i0 + a * L / 4, p.j0 + b * L / 4});
        }
        lat.evaluate_missing(pts, true, f);
        std::vector<Pending> next;
        for (const auto& p : pending) {
            const std::int64_t L = std::int64_t(1) << (bits - p.depth);
            const double v00 = lat.at(p.i0, p.j0), v10 = lat.at(p.i0 + L, p.j0);
            const double v01 = lat.at(p.i0, p.j0 + L), v11 = lat.at(p.i0 + L, p.j0 + L);
            // Check points: edge midpoints, centre, and the four quarter-centres (the children's centres).
            double err = 0;
            for (int a = 0; a <= 4; ++a)
                for (int b = 0; b <= 4; ++b) {
                    const bool corner = (a == 0 || a == 4) && (b == 0 || b == 4);
                    if (corner || !((a % 2 == 0 && b % 2 == 0) || (a % 2 == 1 && b % 2 == 1))) continue;
                    const double tx = a / 4.0, ty = b / 4.0;
                    const double interp = bilinear_at(v00, v10, v01, v11, tx, ty);
                    const double fq = lat.at(p.i0 + a * L / 4, p.j0 + b * L / 4);
                    err = std::max(err, std::abs(interp - fq) / (opt.relative ? std::abs(fq) : 1.0));
                }
            if (!std::isfinite(v00 + v10 + v01 + v11)) err = nan_v;
            if (err <= opt.tol) {
                t.nodes_[p.node] = Node{{v00, v10, v01, v11}, -1};
                ++t.stats_.leaves;
                t.stats_.max_leaf_error = std::max(t.stats_.max_leaf_error, err);
            } else if (p.depth == opt.max_depth) {
                t.nodes_[p.node] = empty;
                ++t.stats_.direct_leaves;
            } else {
                const auto child = static_cast<std::int32_t>(t.nodes_.size());
                t.nodes_[p.node].child = child;
                for (int c = 0; c < 4; ++c) t.nodes_.push_back(empty);
                const std::int64_t h = L / 2;
                next.push_back({p.i0, p.j0, p.depth + 1, child});
                next.push_back({p.i0 + h, p.j0, p.depth + 1, child + 1});
                next.push_back({p.i0, p.j0 + h, p.depth + 1, child + 2});
                next.push_back({p.i0 + h, p.j0 + h, p.depth + 1, child + 3});
            }
        }
        pending.swap(next);
    }
    t.stats_.samples = lat.memo.size();
    t.build_flat_index();
    return t;
}

std::vector<double> AdaptiveTable1D::serialize() const {
    std::vector<double> out{x_lo_, inv_root_, double(n_root_), double(nodes_.size())};
    for (const auto& n : nodes_) out.insert(out.end(), {n.c[0], n.c[1], n.c[2], n.c[3], n.c[4], double(n.child)});
    put(out, stats_);
    return out;
}

AdaptiveTable1D AdaptiveTable1D::deserialize(std::span<const double> d, std::size_t& pos) {
    need(d, pos, 4);
    AdaptiveTable1D t;
    t.x_lo_ = d[pos];
    t.inv_root_ = d[pos + 1];
    t.n_root_ = int(d[pos + 2]);
    const auto n = std::size_t(d[pos + 3]);
    pos += 4;
    need(d, pos, 6 * n + 4);
    t.nodes_.resize(n);
    for (auto& node : t.nodes_) {
        node = Node{{d[pos], d[pos + 1], d[pos + 2], d[pos + 3], d[pos + 4]}, std::int32_t(d[pos + 5])};
        if (node.child >= std::int32_t(n) || node.child < -1) throw std::runtime_error("adaptive table: bad node");
        pos += 6;
    }
    t.stats_ = get_stats(d, pos);
    t.build_flat_index();
    return t;
}

std::vector<double> AdaptiveTable2D::serialize() const {
    std::vector<double> out{x_lo_, y_lo_, inv_x_, inv_y_, double(nx_), double(ny_), double(nodes_.size())};
    for (const auto& n : nodes_) out.insert(out.end(), {n.v[0], n.v[1], n.v[2], n.v[3], double(n.child)});
    put(out, stats_);
    return out;
}

AdaptiveTable2D AdaptiveTable2D::deserialize(std::span<const double> d, std::size_t& pos) {
    need(d, pos, 7);
    AdaptiveTable2D t;
    t.x_lo_ = d[pos];
    t.y_lo_ = d[pos + 1];
    t.inv_x_ = d[pos + 2];
    t.inv_y_ = d[pos + 3];
    t.nx_ = int(d[pos + 4]);
    t.ny_ = int(d[pos + 5]);
    const auto n = std::size_t(d[pos + 6]);
    pos += 7;
    need(d, pos, 5 * n + 4);
    t.nodes_.resize(n);
    for (auto& node : t.nodes_) {
        node = Node{{d[pos], d[pos + 1], d[pos + 2], d[pos + 3]}, std::int32_t(d[pos + 4])};
        if (node.child >= std::int32_t(n) || node.child < -1) throw std::runtime_error("adaptive table: bad node");
        pos += 5;
    }
    t.stats_ = get_stats(d, pos);
    t.build_flat_index();
    return t;
}

} // namespace roughgas
