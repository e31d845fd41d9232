// Sums over the grains of each bin in the middle of a flight: bin_sums.hpp.
#include "bin_sums.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace roughgas::detail {
namespace {

double& component(Vec3& q, std::size_t a) { return a == 0 ? q.x : a == 1 ? q.y : q.z; }

} // namespace

std::vector<BinSums> bin_sums(const FlightSampling& s, const BinGrid& g, const std::vector<Vec3>& x,
                              const std::vector<Vec3>& v, const std::vector<Vec3>& w,
                              const std::vector<SpeciesBlock>& species) {
    const double tau = s.half_flight;
    const Vec3 dv = tau * s.gravity;
    // The axes a grain's bin or mid-flight velocity depends on: binned ones, walled ones (a
    // reflection reverses the velocity) and, for the Lees-Edwards image, y.
    std::array<bool, 3> track{};
    std::array<double, 3> per_length{}; // B/L: bins per unit length (no division per grain)
    for (std::size_t a = 0; a < 3; ++a) {
        track[a] = g.bins[a] > 1 || g.walled[a];
        per_length[a] = g.bins[a] / g.length[a];
    }
    // A grain's bin and velocity in the middle of the flight (profiles.hpp). Along a walled axis a
    // grain that would pass a wall in that half flight is reflected specularly (position mirrored,
    // normal velocity reversed): without it, the grains flying into a wall would pile up in the
    // wall's bin and give it a flow into the wall. Computed in each pass, not stored: no array per grain.
    const auto locate = [&](std::size_t i) -> std::pair<std::size_t, Vec3> {
        Vec3 u = v[i] + dv;
        Vec3 q = x[i] + tau * v[i] + (0.5 * tau) * dv;
        if (s.shear_rate != 0) { // Lees-Edwards: the image's grain after a crossing of y
            const double Lx = s.box[0], Ly = s.box[1];
            const double k = q.y >= 0 && q.y < Ly ? 0.0 : std::floor(q.y / Ly);
            if (k != 0) {
                u.x -= k * s.shear_rate * Ly;
                q.x -= k * std::fmod(s.shear_rate * Ly * (s.time + tau), Lx);
            }
        }
        std::size_t bin = 0; // z, y, x: i_x + B_x (i_y + B_y i_z); an untracked axis has one bin
        for (std::size_t a = 3; a-- > 0;) {
            if (!track[a]) {
                continue;
            }
            const double L = g.length[a];
            double c = component(q, a);
            if (!g.walled[a]) {
                if (c < 0 || c >= L) // most grains stay in the box: no division for them
                    c -= L * std::floor(c / L);
            } else if (c < 0 || c > L) {
                c = c < 0 ? -c : 2 * L - c;
                component(u, a) = -component(u, a);
            }
            const int B = g.bins[a];
            const int k = std::clamp(static_cast<int>(std::clamp(c, 0.0, L) * per_length[a]), 0, B - 1);
            bin = bin * static_cast<std::size_t>(B) + static_cast<std::size_t>(k);
        }
        return {bin, u};
    };

    std::vector<BinSums> sums(g.size());
    for (const SpeciesBlock& sp : species)
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i) {
            const auto [bin, u] = locate(i);
            BinSums& b = sums[bin];
            b.count += 1;
            b.mass += sp.grain.mass;
            b.momentum += sp.grain.mass * u;
            b.spin += w[i];
            b.rot += sp.moment_of_inertia() * norm2(w[i]);
        }
    std::vector<Vec3> flow(sums.size());
    for (std::size_t k = 0; k < sums.size(); ++k)
        flow[k] = sums[k].flow();
    for (const SpeciesBlock& sp : species) {
        const double m = sp.grain.mass, J = sp.moment_of_inertia();
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i) {
            const auto [bin, u] = locate(i);
            BinSums& b = sums[bin];
            const Vec3 c = u - flow[bin];
            b.cc[0] += m * c.x * c.x;
            b.cc[1] += m * c.y * c.y;
            b.cc[2] += m * c.z * c.z;
            b.cc[3] += m * c.x * c.y;
            b.cc[4] += m * c.x * c.z;
            b.cc[5] += m * c.y * c.z;
            b.heat += (0.5 * m * norm2(c) + (s.rotation ? 0.5 * J * norm2(w[i]) : 0.0)) * c;
        }
    }
    return sums;
}

std::vector<BinSums> layer_sums(const std::vector<BinSums>& cells, const BinGrid& g, int axis, bool rotation) {
    const auto a = static_cast<std::size_t>(axis);
    const std::size_t stride = a == 0 ? 1 : a == 1 ? static_cast<std::size_t>(g.bins[0])
                                                    : static_cast<std::size_t>(g.bins[0]) * static_cast<std::size_t>(g.bins[1]);
    const auto layers = static_cast<std::size_t>(g.bins[a]);
    const auto layer_of = [&](std::size_t k) { return k / stride % layers; };
    std::vector<BinSums> out(layers);
    for (std::size_t k = 0; k < cells.size(); ++k) {
        const BinSums& c = cells[k];
        BinSums& l = out[layer_of(k)];
        l.count += c.count;
        l.mass += c.mass;
        l.rot += c.rot;
        l.momentum += c.momentum;
        l.spin += c.spin;
    }
    for (std::size_t k = 0; k < cells.size(); ++k) {
        const BinSums& c = cells[k];
        if (c.count == 0)
            continue;
        BinSums& l = out[layer_of(k)];
        const Vec3 d = c.flow() - l.flow();
        const double M = c.mass;
        l.cc[0] += c.cc[0] + M * d.x * d.x;
        l.cc[1] += c.cc[1] + M * d.y * d.y;
        l.cc[2] += c.cc[2] + M * d.z * d.z;
        l.cc[3] += c.cc[3] + M * d.x * d.y;
        l.cc[4] += c.cc[4] + M * d.x * d.z;
        l.cc[5] += c.cc[5] + M * d.y * d.z;
        const Vec3 Cd{c.cc[0] * d.x + c.cc[3] * d.y + c.cc[4] * d.z, c.cc[3] * d.x + c.cc[1] * d.y + c.cc[5] * d.z,
                      c.cc[4] * d.x + c.cc[5] * d.y + c.cc[2] * d.z};
        l.heat += c.heat + Cd + (0.5 * (c.cc[0] + c.cc[1] + c.cc[2]) + 0.5 * M * norm2(d)) * d;
        if (rotation)
            l.heat += (0.5 * c.rot) * d;
    }
    return out;
}

} // namespace roughgas::detail
