#include "roughgas/io/histograms_csv.hpp"

#include "roughgas/io/replica_mean.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace roughgas {
namespace {

// The three histograms: column stem, what is binned.
struct Quantity {
    const char* x;    // bin-centre column
    const char* f;    // density column stem
    const char* what; // for docs/reference.md's table
    std::vector<double> SpeciesHistograms::*member;
};
const Quantity quantities[] = {
    {"c_star", "f_c", "|c*| = |c| sqrt(m/(2 T_tr))", &SpeciesHistograms::c},
    {"w_star", "f_w", "|w*| = |omega| sqrt(J/(2 T_rot))", &SpeciesHistograms::w},
    {"cw_star", "f_cw", "c*.w*", &SpeciesHistograms::cw},
};

} // namespace

HistogramsTable::HistogramsTable(const RunSpec& spec)
    : replicas_(spec.replicas), time_clock_(spec.clock == Clock::time),
      grid_{spec.histogram_bins, spec.histogram_max} {
    if (replicas_ < 1)
        throw std::invalid_argument("HistogramsTable: replicas must be >= 1");
    for (const SpeciesSpec& s : spec.species)
        species_.push_back(s.name);
    const bool mixture = species_.size() > 1;
    const bool errors = replicas_ > 1;
    columns_ = {{"coll_per_particle", "-"}, {"t", "time"}};
    if (errors)
        columns_.push_back({"t_err", "time"});
    for (const Quantity& q : quantities) {
        columns_.push_back({q.x, "-"});
        for (const std::string& name : species_) {
            const std::string f = mixture ? std::string(q.f) + "." + name : std::string(q.f);
            columns_.push_back({f, "-"});
            if (errors)
                columns_.push_back({f + "_err", "-"});
        }
        columns_.push_back({std::string(q.f) + "_maxwell", "-"});
    }
    speed_x_ = speed_bin_centres(grid_);
    product_x_ = product_bin_centres(grid_);
    speed_ref_ = maxwell_speed_bins(grid_);
    product_ref_ = maxwell_product_bins(grid_);
}

std::vector<std::vector<double>> HistogramsTable::combine(std::span<const HistogramSet> sets) const {
    if (sets.size() != static_cast<std::size_t>(replicas_))
        throw std::invalid_argument(
            fmt::format("HistogramsTable: {} replica sets for {} replicas", sets.size(), replicas_));
    const auto B = static_cast<std::size_t>(grid_.bins);
    for (const HistogramSet& h : sets) {
        if (h.species.size() != species_.size())
            throw std::invalid_argument("HistogramsTable: a set of another species list");
        for (const SpeciesHistograms& s : h.species)
            if (s.c.size() != B || s.w.size() != B || s.cw.size() != B)
                throw std::invalid_argument("HistogramsTable: a set of another bin count");
    }
    const bool errors = replicas_ > 1;
    std::vector<double> x(sets.size());
    const auto mean = [&](auto value) {
        for (std::size_t r = 0; r < sets.size(); ++r)
            x[r] = value(sets[r]);
        return replica_mean(x);
    };
    // The time clock's histograms are at the same t in every replica: that t exactly.
    for (std::size_t r = 0; r < sets.size(); ++r)
        x[r] = sets[r].t;
    const ReplicaMean t = replica_mean_of_shared(x);
    // The collision clock's: replica 0's count, the one the histograms were asked at (the replicas of
    // a shear run pause at the end of the first Strang step past it, a few collisions apart). The
    // time clock's: each replica has its own count at the shared t, so their mean.
    const double coll = time_clock_ ? mean([](const HistogramSet& h) { return h.coll_per_particle; }).mean
                                    : sets[0].coll_per_particle;
    std::vector<std::vector<double>> rows(B);
    for (std::size_t k = 0; k < B; ++k) {
        std::vector<double>& row = rows[k];
        row.push_back(coll);
        row.push_back(t.mean);
        if (errors)
            row.push_back(t.error);
        for (const Quantity& q : quantities) {
            const bool product = q.member == &SpeciesHistograms::cw;
            row.push_back(product ? product_x_[k] : speed_x_[k]);
            for (std::size_t s = 0; s < species_.size(); ++s) {
                const ReplicaMean f = mean([&](const HistogramSet& h) { return (h.species[s].*q.member)[k]; });
                row.push_back(f.mean);
                if (errors)
                    row.push_back(f.error);
            }
            row.push_back(product ? product_ref_[k] : speed_ref_[k]);
        }
        if (row.size() != columns_.size())
            throw std::logic_error("HistogramsTable: row and columns differ");
    }
    return rows;
}

std::string histograms_columns_markdown() {
    std::string s = "| Column | Unit | Meaning |\n|--------|------|---------|\n";
    s += "| `coll_per_particle` | - | time of the histograms, in collisions per particle (2 x collisions / N; with run.end_time the mean over replicas) |\n";
    s += "| `t` | time | the same in the case's time unit (mean over replicas; with run.end_time the requested time) |\n";
    s += "| `t_err` | time | standard error of t over replicas (replicas > 1) |\n";
    for (const Quantity& q : quantities) {
        const bool product = q.member == &SpeciesHistograms::cw;
        s += fmt::format("| `{}` | - | bin centre of {}: {} bins over {} |\n", q.x, q.what, "run.histogram_bins",
                         product ? "[-histogram_max, histogram_max)" : "[0, histogram_max)");
        s += fmt::format("| `{}` | - | probability density of {}, averaged over the bin (count/(N x width)); "
                         "mixtures: `{}.NAME` per species, in the species' own temperatures |\n",
                         q.f, q.what, q.f);
        s += fmt::format("| `{}_err` | - | its standard error over replicas (replicas > 1) |\n", q.f);
        s += fmt::format("| `{}_maxwell` | - | the same bin average of the Maxwellian density ({}) |\n", q.f,
                         product ? "(4/pi) abs(z) K_1(2 abs(z))" : "(4/sqrt(pi)) x^2 exp(-x^2)");
    }
    return s;
}

} // namespace roughgas
