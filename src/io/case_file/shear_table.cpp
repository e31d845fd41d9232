// [shear]: its build, its check, whether it is used, and its emission.
#include "shear_table.hpp"

#include "toml_access.hpp"

#include <fmt/format.h>

namespace roughgas::case_file {

std::optional<ShearConfig> build_shear(const toml::table& root) {
    const toml::table* s = root["shear"].as_table();
    if (s == nullptr || !s->contains("rate"))
        return std::nullopt;
    const Reader r(s, "shear");
    return ShearConfig{r.real("rate"), r.real("time_step")};
}

void check_shear(BuildContext& ctx, const CaseConfig& c) {
    if (c.run.kind == RunKind::shear) {
        ctx.require(c.shear.has_value(), "shear.rate", "run.kind = \"shear\"", "shear");
    }
}

void note_unused_shear(const toml::table& root, CaseConfig& c) {
    if (root["shear"].as_table() != nullptr && c.run.kind != RunKind::shear)
        c.unused.push_back(fmt::format("[shear] is not used by run.kind = \"{}\"", name(c.run.kind)));
}

void emit_shear(Emitter& e, const ShearConfig& s) {
    e.header("[shear]");
    e.put("rate", s.rate);
    e.put("time_step", s.time_step);
}

} // namespace roughgas::case_file
