// [material]: its build (the dissipation A given or from the viscosities), its checks, whether it is
// used, and its emission.
#include "material_table.hpp"

#include "messages.hpp"
#include "roughgas/contact/material.hpp"

#include <fmt/format.h>

namespace roughgas::case_file {
namespace {

// A is given directly or, by Brilliantov et al. (1996) eq. 23, from both viscosities: never both,
// never neither.
double dissipation(BuildContext& ctx, const Reader& r, const MaterialConfig& m) {
    const KeySpec& a_spec = *find_key("material.dissipation");
    const bool viscous = m.eta1 || m.eta2;
    if (r.has("dissipation")) {
        if (viscous) {
            ctx.add("material.dissipation",
                    "material.dissipation: give either dissipation or eta1 and eta2, not both");
        }
        return r.real("dissipation");
    }
    if (!viscous) {
        ctx.add("material.dissipation",
                fmt::format("material.dissipation: required key is missing (must be {}; "
                            "or give eta1 and eta2)",
                            expectation(a_spec)),
                "material");
        return 0;
    }
    if (!m.eta1 || !m.eta2) {
        const std::string missing = m.eta1 ? "material.eta2" : "material.eta1";
        ctx.add(missing,
                fmt::format("{}: required with {} (A follows from both viscosities, Brilliantov et al. "
                            "1996 eq. 23; must be >= 0 (Pa s))",
                            missing, m.eta1 ? "eta1" : "eta2"),
                "material");
        return 0;
    }
    if (m.poisson_ratio == 0 || 3 * *m.eta2 + 2 * *m.eta1 <= 0) {
        ctx.add("material.eta1", "material.eta1, material.eta2: Brilliantov et al. 1996 eq. 23 needs "
                                 "poisson_ratio != 0 and 3 eta2 + 2 eta1 > 0");
        return 0;
    }
    return dissipation_from_viscosities(*m.eta1, *m.eta2, m.young_modulus, m.poisson_ratio);
}

} // namespace

MaterialConfig build_material(BuildContext& ctx, const Reader& r) {
    MaterialConfig m;
    m.young_modulus = r.real("young_modulus");
    m.poisson_ratio = r.real("poisson_ratio");
    m.eta1 = r.opt_real("eta1");
    m.eta2 = r.opt_real("eta2");
    m.friction = r.opt_real("friction");
    m.asperity = r.opt_real("asperity");
    m.dissipation = dissipation(ctx, r, m);
    return m;
}

void check_material(BuildContext& ctx, const CaseConfig& c) {
    if (ctx.use() == CaseUse::restitution)
        ctx.need_material("roughgas restitution", true);
    if (ctx.material_users().empty())
        return;
    if (!c.material) {
        ctx.add("material", fmt::format("material: the [material] table is required for {} but missing "
                                        "(young_modulus, poisson_ratio, dissipation{})",
                                        join(ctx.material_users()),
                                        ctx.asperity_users().empty() ? "" : ", friction, asperity"));
        return;
    }
    if (!ctx.asperity_users().empty()) {
        const std::string why = join(ctx.asperity_users());
        ctx.require(c.material->friction.has_value(), "material.friction", why, "material");
        ctx.require(c.material->asperity.has_value(), "material.asperity", why, "material");
    }
}

void note_unused_material(const BuildContext& ctx, CaseConfig& c) {
    if (ctx.use() == CaseUse::run && ctx.material_users().empty() && ctx.root()["material"].as_table() != nullptr)
        c.unused.push_back("[material] is not used: no species pair has model = \"viscoelastic\" or "
                           "\"brilliantov\"");
}

void emit_material(Emitter& e, const MaterialConfig& m) {
    e.header("[material]");
    e.put("young_modulus", m.young_modulus);
    e.put("poisson_ratio", m.poisson_ratio);
    if (m.eta1 && m.eta2) { // A was derived: echo what the user gave, so that it reads back the same
        e.put("eta1", m.eta1);
        e.put("eta2", m.eta2);
    } else {
        e.put("dissipation", m.dissipation);
    }
    e.put("friction", m.friction);
    e.put("asperity", m.asperity);
}

} // namespace roughgas::case_file
