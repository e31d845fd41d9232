// [collision] and [[pair]]: their build, their checks, the keys their models leave unused, and
// their emission.
#include "collision_tables.hpp"

#include "messages.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace roughgas::case_file {
namespace {

// What a collision model reads of its table (case_schema.cpp's collision keys).
bool model_uses(CollisionModel m, std::string_view key) {
    switch (m) {
    case CollisionModel::constant:
        return key == "alpha" || key == "beta";
    case CollisionModel::coulomb:
        return key == "alpha" || key == "beta0" || key == "friction";
    case CollisionModel::viscoelastic:
        return key == "beta" || key == "direct";
    case CollisionModel::brilliantov:
        return key == "direct";
    }
    return true;
}

void check_pair(BuildContext& ctx, const CaseConfig& c, std::size_t i) {
    const std::string key = fmt::format("pair.{}.species", i);
    std::vector<std::string> names;
    for (const SpeciesConfig& s : c.species)
        names.push_back("\"" + s.name + "\"");
    const auto& p = c.pairs[i].species;
    for (const std::string& n : p) {
        const bool known = std::any_of(c.species.begin(), c.species.end(),
                                       [&](const SpeciesConfig& s) { return s.name == n; });
        if (!known) {
            ctx.add(key, fmt::format("{} = [\"{}\", \"{}\"]: \"{}\" is not a species (must be one of {})", key,
                                     p[0], p[1], n, join(names)));
        }
    }
    for (std::size_t j = 0; j < i; ++j) {
        const auto& q = c.pairs[j].species;
        if ((q[0] == p[0] && q[1] == p[1]) || (q[0] == p[1] && q[1] == p[0])) {
            ctx.add(key, fmt::format("{} = [\"{}\", \"{}\"]: pair.{} already sets this pair (one [[pair]] per pair)",
                                     key, p[0], p[1], j));
        }
    }
}

void check_collision(BuildContext& ctx, const CollisionConfig& c, const std::string& prefix) {
    const std::string why = fmt::format("{}.model = \"{}\"", prefix, name(c.model));
    switch (c.model) {
    case CollisionModel::constant:
        ctx.require(c.alpha.has_value(), prefix + ".alpha", why, prefix);
        ctx.require(c.beta.has_value(), prefix + ".beta", why, prefix);
        break;
    case CollisionModel::coulomb:
        ctx.require(c.alpha.has_value(), prefix + ".alpha", why, prefix);
        ctx.require(c.beta0.has_value(), prefix + ".beta0", why, prefix);
        ctx.require(c.friction.has_value(), prefix + ".friction", why, prefix);
        break;
    case CollisionModel::viscoelastic:
    case CollisionModel::brilliantov:
        ctx.need_material(why, c.model == CollisionModel::brilliantov);
        break;
    }
}

void note_unused_keys(const toml::table* t, const CollisionConfig& cc, const std::string& prefix, CaseConfig& c) {
    if (t == nullptr)
        return;
    // (direct, a defaulted flag that emit_case always writes, is left out: a resumed run
    // parses the emitted case and must report exactly what the first one did)
    for (const char* k : {"alpha", "beta", "beta0", "friction"})
        if (t->contains(k) && !model_uses(cc.model, k))
            c.unused.push_back(
                fmt::format("{}.{} is not used by {}.model = \"{}\"", prefix, k, prefix, name(cc.model)));
}

void emit_collision_keys(Emitter& e, const CollisionConfig& c) {
    e.put("model", name(c.model));
    e.put("alpha", c.alpha);
    e.put("beta", c.beta);
    e.put("beta0", c.beta0);
    e.put("friction", c.friction);
    e.put("direct", c.direct);
}

} // namespace

CollisionConfig build_collision(const Reader& r) {
    CollisionConfig c;
    c.model = r.choice<CollisionModel>("model", collision_model_names);
    c.alpha = r.opt_real("alpha");
    c.beta = r.opt_real("beta");
    c.beta0 = r.opt_real("beta0");
    c.friction = r.opt_real("friction");
    c.direct = r.boolean("direct");
    return c;
}

PairConfig build_pair(const toml::table& pair, const toml::table* collision) {
    toml::table merged = collision ? *collision : toml::table{};
    for (auto&& [k, v] : pair) {
        if (k.str() != "species")
            merged.insert_or_assign(k.str(), v);
    }
    PairConfig p;
    const toml::array& names = *pair["species"].as_array();
    p.species = {names[0].as_string()->get(), names[1].as_string()->get()};
    p.collision = build_collision(Reader(&merged, "collision"));
    return p;
}

void check_collisions(BuildContext& ctx, const CaseConfig& c) {
    check_collision(ctx, c.collision, "collision");
    for (std::size_t i = 0; i < c.pairs.size(); ++i) {
        check_pair(ctx, c, i);
        check_collision(ctx, c.pairs[i].collision, fmt::format("pair.{}", i));
    }
}

void note_unused_collision_keys(const toml::table& root, CaseConfig& c) {
    note_unused_keys(root["collision"].as_table(), c.collision, "collision", c);
    if (const toml::array* a = root["pair"].as_array())
        for (std::size_t i = 0; i < a->size() && i < c.pairs.size(); ++i)
            note_unused_keys(a->get(i)->as_table(), c.pairs[i].collision, fmt::format("pair.{}", i), c);
}

void emit_collision(Emitter& e, const CollisionConfig& collision) {
    e.header("[collision]");
    emit_collision_keys(e, collision);
}

void emit_pairs(Emitter& e, const std::vector<PairConfig>& pairs) {
    for (const PairConfig& p : pairs) {
        e.header("[[pair]]");
        e.put("species", p.species);
        emit_collision_keys(e, p.collision);
    }
}

} // namespace roughgas::case_file
