// [spectra]: its build, its checks and its emission.
#include "spectra_table.hpp"

#include "toml_access.hpp"

namespace roughgas::case_file {

std::optional<SpectraConfig> build_spectra(const toml::table& root) {
    const toml::table* t = root["spectra"].as_table();
    if (t == nullptr)
        return std::nullopt;
    const Reader r(t, "spectra");
    SpectraConfig s;
    s.modes = r.integer("modes");
    return s;
}

void check_spectra(BuildContext& ctx, const CaseConfig& c) {
    if (!c.spectra)
        return;
    if (!c.domain)
        ctx.add("spectra", "[spectra] without [domain]: spectra are of a box's fields (give the box in [domain])");
    else if (c.domain->has_walls())
        ctx.add("domain.boundary", "[spectra] with walls: the Fourier modes need a periodic box (every "
                                   "domain.boundary \"periodic\")");
    else if (c.run.kind == RunKind::shear)
        ctx.add("spectra", "[spectra] with run.kind = \"shear\": the Lees-Edwards box is periodic only in its "
                           "sheared frame, which the spectra do not follow");
}

void emit_spectra(Emitter& e, const SpectraConfig& s) {
    e.header("[spectra]");
    e.put("modes", s.modes);
}

} // namespace roughgas::case_file
