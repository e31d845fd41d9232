// [initial]: its build, its checks and its emission.
#include "initial_table.hpp"

#include "toml_access.hpp"

#include <fmt/format.h>

#include <cmath>

namespace roughgas::case_file {

std::optional<InitialConfig> build_initial(const toml::table& root) {
    const toml::table* t = root["initial"].as_table();
    if (t == nullptr)
        return std::nullopt;
    const Reader r(t, "initial");
    InitialConfig w;
    w.mode = r.choice<Perturbation>("mode", perturbation_names);
    w.amplitude = r.real("amplitude");
    if (r.has("wave"))
        w.wave = r.integer3("wave");
    if (r.has("from"))
        w.from = r.string("from");
    return w;
}

void check_initial(BuildContext& ctx, const CaseConfig& c) {
    if (c.initial && !c.initial->from.empty() && c.run.kernel == CollisionKernel::maxwell)
        ctx.add("initial.from",
                fmt::format("initial.from = \"{}\" with run.kernel = \"maxwell\": the kernel's rates come from "
                            "the species' temperatures in this case, not from the saved grains' (start a Maxwell "
                            "kernel run from its Maxwellian)",
                            c.initial->from));
    if (c.initial && c.initial->mode != Perturbation::none) {
        if (!c.domain)
            ctx.add("initial.mode", fmt::format("initial.mode = \"{}\" without [domain]: a wave needs positions "
                                                "(give the box in [domain])",
                                                name(c.initial->mode)));
        const auto& k = c.initial->wave;
        if (k[0] == 0 && k[1] == 0 && k[2] == 0)
            ctx.add("initial.wave", "initial.wave = [0, 0, 0]: a wave needs a wave number other than 0");
    }
}

void check_wave_resolution(BuildContext& ctx, const CaseConfig& c) {
    const DomainConfig& d = *c.domain;
    if (c.initial && c.initial->mode != Perturbation::none)
        for (std::size_t i = 0; i < 3; ++i) {
            const double n = std::abs(static_cast<double>(c.initial->wave[i]));
            if (n > 0 && d.size[i] / n < 2 * d.size[i] / static_cast<double>(d.cells[i]))
                ctx.add("initial.wave",
                        fmt::format("initial.wave = [{}, {}, {}]: a wavelength along {} of {:.4g} spans fewer than "
                                    "two cells of {:.4g} (collisions inside a cell ignore positions)",
                                    c.initial->wave[0], c.initial->wave[1], c.initial->wave[2], "xyz"[i],
                                    d.size[i] / n, d.size[i] / static_cast<double>(d.cells[i])));
        }
}

void emit_initial(Emitter& e, const InitialConfig& w) {
    e.header("[initial]");
    e.put("mode", name(w.mode));
    e.put("amplitude", w.amplitude);
    e.put("wave", w.wave);
    if (!w.from.empty())
        e.put("from", w.from);
}

} // namespace roughgas::case_file
