// Sums over the grains of each bin in the middle of a flight: bin_sums.hpp.
#include "bin_sums.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace roughgas::detail {
namespace {

// On a team, a grid of at most max_bins_in_units bins (the slabs of the profiles, not every cell of
// the box) is summed in units of each species' grains: at least min_unit_grains grains, at most
// max_units units (each with sums of its own over every bin: 24 MB for 1024 bins at most).
constexpr std::size_t max_bins_in_units = 1024, min_unit_grains = 65536, max_units = 64;

// Each bin's moments about its reference turned into its sums about its flow (the identities in
// bin_sums), the running moments cleared for the next pass.
void moments_to_sums(std::vector<BinMoments>& acc, std::vector<BinSums>& sums, bool rotation) {
    sums.resize(acc.size());
    for (std::size_t k = 0; k < sums.size(); ++k) {
        // Each bin's running sums are read once here and cleared at once, while in the cache: no
        // pass of its own to clear them for the next call.
        const BinMoments b = std::exchange(acc[k], BinMoments{});
        BinSums& o = sums[k];
        o = BinSums{};
        o.count = b.count;
        o.mass = b.mass;
        o.rot = b.rot;
        o.momentum = b.momentum;
        o.spin = b.spin;
        if (b.count == 0)
            continue;
        const Vec3 D = (1.0 / b.mass) * b.md;
        // The diagonal is a sum of squares: a bin whose grains share one velocity gives zero, not
        // a negative round-off.
        o.cc[0] = std::max(0.0, b.a[0] - b.md.x * D.x);
        o.cc[1] = std::max(0.0, b.a[1] - b.md.y * D.y);
        o.cc[2] = std::max(0.0, b.a[2] - b.md.z * D.z);
        o.cc[3] = b.a[3] - b.md.x * D.y;
        o.cc[4] = b.a[4] - b.md.x * D.z;
        o.cc[5] = b.a[5] - b.md.y * D.z;
        const Vec3 AD{b.a[0] * D.x + b.a[3] * D.y + b.a[4] * D.z, b.a[3] * D.x + b.a[1] * D.y + b.a[5] * D.z,
                      b.a[4] * D.x + b.a[5] * D.y + b.a[2] * D.z};
        o.heat = b.q - AD + (b.mass * norm2(D) - 0.5 * (b.a[0] + b.a[1] + b.a[2])) * D;
        if (rotation)
            o.heat += b.r - (0.5 * b.rot) * D;
    }
}

// The additive sums of `part` into `whole`.
void add_totals(BinSums& whole, const BinSums& part) {
    whole.count += part.count;
    whole.mass += part.mass;
    whole.rot += part.rot;
    whole.momentum += part.momentum;
    whole.spin += part.spin;
}

// `part`'s moments about its own flow into `whole`'s about the flow U of the whole, with d = U_p - U
// (the parallel-axis identities):
//   sum m c_a c_b = sum_parts [C_ab + M_p d_a d_b],
//   sum (m c^2/2) c = sum_parts [Q + C.d + (tr C/2) d + (M_p d^2/2) d] (+ (rot_p/2) d with `rotation`).
void add_about(BinSums& whole, const BinSums& part, const Vec3& U, bool rotation) {
    const Vec3 d = part.flow() - U;
    const double M = part.mass;
    const double* C = part.cc;
    whole.cc[0] += C[0] + M * d.x * d.x;
    whole.cc[1] += C[1] + M * d.y * d.y;
    whole.cc[2] += C[2] + M * d.z * d.z;
    whole.cc[3] += C[3] + M * d.x * d.y;
    whole.cc[4] += C[4] + M * d.x * d.z;
    whole.cc[5] += C[5] + M * d.y * d.z;
    const Vec3 Cd{C[0] * d.x + C[3] * d.y + C[4] * d.z, C[3] * d.x + C[1] * d.y + C[5] * d.z,
                  C[4] * d.x + C[5] * d.y + C[2] * d.z};
    whole.heat += part.heat + Cd + (0.5 * (C[0] + C[1] + C[2]) + 0.5 * M * norm2(d)) * d;
    if (rotation)
        whole.heat += (0.5 * part.rot) * d;
}

} // namespace

std::vector<BinSums> bin_sums(const FlightSampling& s, const BinGrid& g, const std::vector<Vec3>& x,
                              const std::vector<Vec3>& v, const std::vector<Vec3>& w,
                              const std::vector<SpeciesBlock>& species, WorkerTeam* team) {
    BinSumsBuffers buffers;
    bin_sums(s, g, x, v, w, species, buffers, team);
    return std::move(buffers.sums);
}

const std::vector<BinSums>& bin_sums(const FlightSampling& s, const BinGrid& g, const std::vector<Vec3>& x,
                                     const std::vector<Vec3>& v, const std::vector<Vec3>& w,
                                     const std::vector<SpeciesBlock>& species, BinSumsBuffers& buffers,
                                     WorkerTeam* team) {
    const double tau = s.half_flight;
    const Vec3 dv = tau * s.gravity;
    // Each axis's bins: walled ones reflect (a reflection reverses the velocity); an axis of one
    // periodic bin needs no coordinate (its index is 0).
    struct AxisBins {
        double length, per_length; // per_length = B/L: bins per unit length (no division per grain)
        int bins;
        bool walled, tracked;
    };
    std::array<AxisBins, 3> axes{};
    for (std::size_t a = 0; a < 3; ++a)
        axes[a] = {g.length[a], g.bins[a] / g.length[a], g.bins[a], g.walled[a], g.bins[a] > 1 || g.walled[a]};
    // The Lees-Edwards image's shift along x at the middle of the flight, the same for every grain.
    const double image_shift = s.shear_rate != 0 ? std::fmod(s.shear_rate * s.box[1] * (s.time + tau), s.box[0]) : 0.0;
    // Coordinate c's bin along one axis; along a walled axis a grain past a wall is mirrored into
    // the box and its velocity component `u` reversed.
    const auto index = [](const AxisBins& ax, double c, double& u) -> std::size_t {
        if (!ax.tracked)
            return 0;
        const double L = ax.length;
        if (!ax.walled) {
            if (c < 0 || c >= L) // most grains stay in the box: no division for them
                c -= L * std::floor(c / L);
        } else if (c < 0 || c > L) {
            c = c < 0 ? -c : 2 * L - c;
            u = -u;
        }
        const int k = static_cast<int>(std::clamp(c, 0.0, L) * ax.per_length);
        return static_cast<std::size_t>(std::clamp(k, 0, ax.bins - 1));
    };
    // A grain's bin and velocity in the middle of the flight (profiles.hpp). Along a walled axis a
    // grain that would pass a wall in that half flight is reflected specularly (position mirrored,
    // normal velocity reversed): without it, the grains flying into a wall would pile up in the
    // wall's bin and give it a flow into the wall. Computed in each pass, not stored: no array per grain.
    const auto locate = [&](std::size_t i) -> std::pair<std::size_t, Vec3> {
        Vec3 u = v[i] + dv;
        Vec3 q = x[i] + tau * v[i] + (0.5 * tau) * dv;
        if (s.shear_rate != 0) { // Lees-Edwards: the image's grain after a crossing of y
            const double Ly = s.box[1];
            const double k = q.y >= 0 && q.y < Ly ? 0.0 : std::floor(q.y / Ly);
            if (k != 0) {
                u.x -= k * s.shear_rate * Ly;
                q.x -= k * image_shift;
            }
        }
        // z, y, x: i_x + B_x (i_y + B_y i_z)
        const std::size_t kz = index(axes[2], q.z, u.z), ky = index(axes[1], q.y, u.y), kx = index(axes[0], q.x, u.x);
        return {(kz * static_cast<std::size_t>(axes[1].bins) + ky) * static_cast<std::size_t>(axes[0].bins) + kx, u};
    };

    // One pass: each bin's moments about a velocity r_b of its own, its first grain's (d = u - r_b),
    // then about its flow U_b (D = U_b - r_b = sum m d / M, c = d - D):
    //   sum m c_a c_b = A_ab - M D_a D_b                     (A = sum m d_a d_b),
    //   sum (m c^2/2) c = Q - (tr A/2) D - A D + M D^2 D      (Q = sum (m d^2/2) d),
    //   sum (J w^2/2) c = R - (rot/2) D                       (R = sum (J w^2/2) d).
    // A reference inside the bin's velocity spread keeps the cancellation of A - M D D to the order
    // of the spread itself, as in the two-pass sums about U_b (a bin of one grain: exactly zero).
    // Grains [from, to) of one species (mass m, moment of inertia J) into `acc`, in chunks: first
    // every grain's bin and velocity, then their sums. The bins known before the sums start, the
    // loads of a bin's running sums need not wait for the locating of the grain before (whose bin
    // is most often the same).
    const auto accumulate = [&](std::size_t from, std::size_t to, double m, double J, std::vector<BinMoments>& acc) {
        constexpr std::size_t chunk = 256;
        std::array<std::size_t, chunk> bins;
        std::array<Vec3, chunk> us;
        for (std::size_t i0 = from; i0 < to; i0 += chunk) {
            const std::size_t n = std::min(chunk, to - i0);
            for (std::size_t k = 0; k < n; ++k)
                std::tie(bins[k], us[k]) = locate(i0 + k);
            for (std::size_t k = 0; k < n; ++k) {
                const std::size_t i = i0 + k;
                const Vec3 u = us[k];
                BinMoments& b = acc[bins[k]];
                if (b.count == 0)
                    b.ref = u;
                const double e_rot = J * norm2(w[i]);
                b.count += 1;
                b.mass += m;
                b.momentum += m * u;
                b.spin += w[i];
                b.rot += e_rot;
                const Vec3 d = u - b.ref, md = m * d;
                b.md += md;
                b.a[0] += md.x * d.x;
                b.a[1] += md.y * d.y;
                b.a[2] += md.z * d.z;
                b.a[3] += md.x * d.y;
                b.a[4] += md.x * d.z;
                b.a[5] += md.y * d.z;
                b.q += (0.5 * dot(md, d)) * d;
                if (s.rotation)
                    b.r += (0.5 * e_rot) * d;
            }
        }
    };
    std::vector<BinSums>& sums = buffers.sums;
    if (team && g.size() <= max_bins_in_units) {
        // Fixed units of each species' grains (their number depends on the grains alone, never on
        // the threads), each into sums of its own, added in unit order: the same sums on any team.
        struct Unit {
            std::size_t from, to;
            double m, J;
        };
        std::vector<Unit> units;
        for (const SpeciesBlock& sp : species) {
            const std::size_t size = std::max(min_unit_grains, (sp.count + max_units - 1) / max_units);
            for (std::size_t from = sp.offset; from < sp.offset + sp.count; from += size)
                units.push_back({from, std::min(from + size, sp.offset + sp.count), sp.grain.mass,
                                 sp.moment_of_inertia()});
        }
        std::vector<std::vector<BinSums>> parts(units.size());
        team->for_each(units.size(), [&](std::size_t k) {
            std::vector<BinMoments> acc(g.size());
            accumulate(units[k].from, units[k].to, units[k].m, units[k].J, acc);
            moments_to_sums(acc, parts[k], s.rotation);
        });
        sums.assign(g.size(), BinSums{});
        for (const std::vector<BinSums>& part : parts)
            for (std::size_t b = 0; b < sums.size(); ++b)
                add_totals(sums[b], part[b]);
        for (std::size_t b = 0; b < sums.size(); ++b) {
            const Vec3 U = sums[b].flow();
            for (const std::vector<BinSums>& part : parts)
                if (part[b].count > 0)
                    add_about(sums[b], part[b], U, s.rotation);
        }
        return sums;
    }
    std::vector<BinMoments>& acc = buffers.moments;
    if (acc.size() != g.size())
        acc.assign(g.size(), BinMoments{});
    for (const SpeciesBlock& sp : species)
        accumulate(sp.offset, sp.offset + sp.count, sp.grain.mass, sp.moment_of_inertia(), acc);
    moments_to_sums(acc, sums, s.rotation);
    return sums;
}
std::vector<BinSums> layer_sums(const std::vector<BinSums>& cells, const BinGrid& g, int axis, bool rotation) {
    const auto a = static_cast<std::size_t>(axis);
    const std::size_t stride = a == 0 ? 1 : a == 1 ? static_cast<std::size_t>(g.bins[0])
                                                    : static_cast<std::size_t>(g.bins[0]) * static_cast<std::size_t>(g.bins[1]);
    const auto layers = static_cast<std::size_t>(g.bins[a]);
    const auto layer_of = [&](std::size_t k) { return k / stride % layers; };
    std::vector<BinSums> out(layers);
    for (std::size_t k = 0; k < cells.size(); ++k)
        add_totals(out[layer_of(k)], cells[k]);
    for (std::size_t k = 0; k < cells.size(); ++k) {
        if (cells[k].count == 0)
            continue;
        BinSums& l = out[layer_of(k)];
        add_about(l, cells[k], l.flow(), rotation);
    }
    return out;
}

} // namespace roughgas::detail
