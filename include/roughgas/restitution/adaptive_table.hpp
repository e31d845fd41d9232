#pragma once
// Adaptive tables in one variable (piecewise quartic: a leaf interpolates 5 equally spaced samples,
// so smooth functions converge as h^5) and two (piecewise bilinear), refined by bisection until
// the interpolant matches the function at check points within `tol`. A cell that still fails at the
// maximum depth is marked `direct`: look-ups there return NaN, and the caller evaluates the
// function itself. So a discontinuity (the jumps of eps^T, docs/model.md §7) is never interpolated
// across: it ends up inside a thin band of direct cells.
//
// Build: level by level, all new sample points of a level are evaluated in one batch (the batch
// evaluator runs them in parallel). Look-up: a uniform grid of flat cells, 2^flat_bits per root
// cell and axis, each holding the interpolant of the leaf that covers it; only where a leaf is
// deeper than the flat grid does the look-up walk down the tree.
#include "roughgas/restitution/pseudo_log.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

namespace roughgas {

struct AdaptiveOptions {
    int root_cells_x = 16;
    int root_cells_y = 8;     // 2-D only
    int max_depth = 6;        // bisections below a root cell
    double tol = 2.5e-5;      // max |interpolant - f| at the check points of a leaf
    bool relative = false;    // tol bounds |interpolant - f| / |f| instead
};

struct AdaptiveStats {
    std::size_t samples = 0, leaves = 0, direct_leaves = 0;
    double max_leaf_error = 0; // largest check-point error among interpolating leaves
};

// A cell of the flat index over a table: the deepest node at depth <= flat_bits that covers it,
// and that depth (2^depth turns root-cell coordinates into the node's local ones), packed in 4
// bytes: node << 3 | depth. The look-ups read the flat cells (the leaf's interpolant on the cell)
// instead; this index is their way into the tree where a leaf is deeper than the flat grid.
inline constexpr int flat_bits = 4;
struct FlatEntry {
    std::uint32_t packed = 0;
    static constexpr std::int32_t max_node = (std::int32_t{1} << 29) - 1;
    static FlatEntry make(std::int32_t node, int depth) {
        return {(static_cast<std::uint32_t>(node) << 3) | static_cast<std::uint32_t>(depth)};
    }
    std::int32_t node() const { return static_cast<std::int32_t>(packed >> 3); }
    unsigned depth() const { return packed & 7u; }
};
static_assert(flat_bits < 8, "FlatEntry keeps the depth in 3 bits");

// The local coordinate, in the node of depth `depth`, of the point at tf in [0, 1] within flat
// cell i (along one axis): that node spans 2^(flat_bits - depth) flat cells. Taken from the index
// (exact but for the last bit), not as f 2^depth - floor(f 2^depth) after the flat index has been
// read: only a mask, a conversion and a product wait for the load. The look-up's latency is the
// collision loop's.
inline double node_coordinate(std::size_t i, double tf, unsigned depth) {
    const unsigned up = static_cast<unsigned>(flat_bits) - depth;
    const double span_inv = std::bit_cast<double>(static_cast<std::uint64_t>(1023 - up) << 52); // 2^-up
    return (static_cast<double>(i & ((std::size_t{1} << up) - 1)) + tf) * span_inv;
}

// The leaf interpolants, one expression each for the build's checks, the flat cells and the look-ups:
// the quartic in power basis (Horner) and the bilinear through corners (0,0) (1,0) (0,1) (1,1).
inline double quartic_at(const double* c, double t) { return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * c[4]))); }
inline double bilinear_at(double v00, double v10, double v01, double v11, double tx, double ty) {
    return (v00 + (v10 - v00) * tx) * (1 - ty) + (v01 + (v11 - v01) * tx) * ty;
}

// f evaluated on a batch of points (xs[i], ys[i]) -> out[i]; ys is empty for 1-D tables.
using BatchFunction = std::function<void(std::span<const double> xs, std::span<const double> ys, std::span<double> out)>;

class AdaptiveTable1D {
public:
    static AdaptiveTable1D build(double x_lo, double x_hi, const AdaptiveOptions& opt, const BatchFunction& f);

    // NaN outside [x_lo, x_hi] and in direct cells.
    // The flat cell covering x holds the quartic of its leaf re-expressed in the cell's own
    // coordinate (shifted_quartic in the .cpp), so a look-up is one load and a Horner evaluation; cells of
    // deeper leaves (and direct ones) hold NaN and go down the tree instead. The look-up's latency
    // is the collision loop's.
    double operator()(double x) const {
        const double F = (x - x_lo_) * flat_inv_;
        if (!(F >= 0.0) || F >= flat_n_) return std::numeric_limits<double>::quiet_NaN();
        const auto i = static_cast<std::size_t>(F);
        return in_cell(i, F - static_cast<double>(i), x);
    }
    // The same at x = pseudo_log2(g) (g > 0), with the cell and its coordinate read off the bits of g:
    // no conversion waits for g. Needs whole binades (integral x_lo) cut into a power of two of flat
    // cells each (binade_bits() >= 0); else it converts g.
    [[gnu::always_inline]] double at_speed(double g) const {
        if (binade_bits_ < 0) [[unlikely]]
            return (*this)(pseudo_log2(g));
        const std::uint64_t bits = std::bit_cast<std::uint64_t>(g);
        const std::uint64_t i = (bits >> cell_shift_) - cell_base_; // wraps around below the table
        if (i >= cells_.size()) return std::numeric_limits<double>::quiet_NaN();
        const double t = static_cast<double>(bits & cell_mask_) * cell_t_scale_;
        return in_cell(i, t, pseudo_log2(g));
    }
    // The tree walk alone (the flat index down to the leaf): the reference for the flat cells.
    double tree(double x) const {
        const double f = (x - x_lo_) * inv_root_;
        if (!(f >= 0.0) || f >= n_root_) return std::numeric_limits<double>::quiet_NaN();
        const double F = f * flat_scale_;
        const auto i = static_cast<std::size_t>(F);
        return walk(i, F - static_cast<double>(i));
    }
    // Flat cells per binade of x as a power of two (-1: the table is not on whole binades).
    int binade_bits() const { return binade_bits_; }

    const AdaptiveStats& stats() const { return stats_; }
    double x_lo() const { return x_lo_; }
    double x_hi() const { return x_lo_ + n_root_ / inv_root_; }

    std::vector<double> serialize() const;
    static AdaptiveTable1D deserialize(std::span<const double> data, std::size_t& pos);

private:
    struct Node { double c[5]; std::int32_t child; };
    struct alignas(64) Cell { double c[5]; }; // one cache line: power-basis coefficients in the cell's t
    double x_lo_ = 0, inv_root_ = 1;
    int n_root_ = 0;
    std::vector<Node> nodes_; // the first n_root_ are the root cells; children come in pairs
    AdaptiveStats stats_;
    std::vector<FlatEntry> flat_; // n_root_ 2^flat_bits cells: node reached and 2^depth
    std::vector<Cell> cells_;     // the same cells: the quartic of their leaf, or NaN
    double flat_scale_ = 1, flat_inv_ = 1, flat_n_ = 0;
    int binade_bits_ = -1;
    unsigned cell_shift_ = 0;
    std::uint64_t cell_base_ = 0, cell_mask_ = 0;
    double cell_t_scale_ = 0;
    void build_flat_index();

    [[gnu::always_inline]] double in_cell(std::size_t i, double t, double x) const {
        const double v = quartic_at(cells_[i].c, t);
        if (std::isnan(v)) [[unlikely]]
            return tree_cold(x); // a deeper leaf (or a direct one: NaN again)
        return v;
    }
    [[gnu::noinline, gnu::cold]] double tree_cold(double x) const { return tree(x); }
    double walk(std::size_t i, double tf) const {
        const FlatEntry e = flat_[i];
        double t = node_coordinate(i, tf, e.depth());
        std::int32_t k = e.node();
        while (nodes_[k].child >= 0) {
            t *= 2;
            const int c = t >= 1.0;
            t -= c;
            k = nodes_[k].child + c;
        }
        return quartic_at(nodes_[k].c, t); // power-basis coefficients in t; NaN in a direct leaf
    }
};

class AdaptiveTable2D {
public:
    static AdaptiveTable2D build(double x_lo, double x_hi, double y_lo, double y_hi, const AdaptiveOptions& opt,
                                 const BatchFunction& f);

    // NaN outside the table and in direct cells. As in 1-D, the flat cell covering (x, y) holds
    // the bilinear interpolant of its leaf restricted to the cell, so a look-up is one 32-byte load
    // and the cell's own coordinates; cells of deeper leaves (and direct ones) hold NaN and go down
    // the tree. The interpolant is kept as a + b tx + ty (c + d tx): two products in parallel and
    // one after them, where the corners would take three in a row; and (y - y_lo) k is taken as
    // y k - y_lo k in one fused product (the same for y_lo = 0): the look-up's latency is the
    // collision loop's.
    [[gnu::always_inline]] double operator()(double x, double y) const {
        const double Fx = (x - x_lo_) * flat_inv_x_, Fy = std::fma(y, flat_inv_y_, fy_offset_);
        if (!(Fx >= 0.0) || Fx >= flat_nx_d_ || !(Fy >= 0.0) || Fy > flat_ny_d_)
            return std::numeric_limits<double>::quiet_NaN();
        const auto ix = static_cast<std::size_t>(Fx);
        const auto iy = std::min(static_cast<std::size_t>(Fy), flat_ny_ - 1); // Fy = flat_ny: the top edge
        const Cell& c = cells_[iy * flat_nx_ + ix];
        const double tx = Fx - static_cast<double>(ix), ty = Fy - static_cast<double>(iy); // ty = 1 at the top edge
        const double v = std::fma(ty, std::fma(c.d, tx, c.c), std::fma(c.b, tx, c.a));
        if (std::isnan(v)) [[unlikely]]
            return tree_cold(x, y); // a deeper leaf (or a direct one: NaN again)
        return v;
    }
    // The tree walk alone (the flat index down to the leaf): the reference for the flat cells.
    double tree(double x, double y) const {
        const double fx = (x - x_lo_) * inv_x_, fy = (y - y_lo_) * inv_y_;
        if (!(fx >= 0.0) || fx >= nx_ || !(fy >= 0.0) || fy > ny_) return std::numeric_limits<double>::quiet_NaN();
        const double Fx = fx * flat_scale_, Fy = fy * flat_scale_;
        const auto ix = static_cast<std::size_t>(Fx);
        const auto iy = std::min(static_cast<std::size_t>(Fy), flat_ny_ - 1); // fy = ny_: the top edge
        const FlatEntry e = flat_[iy * flat_nx_ + ix];
        double tx = node_coordinate(ix, Fx - static_cast<double>(ix), e.depth());
        double ty = node_coordinate(iy, Fy - static_cast<double>(iy), e.depth()); // 1 at the top edge
        std::int32_t k = e.node();
        while (nodes_[k].child >= 0) {
            tx *= 2;
            ty *= 2;
            const int cx = tx >= 1.0, cy = ty >= 1.0;
            tx -= cx;
            ty -= cy;
            k = nodes_[k].child + 2 * cy + cx;
        }
        const auto& v = nodes_[k].v; // corners (0,0) (1,0) (0,1) (1,1); NaN in a direct leaf
        return bilinear_at(v[0], v[1], v[2], v[3], tx, ty);
    }

    const AdaptiveStats& stats() const { return stats_; }

    std::vector<double> serialize() const;
    static AdaptiveTable2D deserialize(std::span<const double> data, std::size_t& pos);

private:
    struct Node { double v[4]; std::int32_t child; };
    struct alignas(32) Cell { double a, b, c, d; }; // a + b tx + c ty + d tx ty on the flat cell
    double x_lo_ = 0, y_lo_ = 0, inv_x_ = 1, inv_y_ = 1;
    int nx_ = 0, ny_ = 0;
    std::vector<Node> nodes_; // nx_*ny_ root cells (row-major in y), children in blocks of 4
    AdaptiveStats stats_;
    std::vector<FlatEntry> flat_; // (nx_ 2^flat_bits) x (ny_ 2^flat_bits) cells
    std::vector<Cell> cells_;     // the same cells: their leaf's interpolant on the cell, or NaN
    std::size_t flat_nx_ = 0, flat_ny_ = 0;
    double flat_scale_ = 1, flat_inv_x_ = 1, flat_inv_y_ = 1, flat_nx_d_ = 0, flat_ny_d_ = 0;
    double fy_offset_ = 0; // -y_lo flat_inv_y
    void build_flat_index();
    [[gnu::noinline, gnu::cold]] double tree_cold(double x, double y) const { return tree(x, y); }
};

} // namespace roughgas
