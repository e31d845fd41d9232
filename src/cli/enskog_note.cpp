#include "enskog_note.hpp"

#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/dsmc/species.hpp"

#include <fmt/format.h>

#include <variant>

namespace roughgas::cli {

std::optional<std::string> enskog_note(const RunSpec& spec) {
    if (!spec.enskog)
        return std::nullopt;
    const double phi = solid_fraction(spec.density, spec.species);
    const std::vector<double> chi = pair_correlations(spec);
    const bool constant = spec.enskog->model == PairCorrelationModel::constant;
    const std::size_t S = spec.species.size();
    std::string text = fmt::format("Enskog equation: solid fraction phi = {:.4g}, ", phi);
    if (S == 1) {
        text += fmt::format("pair correlation at contact chi = {:.4g} ({})", chi[0],
                            constant ? "run.chi" : "Carnahan & Starling");
    } else {
        text += constant ? "pair correlation at contact chi = " : "pair correlations at contact (BMCSL) ";
        if (constant) {
            text += fmt::format("{:.4g} (run.chi) for every pair", chi[0]);
        } else {
            for (std::size_t a = 0; a < S; ++a)
                for (std::size_t b = a; b < S; ++b)
                    text += fmt::format("{}chi({}, {}) = {:.4g}", a == 0 && b == 0 ? "" : ", ", spec.species[a].name,
                                        spec.species[b].name, chi[pair_index(a, b, S)]);
        }
    }
    text += ": every pair collides chi times as often as in the dilute gas";
    if (S == 1)
        if (const auto* r = std::get_if<ConstantRestitution>(&spec.pairs[0]))
            text += fmt::format("; the pressure of the uniform, unsheared gas p/(n T_tr) = 1 + 2 (1 + alpha) phi chi = {:.4g}",
                                1 + 2 * (1 + r->alpha) * phi * chi[0]);
    return text;
}

} // namespace roughgas::cli
