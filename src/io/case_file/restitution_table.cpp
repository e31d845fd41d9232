// [restitution]: its build, its checks and its emission.
#include "restitution_table.hpp"

#include <fmt/format.h>

namespace roughgas::case_file {

RestitutionGridConfig build_restitution_grid(const Reader& r) {
    RestitutionGridConfig g;
    g.g_n_min = r.real("g_n_min");
    g.g_n_max = r.real("g_n_max");
    g.g_n_points = r.integer("g_n_points");
    g.g_t_min = r.real("g_t_min");
    g.g_t_max = r.real("g_t_max");
    g.g_t_points = r.integer("g_t_points");
    g.spacing = r.choice<GridSpacing>("spacing", grid_spacing_names);
    return g;
}

void check_restitution_grid(BuildContext& ctx, const RestitutionGridConfig& g) {
    if (g.g_n_max < g.g_n_min) {
        ctx.add("restitution.g_n_max",
                fmt::format("restitution.g_n_max = {}: must be >= restitution.g_n_min = {} (m/s)", g.g_n_max,
                            g.g_n_min));
    }
    if (g.g_t_max < g.g_t_min) {
        ctx.add("restitution.g_t_max",
                fmt::format("restitution.g_t_max = {}: must be >= restitution.g_t_min = {} (m/s)", g.g_t_max,
                            g.g_t_min));
    }
}

void emit_restitution_grid(Emitter& e, const RestitutionGridConfig& g) {
    e.header("[restitution]");
    e.put("g_n_min", g.g_n_min);
    e.put("g_n_max", g.g_n_max);
    e.put("g_n_points", g.g_n_points);
    e.put("g_t_min", g.g_t_min);
    e.put("g_t_max", g.g_t_max);
    e.put("g_t_points", g.g_t_points);
    e.put("spacing", name(g.spacing));
}

} // namespace roughgas::case_file
