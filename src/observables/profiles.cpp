// Profiles of the spatially resolved gas: observables/profiles.hpp.
#include "roughgas/observables/profiles.hpp"

#include "bin_sums.hpp"

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

std::vector<double> compute_profiles(const ProfileGeometry& g, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                     const std::vector<Vec3>& w, const std::vector<SpeciesBlock>& species,
                                     const std::vector<Virial>& virial, double dt, WorkerTeam* team) {
    if (g.bins < 1 || virial.size() != static_cast<std::size_t>(g.bins))
        throw std::invalid_argument("compute_profiles: one virial per bin needed");
    detail::BinGrid grid;
    grid.length = g.box;
    const auto axis = static_cast<std::size_t>(g.axis);
    grid.bins[axis] = g.bins;
    grid.length[axis] = g.length;
    grid.walled[axis] = !g.periodic;
    return detail::profiles_from_sums(g, detail::bin_sums(g, grid, x, v, w, species, team), virial, dt);
}

namespace detail {

std::vector<double> profiles_from_sums(const ProfileGeometry& g, const std::vector<BinSums>& s,
                                       const std::vector<Virial>& virial, double dt) {
    const auto B = static_cast<std::size_t>(g.bins);
    if (s.size() != B || virial.size() != B)
        throw std::invalid_argument("profiles_from_sums: one sum and one virial per bin needed");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double f = g.weight / g.bin_volume;
    std::vector<double> out;
    out.reserve(B * profile_field_count);
    for (std::size_t k = 0; k < B; ++k) {
        const BinSums& b = s[k];
        out.push_back(f * b.count);
        if (b.count == 0) {
            out.insert(out.end(), profile_field_count - 1, nan);
            continue;
        }
        const Vec3 u = b.flow();
        const double T_tr = (b.cc[0] + b.cc[1] + b.cc[2]) / (3 * b.count), T_rot = b.rot / (3 * b.count);
        for (double q : {u.x, u.y, u.z, T_tr, T_rot, T_tr > 0 ? T_rot / T_tr : nan})
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

} // namespace detail
} // namespace roughgas
