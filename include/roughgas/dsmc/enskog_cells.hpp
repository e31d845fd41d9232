#pragma once
// What the Enskog collisions of a box read besides the grains (docs/model.md, "The Enskog equation in
// a box"; dsmc/spatial_engine.hpp, "Enskog collisions"): the cells' grid and reach, the blocks of
// cells that collide in parallel, and the fields of a step:
//
//   - the local density n_s of each species, averaged over a cube of cells around each cell (the
//     smoothing cube, `smoothing` cells per side): the pair correlation chi_ab at contact is a
//     nonlinear function of the density, so the count of one small cell, a few grains, would bias it
//     by chi''(n) Var(n)/2 (3 % at phi = 0.2 for 10 grains, 0.03 % for 1000); the cube holds
//     enough grains for that bias to stay below the statistical errors, and its chi_ab(c) is the
//     local equation of state's (Carnahan & Starling, or BMCSL for mixtures);
//   - the flow U(c), the mean velocity over the same cube: the reference about which the speed
//     bounds are taken (smooth, so that it differs little between neighbouring cells); with
//     Lees-Edwards boundaries the images' flow a (y - L_y/2) x^ plus the mean about it, which is
//     periodic across the images;
//   - the bounds of the candidates' acceptance over each cell's reach (the cells a partner a
//     diameter away can lie in): the largest sigma_ab^2 chi_ab, the largest count of one species,
//     the largest spread of U, and (speed_bounds) the largest speed about U.
//
// Blocks. A collision of a grain of cell c changes a grain up to reach_a cells away along each axis,
// and the cell's bounds read that far. Blocks of at least 2 reach_a cells along each axis that differ
// in the parity of their index along some axis are then never within reach of each other: the blocks
// of one colour (the parities of their three indices) collide at the same time, the colours one
// after the other. A periodic axis has an even number of blocks (the first and the last are
// neighbours), or one block when it is shorter than 4 reach_a cells.
#include "roughgas/dsmc/pair_correlation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace roughgas {

// n_x x n_y x n_z cells, x fastest: cell (i, j, k) is i + n_x (j + n_y k); each axis periodic or walled.
struct CellGrid {
    std::array<int, 3> n{1, 1, 1};
    std::array<bool, 3> periodic{true, true, true};
    std::size_t cells() const {
        return static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(n[2]);
    }
    std::size_t stride(int axis) const {
        return axis == 0 ? 1 : axis == 1 ? static_cast<std::size_t>(n[0])
                                         : static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]);
    }
};

// Along `axis`: out[c * F + f] = the sum (Max = false) or the maximum (Max = true) of in[c * F + f]
// over the cells c' of c's line with index within `reach` of c's, wrapped on a periodic axis (each
// cell once when the window covers the line), clipped at walls. Each line is copied into a buffer of
// its own (padded by `reach` cells on either side: wrapped copies, or the identity beyond walls),
// then sums by a sliding window, maxima over the window.
template <bool Max>
void reduce_along(const CellGrid& g, int axis, int reach, const std::vector<double>& in, std::vector<double>& out,
                  std::size_t F) {
    const auto A = static_cast<std::size_t>(axis);
    const int n = g.n[A];
    const std::size_t stride = g.stride(axis), cells = g.cells();
    const bool periodic = g.periodic[A];
    const double identity = Max ? -std::numeric_limits<double>::infinity() : 0.0;
    out.resize(in.size());
    const bool whole = periodic && 2 * reach + 1 >= n;
    const int r = whole ? 0 : reach;
    const auto padded = static_cast<std::size_t>(n + 2 * r);
    std::vector<double> line(padded * F), acc(F);
    // The lines along the axis: start cells with index 0 along it.
    const std::size_t outer = cells / (stride * static_cast<std::size_t>(n));
    for (std::size_t o = 0; o < outer; ++o)
        for (std::size_t inner = 0; inner < stride; ++inner) {
            const std::size_t start = o * stride * static_cast<std::size_t>(n) + inner;
            for (int k = -r; k < n + r; ++k) {
                double* to = &line[static_cast<std::size_t>(k + r) * F];
                int q = k;
                if (q < 0 || q >= n) {
                    if (!periodic) {
                        std::fill(to, to + F, identity);
                        continue;
                    }
                    q = ((q % n) + n) % n;
                }
                const double* from = &in[(start + static_cast<std::size_t>(q) * stride) * F];
                std::copy(from, from + F, to);
            }
            if (whole) { // every cell of the line sees the whole line
                std::fill(acc.begin(), acc.end(), identity);
                for (int k = 0; k < n; ++k)
                    for (std::size_t f = 0; f < F; ++f)
                        acc[f] = Max ? std::max(acc[f], line[static_cast<std::size_t>(k) * F + f])
                                     : acc[f] + line[static_cast<std::size_t>(k) * F + f];
                for (int k = 0; k < n; ++k)
                    std::copy(acc.begin(), acc.end(), &out[(start + static_cast<std::size_t>(k) * stride) * F]);
                continue;
            }
            for (int k = 0; k < n; ++k) {
                // The window [k - r, k + r] of the line is [k, k + 2r] of the padded buffer.
                const double* w = &line[static_cast<std::size_t>(k) * F];
                if (Max || k == 0) {
                    std::fill(acc.begin(), acc.end(), identity);
                    for (int d = 0; d <= 2 * r; ++d)
                        for (std::size_t f = 0; f < F; ++f)
                            acc[f] = Max ? std::max(acc[f], w[static_cast<std::size_t>(d) * F + f])
                                         : acc[f] + w[static_cast<std::size_t>(d) * F + f];
                } else { // the window moves by one cell
                    for (std::size_t f = 0; f < F; ++f)
                        acc[f] += w[static_cast<std::size_t>(2 * r) * F + f] - line[static_cast<std::size_t>(k - 1) * F + f];
                }
                std::copy(acc.begin(), acc.end(), &out[(start + static_cast<std::size_t>(k) * stride) * F]);
            }
        }
}

// The three axes in turn: the reduction over the box of cells within reach[a] along each axis.
template <bool Max>
void reduce_neighbourhood(const CellGrid& g, const std::array<int, 3>& reach, std::vector<double>& values,
                          std::size_t F, std::vector<double>& scratch) {
    for (int a = 0; a < 3; ++a) {
        reduce_along<Max>(g, a, reach[static_cast<std::size_t>(a)], values, scratch, F);
        values.swap(scratch);
    }
}

// The blocks of cells of the parallel collision phase (the header's "Blocks").
struct CellBlocks {
    std::array<std::vector<int>, 3> edges; // per axis: block k covers cells [edges[k], edges[k + 1])
    std::array<std::vector<std::size_t>, 8> by_colour; // block indices of each colour, increasing
    std::size_t count() const { return (edges[0].size() - 1) * (edges[1].size() - 1) * (edges[2].size() - 1); }
    std::array<int, 3> index(std::size_t block) const {
        const std::size_t bx = edges[0].size() - 1, by = edges[1].size() - 1;
        return {static_cast<int>(block % bx), static_cast<int>((block / bx) % by), static_cast<int>(block / (bx * by))};
    }
};

// `lees_edwards`: the images across y are shifted along x (Lees-Edwards boundaries) by a whole number of
// cells and a fraction of one, so a block's reach across y is a window one cell wider than its reach,
// shifted along x: the blocks are a cell longer along x. A block that is the only one along y reaches
// across y into itself anywhere along x: then it is the only one along x too.
inline CellBlocks make_cell_blocks(const CellGrid& g, const std::array<int, 3>& reach, bool lees_edwards = false) {
    CellBlocks b;
    std::array<int, 3> count{};
    for (std::size_t a = 0; a < 3; ++a) {
        const int n = g.n[a], r = std::max(1, reach[a]) + (lees_edwards && a == 0 ? 1 : 0);
        count[a] = std::max(g.periodic[a] ? 2 * (n / (4 * r)) : n / (2 * r), 1);
    }
    if (lees_edwards && count[1] == 1)
        count[0] = 1;
    for (std::size_t a = 0; a < 3; ++a)
        for (int k = 0; k <= count[a]; ++k)
            b.edges[a].push_back(static_cast<int>(static_cast<long long>(g.n[a]) * k / count[a]));
    for (std::size_t u = 0; u < b.count(); ++u) {
        const std::array<int, 3> i = b.index(u);
        b.by_colour[static_cast<std::size_t>((i[0] & 1) | (i[1] & 1) << 1 | (i[2] & 1) << 2)].push_back(u);
    }
    return b;
}

// The fields of a step (the header's list), per cell c (x fastest).
class EnskogCells {
  public:
    // `sigma[s]`: species s's diameter; `h[a]`: the cells' edge along a; `smoothing`: the smoothing
    // cube's cells per side (odd; larger than an axis's cells: that whole axis); `chi_constant` > 0: chi
    // of every pair (run.chi), else BMCSL's (Carnahan & Starling's for one species).
    // `shear_rate` a != 0: Lees-Edwards boundaries along y with the flow a (y - L_y/2) x^ (L_y = n_y h_y):
    // U is then that flow plus the smoothed flow about it, which is periodic across the images.
    EnskogCells(const CellGrid& grid, std::vector<double> sigma, const std::array<double, 3>& h, int smoothing,
                double chi_constant, double shear_rate = 0)
        : grid_(grid), sigma_(std::move(sigma)), chi_constant_(chi_constant), shear_rate_(shear_rate), h_(h) {
        const std::size_t S = sigma_.size();
        if (S == 0 || smoothing < 1 || smoothing % 2 == 0)
            throw std::invalid_argument("EnskogCells: species and an odd smoothing cube needed");
        double sigma_max = 0;
        for (double s : sigma_)
            sigma_max = std::max(sigma_max, s);
        for (std::size_t a = 0; a < 3; ++a) {
            reach_[a] = static_cast<int>(std::ceil(sigma_max / h[a] * (1 + 1e-12)));
            smooth_[a] = std::min(smoothing / 2, grid.n[a]);
        }
        blocks_ = make_cell_blocks(grid_, reach_, shear_rate_ != 0);
        // The bounds' reach: with Lees-Edwards a partner across y lies anywhere along x.
        bound_reach_ = reach_;
        if (shear_rate_ != 0)
            bound_reach_[0] = grid.n[0];
        for (std::size_t a = 0; a < S; ++a)
            for (std::size_t b = a; b < S; ++b)
                sigma_pair_.push_back(0.5 * (sigma_[a] + sigma_[b]));
    }

    const CellGrid& grid() const { return grid_; }
    const std::array<int, 3>& reach() const { return reach_; }
    const CellBlocks& blocks() const { return blocks_; }
    std::size_t types() const { return sigma_pair_.size(); }

    // From `count[c * S + s]` (grains of species s in cell c) and `momentum[c * 3 + a]` (the sum of
    // their velocities' component a, about base_flow(c) along x), `weight` = F/V_c (a simulated grain's contribution to the
    // number density): the local densities, chi_ab, the flow U and the bounds that do not depend on
    // the speeds.
    void set_densities(const std::vector<double>& count, const std::vector<double>& momentum, double weight) {
        const std::size_t C = grid_.cells(), S = sigma_.size(), T = types(), F = S + 3;
        if (volume_.empty()) { // the smoothing cube's cells (clipped at walls): a cube of ones summed
            volume_.assign(C, 1.0);
            reduce_neighbourhood<false>(grid_, smooth_, volume_, 1, scratch_);
        }
        sums_.resize(C * F);
        for (std::size_t c = 0; c < C; ++c) {
            for (std::size_t s = 0; s < S; ++s)
                sums_[c * F + s] = count[c * S + s];
            for (std::size_t a = 0; a < 3; ++a)
                sums_[c * F + S + a] = momentum[c * 3 + a];
        }
        reduce_neighbourhood<false>(grid_, smooth_, sums_, F, scratch_);
        // Per cell, the fields whose maxima over the reach are taken together: sigma^2 chi, the counts,
        // U and -U (the spread).
        const std::size_t M = 1 + S + 6;
        chi_.resize(C * T);
        flow_.resize(C * 3);
        maxima_.resize(C * M);
        std::vector<double> n(S);
        for (std::size_t c = 0; c < C; ++c) {
            double grains = 0;
            for (std::size_t s = 0; s < S; ++s) {
                n[s] = weight * sums_[c * F + s] / volume_[c];
                grains += sums_[c * F + s];
            }
            double best = 0;
            for (std::size_t a = 0, t = 0; a < S; ++a)
                for (std::size_t b = a; b < S; ++b, ++t) {
                    double chi = chi_constant_;
                    if (!(chi > 0)) {
                        chi = bmcsl_chi_of(n.data(), sigma_.data(), S, a, b);
                        if (!(chi > 0) || !std::isfinite(chi)) // a cluster beyond close packing
                            throw std::runtime_error("the local solid fraction reached 1: the Enskog equation's "
                                                     "pair correlation is undefined there");
                    }
                    chi_[c * T + t] = chi;
                    best = std::max(best, sigma_pair_[t] * sigma_pair_[t] * chi);
                }
            double* m = &maxima_[c * M];
            m[0] = best;
            for (std::size_t s = 0; s < S; ++s)
                m[1 + s] = count[c * S + s];
            for (std::size_t a = 0; a < 3; ++a) {
                flow_[c * 3 + a] = grains > 0 ? sums_[c * F + S + a] / grains : 0.0;
                m[1 + S + a] = flow_[c * 3 + a];
                m[4 + S + a] = -flow_[c * 3 + a];
            }
        }
        reduce_neighbourhood<true>(grid_, bound_reach_, maxima_, M, scratch_);
        weight_max_.resize(C);
        count_max_.resize(C);
        spread_.resize(C);
        for (std::size_t c = 0; c < C; ++c) {
            const double* m = &maxima_[c * M];
            weight_max_[c] = m[0];
            count_max_[c] = *std::max_element(m + 1, m + 1 + S);
            double d2 = 0;
            for (std::size_t a = 0; a < 3; ++a) {
                const double u = flow_[c * 3 + a];
                const double d = std::max(m[1 + S + a] - u, u + m[4 + S + a]);
                d2 += d * d;
            }
            // With Lees-Edwards, the base flow differs by at most a reach_y h_y between a cell and
            // the partners' (their images' across y).
            spread_[c] = std::sqrt(d2) + std::abs(shear_rate_) * reach_[1] * h_[1];
        }
    }

    // From `speed[c]`, the largest |v - U(c)| of cell c's grains at the step's start: its maximum over
    // each cell's reach.
    // Also the floor of each cell, the least of speed_max over the cells within whose reach it lies
    // (the reach is symmetric: those within its own): a grain of cell c' faster than floor(c') about
    // U(c') may exceed some cell's speed_max, one slower never does.
    void set_speed_bounds(const std::vector<double>& speed) {
        speed_max_ = speed;
        reduce_neighbourhood<true>(grid_, bound_reach_, speed_max_, 1, scratch_);
        floor_.resize(speed_max_.size());
        for (std::size_t c = 0; c < floor_.size(); ++c)
            floor_[c] = -speed_max_[c];
        reduce_neighbourhood<true>(grid_, bound_reach_, floor_, 1, scratch_);
        for (double& f : floor_)
            f = -f;
    }

    // chi_ab (pair type t, pair_index order) at cell c.
    double chi(std::size_t c, std::size_t t) const { return chi_[c * types() + t]; }
    // The flow U at cell c (with Lees-Edwards: the base flow at the cell's centre plus the smoothed flow
    // about it).
    std::array<double, 3> flow(std::size_t c) const {
        return {flow_[c * 3] + base_flow(c), flow_[c * 3 + 1], flow_[c * 3 + 2]};
    }
    // The Lees-Edwards flow a (y - L_y/2) at cell c's centre (0 without): set_densities takes the
    // momentum about it.
    double base_flow(std::size_t c) const {
        if (shear_rate_ == 0)
            return 0.0;
        const auto row = static_cast<double>((c / static_cast<std::size_t>(grid_.n[0])) % static_cast<std::size_t>(grid_.n[1]));
        return shear_rate_ * h_[1] * (row + 0.5 - 0.5 * grid_.n[1]);
    }
    // Over c's reach: the largest sigma_ab^2 chi_ab, the largest count of one species, the largest
    // |U(c') - U(c)| (bounded by the spread of each component), the largest speed about U.
    double weight_max(std::size_t c) const { return weight_max_[c]; }
    double count_max(std::size_t c) const { return count_max_[c]; }
    double flow_spread(std::size_t c) const { return spread_[c]; }
    double speed_max(std::size_t c) const { return speed_max_[c]; }
    double speed_floor(std::size_t c) const { return floor_[c]; }

  private:
    CellGrid grid_;
    std::vector<double> sigma_, sigma_pair_;
    double chi_constant_ = 0, shear_rate_ = 0;
    std::array<double, 3> h_{};
    std::array<int, 3> reach_{}, bound_reach_{}, smooth_{};
    CellBlocks blocks_;
    std::vector<double> chi_, flow_, weight_max_, count_max_, spread_, speed_max_, floor_;
    std::vector<double> volume_, sums_, maxima_, scratch_; // the smoothing cube's cells; work arrays
};

} // namespace roughgas
