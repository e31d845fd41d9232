// Profiles of the spatially resolved gas: observables/profiles.hpp.
#include "roughgas/observables/profiles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace roughgas {

std::vector<Column> profile_field_columns() {
    std::vector<Column> c;
    for (const char* f : profile_fields) {
        const std::string name = f;
        const std::string unit = name == "n"                ? "1/volume"
                                 : name.starts_with("u_")   ? "length/time"
                                 : name.starts_with("T_")   ? "energy"
                                 : name == "theta"          ? "-"
                                 : name.starts_with("P")    ? "energy/volume"
                                 : name.starts_with("q_")   ? "energy/(length^2*time)"
                                                            : "1/time";
        c.push_back({name, unit});
    }
    return c;
}

namespace {

double coordinate(const Vec3& q, int a) { return a == 0 ? q.x : a == 1 ? q.y : q.z; }

} // namespace

std::vector<double> compute_profiles(const ProfileGeometry& g, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                     const std::vector<Vec3>& w, const std::vector<SpeciesBlock>& species,
                                     const std::vector<Virial>& virial, double dt) {
    if (g.bins < 1 || virial.size() != static_cast<std::size_t>(g.bins))
        throw std::invalid_argument("compute_profiles: one virial per bin needed");
    const auto B = static_cast<std::size_t>(g.bins);
    const double per_length = g.bins / g.length;
    const double tau = g.half_flight, L = g.length;
    const Vec3 dv = tau * g.gravity;
    // Each grain's bin and velocity in the middle of the flight (profiles.hpp). Along a walled axis
    // a grain that would pass a wall in that half flight is reflected specularly (position mirrored,
    // normal velocity reversed): without it, the grains flying into a wall would pile up in the
    // wall's bin and give it a flow into the wall.
    std::vector<std::size_t> bin(x.size());
    std::vector<Vec3> vel(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        Vec3 u_i = v[i] + dv;
        double q = coordinate(x[i], g.axis) + tau * coordinate(v[i], g.axis) + 0.5 * tau * coordinate(dv, g.axis);
        if (g.shear_rate != 0) { // Lees-Edwards: the image's grain after a crossing of y
            const double Lx = g.box[0], Ly = g.box[1];
            const double k = std::floor((x[i].y + tau * v[i].y + 0.5 * tau * dv.y) / Ly);
            if (k != 0) {
                u_i.x -= k * g.shear_rate * Ly;
                if (g.axis == 0)
                    q -= k * std::fmod(g.shear_rate * Ly * (g.time + tau), Lx);
            }
        }
        if (g.periodic) {
            q -= L * std::floor(q / L);
        } else if (q < 0 || q > L) {
            q = q < 0 ? -q : 2 * L - q;
            double& n = g.axis == 0 ? u_i.x : g.axis == 1 ? u_i.y : u_i.z;
            n = -n;
        }
        bin[i] = static_cast<std::size_t>(std::clamp(static_cast<int>(std::clamp(q, 0.0, L) * per_length), 0, g.bins - 1));
        vel[i] = u_i;
    }

    struct Sums {
        double count = 0, mass = 0, rot = 0;
        Vec3 momentum{}, spin{};
        double cc[6] = {}; // m c_a c_b: xx, yy, zz, xy, xz, yz
        Vec3 heat{};
    };
    std::vector<Sums> s(B);
    for (const SpeciesBlock& sp : species)
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i) {
            Sums& b = s[bin[i]];
            b.count += 1;
            b.mass += sp.grain.mass;
            b.momentum += sp.grain.mass * vel[i];
            b.spin += w[i];
            b.rot += sp.moment_of_inertia() * norm2(w[i]);
        }
    std::vector<Vec3> u(B);
    for (std::size_t k = 0; k < B; ++k)
        u[k] = s[k].mass > 0 ? (1.0 / s[k].mass) * s[k].momentum : Vec3{};
    for (const SpeciesBlock& sp : species) {
        const double m = sp.grain.mass, J = sp.moment_of_inertia();
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i) {
            Sums& b = s[bin[i]];
            const Vec3 c = vel[i] - u[bin[i]];
            b.cc[0] += m * c.x * c.x;
            b.cc[1] += m * c.y * c.y;
            b.cc[2] += m * c.z * c.z;
            b.cc[3] += m * c.x * c.y;
            b.cc[4] += m * c.x * c.z;
            b.cc[5] += m * c.y * c.z;
            b.heat += (0.5 * m * norm2(c) + (g.rotation ? 0.5 * J * norm2(w[i]) : 0.0)) * c;
        }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double f = g.weight / g.bin_volume;
    std::vector<double> out;
    out.reserve(B * profile_field_count);
    for (std::size_t k = 0; k < B; ++k) {
        const Sums& b = s[k];
        out.push_back(f * b.count);
        if (b.count == 0) {
            out.insert(out.end(), profile_field_count - 1, nan);
            continue;
        }
        const double T_tr = (b.cc[0] + b.cc[1] + b.cc[2]) / (3 * b.count), T_rot = b.rot / (3 * b.count);
        for (double q : {u[k].x, u[k].y, u[k].z, T_tr, T_rot, T_tr > 0 ? T_rot / T_tr : nan})
            out.push_back(q);
        for (double q : b.cc)
            out.push_back(f * q);
        for (double q : virial[k])
            out.push_back(std::isnan(dt) ? nan : f * q / dt);
        for (double q : {b.heat.x, b.heat.y, b.heat.z})
            out.push_back(f * q);
        for (double q : {b.spin.x, b.spin.y, b.spin.z})
            out.push_back(q / b.count);
    }
    return out;
}

} // namespace roughgas
