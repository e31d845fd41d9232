// The wall tables: their build, their checks, what of them is unused, and their emission.
#include "wall_tables.hpp"

#include "toml_access.hpp"

#include <fmt/format.h>

#include <vector>

namespace roughgas::case_file {

void build_walls(const toml::table& root, CaseConfig& c) {
    for (const WallTable& table : wall_tables())
        if (const toml::table* t = root[table.name].as_table()) {
            const Reader r(t, table.name);
            WallConfig w;
            w.kind = r.choice<WallKind>("kind", wall_kind_names);
            w.temperature = r.opt_real("temperature");
            w.velocity = r.real3("velocity");
            w.alpha = r.opt_real("alpha");
            w.beta = r.opt_real("beta");
            wall_config(c, table) = w;
        }
}

void check_walls(BuildContext& ctx, const CaseConfig& c) {
    const DomainConfig& d = *c.domain;
    if (!d.has_walls())
        return;
    // Walls on x or y of a sheared box are refused as such (check_domain): their tables' keys are
    // not asked for or checked, so that the conflict is the one message.
    const auto walled = [&](int a) {
        return d.boundary[static_cast<std::size_t>(a)] == Boundary::walls && (c.run.kind != RunKind::shear || a == 2);
    };
    for (int a = 0; a < 3; ++a)
        for (const bool upper : {false, true})
            if (walled(a) && !wall_config(c, wall_table_of(c, a, upper))) {
                const std::string side = upper ? "wall_upper" : "wall_lower";
                ctx.add(side, fmt::format("domain.boundary has \"walls\" but [{}] is missing: give the wall at "
                                          "{} of each walled axis (kind = \"diffuse\", \"specular\" or "
                                          "\"rough\"), or axis {}'s own [{}_{}]",
                                          side, upper ? "L" : "0", "xyz"[a], side, "xyz"[a]));
            }
    for (const WallTable& table : wall_tables()) {
        const std::optional<WallConfig>& w = wall_config(c, table);
        std::vector<int> axes = wall_axes(c, table);
        std::erase_if(axes, [&](int a) { return !walled(a); });
        if (!w || axes.empty())
            continue;
        const std::string& side = table.name;
        if (w->kind == WallKind::diffuse)
            ctx.require(w->temperature.has_value(), side + ".temperature", side + ".kind = \"diffuse\"", side);
        for (const int a : axes)
            if (w->velocity[static_cast<std::size_t>(a)] != 0)
                ctx.add(side + ".velocity",
                        fmt::format("{}.velocity = [{}, {}, {}]: a wall of axis {} moves along itself only "
                                    "(component {} must be 0)",
                                    side, w->velocity[0], w->velocity[1], w->velocity[2], "xyz"[a], "xyz"[a]));
    }
}

void note_unused_walls(const toml::table& root, CaseConfig& c) {
    for (const WallTable& table : wall_tables()) {
        const std::optional<WallConfig>& w = wall_config(c, table);
        const std::string& side = table.name;
        if (!w)
            continue;
        if (!c.domain || !c.domain->has_walls()) {
            c.unused.push_back(fmt::format("[{}] is not used: no axis of domain.boundary has \"walls\"", side));
            continue;
        }
        if (wall_axes(c, table).empty()) {
            c.unused.push_back(
                table.axis >= 0
                    ? fmt::format("[{}] is not used: axis {} of domain.boundary is not \"walls\"", side,
                                  "xyz"[table.axis])
                    : fmt::format("[{}] is not used: every walled axis has a [{}_x], [{}_y] or [{}_z] of its own",
                                  side, side, side, side));
            continue;
        }
        const toml::table* t = root[side].as_table();
        for (const char* k : {"alpha", "beta"})
            if (t->contains(k) && w->kind != WallKind::rough)
                c.unused.push_back(
                    fmt::format("{}.{} is not used by {}.kind = \"{}\"", side, k, side, name(w->kind)));
        if (t->contains("temperature") && w->kind != WallKind::diffuse)
            c.unused.push_back(
                fmt::format("{}.temperature is not used by {}.kind = \"{}\"", side, side, name(w->kind)));
    }
}

void emit_walls(Emitter& e, const CaseConfig& c) {
    for (const WallTable& table : wall_tables()) {
        const std::optional<WallConfig>& w = wall_config(c, table);
        if (!w)
            continue;
        e.header("[" + table.name + "]");
        e.put("kind", name(w->kind));
        if (w->temperature)
            e.put("temperature", *w->temperature);
        e.put("velocity", w->velocity);
        e.put("alpha", w->alpha);
        e.put("beta", w->beta);
    }
}

} // namespace roughgas::case_file
