#include "roughgas/io/moments_csv.hpp"

#include "roughgas/dsmc/run.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>

namespace roughgas {
namespace {

// "a02.ice" -> {"a02", ".ice"}; "T_tr.a/T_tr.b" stays whole.
std::pair<std::string, std::string> split(const std::string& name) {
    const std::size_t dot = name.find('.');
    if (dot == std::string::npos || name.find('/') != std::string::npos) return {name, ""};
    return {name.substr(0, dot), name.substr(dot)};
}

} // namespace

MomentsTable::MomentsTable(const RunSpec& spec) : solver_(dsmc_columns(spec)), replicas_(spec.replicas) {
    if (replicas_ < 1) throw std::invalid_argument("MomentsTable: replicas must be >= 1");
    for (const Column& c : solver_) {
        columns_.push_back(c);
        if (replicas_ > 1) columns_.push_back({c.name + "_err", c.unit});
    }
    if (std::optional<HcsTheory> th = hcs_theory(spec)) {
        trajectory_.emplace(std::move(*th), initial_temperatures(spec));
        columns_.push_back({"T_tr_theory", "energy"});
        columns_.push_back({"T_rot_theory", "energy"});
        columns_.push_back({"theta_theory", "-"});
        if (spec.species.size() > 1) {
            for (const SpeciesSpec& s : spec.species) {
                columns_.push_back({"T_tr_theory." + s.name, "energy"});
                columns_.push_back({"T_rot_theory." + s.name, "energy"});
                columns_.push_back({"theta_theory." + s.name, "-"});
            }
        }
    }
}

std::vector<std::string> MomentsTable::names() const {
    std::vector<std::string> v;
    for (const Column& c : columns_) v.push_back(c.name);
    return v;
}

std::vector<std::string> MomentsTable::units() const {
    std::vector<std::string> v;
    for (const Column& c : columns_) v.push_back(c.unit);
    return v;
}

void MomentsTable::check(std::span<const double> row) const {
    if (row.size() != solver_.size())
        throw std::invalid_argument(fmt::format("moments row has {} values for {} columns", row.size(), solver_.size()));
    std::map<std::string, double> value;
    for (std::size_t j = 0; j < row.size(); ++j) value[solver_[j].name] = row[j];
    const auto zero = [&](const std::string& name) {
        const auto it = value.find(name);
        return it != value.end() && it->second == 0;
    };
    const double t = row[0];
    const bool first = value.count("coll_per_particle") && value["coll_per_particle"] == 0;
    for (std::size_t j = 0; j < row.size(); ++j) {
        if (std::isfinite(row[j])) continue;
        const std::string& name = solver_[j].name;
        const auto [base, suffix] = split(name);
        bool undefined = false;
        if (base == "coll_rate" || base == "E_diss_rate") undefined = first;
        if (base == "theta" || base == "a20" || base == "a11") undefined |= zero("T_tr" + suffix);
        if (base == "a02" || base == "a11" || base == "A_cw") undefined |= zero("T_rot" + suffix);
        if (const std::size_t slash = name.find('/'); slash != std::string::npos)
            undefined = zero(name.substr(slash + 1)); // T_tr.A/T_tr.B with T_tr.B = 0
        if (!undefined) {
            throw NonFiniteValue(name, t, row[j],
                                 fmt::format("column {} is {} at t = {:.17g} (coll_per_particle = {:.17g})", name,
                                             row[j], t, value.count("coll_per_particle") ? value["coll_per_particle"] : 0.0));
        }
    }
}

std::vector<double> MomentsTable::combine(std::span<const std::span<const double>> rows) {
    if (rows.size() != static_cast<std::size_t>(replicas_))
        throw std::invalid_argument(fmt::format("MomentsTable: {} replica rows for {} replicas", rows.size(), replicas_));
    const std::size_t n = solver_.size();
    std::vector<double> out;
    out.reserve(columns_.size());
    const double K = static_cast<double>(replicas_);
    for (std::size_t j = 0; j < n; ++j) {
        double sum = 0;
        for (const auto& r : rows) sum += r[j];
        const double mean = sum / K;
        out.push_back(mean);
        if (replicas_ > 1) {
            double ss = 0;
            for (const auto& r : rows) ss += (r[j] - mean) * (r[j] - mean);
            out.push_back(std::sqrt(ss / (K * (K - 1))));
        }
    }
    if (trajectory_) {
        const double t = out[0];
        const HcsTemperatures T = trajectory_->at(t);
        const HcsTheory& th = trajectory_->theory();
        const double tr = th.mixture_T_tr(T), rot = th.mixture_T_rot(T);
        out.push_back(tr);
        out.push_back(rot);
        out.push_back(rot / tr);
        if (th.species_count() > 1) {
            for (std::size_t s = 0; s < th.species_count(); ++s) {
                out.push_back(T.T_tr[s]);
                out.push_back(T.T_rot[s]);
                out.push_back(T.T_rot[s] / T.T_tr[s]);
            }
        }
    }
    return out;
}

} // namespace roughgas
