#include "run/summary.hpp"

#include "run/output_files.hpp"

#include "roughgas/observables/uniformity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

namespace roughgas::cli {
namespace {

namespace fs = std::filesystem;

// steady_profiles.csv: profiles.csv averaged over the steady window, per bin every field's batch
// mean and error.
void write_steady_profiles(const fs::path& dir, const SteadyResult& st, const MomentsFiles& files,
                           const RunProvenance& provenance) {
    const MomentsTable& table = files.table();
    const std::vector<std::vector<double>>& rows = files.combined();
    const std::vector<std::vector<std::vector<double>>>& blocks = files.profile_blocks();
    const std::vector<Column>& pc = table.profile_table_columns();
    std::vector<std::string> names = {pc[2].name, pc[3].name};
    std::vector<std::string> units = {pc[2].unit, pc[3].unit};
    std::vector<std::size_t> fields;
    for (std::size_t j = 4; j < pc.size(); ++j)
        if (!pc[j].name.ends_with("_err")) {
            fields.push_back(j);
            names.insert(names.end(), {pc[j].name, pc[j].name + "_err"});
            units.insert(units.end(), {pc[j].unit, pc[j].unit});
        }
    const CsvProvenance p = file_provenance(
        provenance,
        fmt::format("profiles.csv averaged over the steady window of moments.csv ({} rows from "
                    "coll_per_particle = {:.6g}{}); X_err = batch-means standard error",
                    st.rows, rows[st.first_row][1], st.reached ? "" : "; NOT steady: the second half of the run"),
        units);
    CsvWriter csv(names, p);
    std::vector<double> x;
    for (std::size_t b = 0; b < blocks[0].size(); ++b) {
        std::vector<double> row = {blocks[0][b][2], blocks[0][b][3]};
        for (std::size_t j : fields) {
            x.clear();
            for (std::size_t r = st.first_row; r < blocks.size(); ++r)
                x.push_back(blocks[r][b][j]);
            const SteadyValue v = batch_mean(x, SteadyOptions{}.batches);
            row.push_back(v.mean);
            row.push_back(v.err);
        }
        csv.add_row(row);
    }
    csv.write(dir / steady_profiles_file);
}

// A cooling gas keeps cooling only if some pair loses energy in its collisions: constant
// restitution with alpha = 1 and beta = -1 or +1 (or Walton's model with alpha = 1, mu = 0 and
// beta0 = +-1) conserves it.
bool cools(const RunSpec& spec) {
    return std::any_of(spec.pairs.begin(), spec.pairs.end(), [](const PairRestitution& p) {
        if (const auto* c = std::get_if<ConstantRestitution>(&p))
            return !(c->alpha == 1 && std::abs(c->beta) == 1);
        if (const auto* w = std::get_if<CoulombRestitution>(&p))
            return !(w->alpha == 1 && w->mu == 0 && std::abs(w->beta0) == 1);
        return true;
    });
}

bool speed_dependent(const RunSpec& spec) {
    return std::any_of(spec.pairs.begin(), spec.pairs.end(), [](const PairRestitution& p) {
        return std::holds_alternative<ViscoelasticRestitution>(p) || std::holds_alternative<BrilliantovRestitution>(p);
    });
}

// The first row whose smallest shell's S a uniform gas does not reach (observables/uniformity.hpp).
std::optional<NonUniformity> non_uniform_row(const MomentsFiles& files, int replicas) {
    const std::vector<std::vector<double>>& shells = files.smallest_shells();
    if (shells.empty() || shells.size() != files.combined().size())
        return std::nullopt;
    const std::vector<Column>& c = files.table().spectra_table_columns();
    const auto col = [&](const char* name) {
        const auto named = [&](const Column& x) { return x.name == name; };
        return static_cast<std::size_t>(std::find_if(c.begin(), c.end(), named) - c.begin());
    };
    const std::size_t modes = col("n_modes"), S = col("S");
    std::vector<double> s, m;
    for (const std::vector<double>& shell : shells) {
        s.push_back(shell.empty() ? std::nan("") : shell[S]);
        m.push_back(shell.empty() ? 0.0 : shell[modes]);
    }
    return first_non_uniform_row(s, m, replicas);
}

// "; zeta_star from 0.0626 to 0.0217 over the last window tried", or "".
std::string drift_text(const SteadyResult& st) {
    return st.drift.empty() ? std::string() : fmt::format("; {} over the last window tried", st.drift);
}

} // namespace

void write_summary_csv(const fs::path& dir, bool steady, const SteadyResult& st, const std::vector<std::string>& names,
                       const std::vector<std::string>& units, const std::vector<std::vector<double>>& rows,
                       CsvProvenance provenance) {
    provenance.units = steady_csv_units(st, names, units);
    provenance.notes.push_back(fmt::format("{} summary of moments.csv: drift criterion on {}; batch means "
                                           "(observables/steady_state.hpp); X_err = batch-means standard error",
                                           steady ? "steady-state" : "scaled-state (late-time)",
                                           fmt::join(st.monitored, ", ")));
    CsvWriter csv(steady_csv_columns(st), provenance);
    csv.add_row(steady_csv_row(st, names, rows));
    csv.write(dir / (steady ? steady_file : scaled_file));
}

RunSummary summarize_run(const fs::path& dir, const RunSpec& spec, bool steady, const MomentsFiles& files,
                         const RunProvenance& provenance) {
    const MomentsTable& table = files.table();
    const std::vector<std::string> names = table.names();
    const std::vector<std::vector<double>>& all_rows = files.combined();
    const auto cpp =
        static_cast<std::size_t>(std::find(names.begin(), names.end(), "coll_per_particle") - names.begin());
    // A cooling box holds a scaled homogeneous state only while it is uniform: the window ends
    // before the first row whose density fluctuations a uniform gas does not make.
    const std::optional<NonUniformity> clusters = steady ? std::nullopt : non_uniform_row(files, spec.replicas);
    const std::vector<std::vector<double>> rows(all_rows.begin(),
                                                all_rows.begin() + static_cast<std::ptrdiff_t>(
                                                                       clusters ? clusters->row : all_rows.size()));
    const SteadyResult st = steady_summary(names, rows, steady, spec.replicas);
    const char* file = steady ? steady_file : scaled_file;
    write_summary_csv(dir, steady, st, names, table.units(), rows, provenance.csv);
    if (steady && files.has_profiles() && files.profile_blocks().size() == rows.size())
        write_steady_profiles(dir, st, files, provenance);
    const std::string path = (dir / file).string();
    const auto averages = [&] {
        std::vector<std::string> parts;
        for (const SteadyValue& v : st.values)
            if (std::find(st.monitored.begin(), st.monitored.end(), v.name) != st.monitored.end())
                parts.push_back(fmt::format("{} = {:.5g} +- {:.2g}", v.name, v.mean, v.err));
        return fmt::format("{}", fmt::join(parts, ", "));
    };
    RunSummary s;
    if (steady) {
        s.note = st.reached ? fmt::format("; steady from {:.4g} collisions per particle ({} rows averaged): {}",
                                          rows[st.first_row][cpp], st.rows, path)
                            : fmt::format("; steady NOT reached (a drift of {} resolved{}); {} holds the second "
                                          "half's averages",
                                          fmt::join(st.monitored, ", "), drift_text(st), path);
        return s;
    }
    // Why a cooling run has no scaled state, when it has none whatever its rows say.
    std::string none;
    if (!cools(spec))
        none = "elastic: equilibrium (the gas does not cool)";
    else if (speed_dependent(spec))
        // Its collisions grow more elastic as the gas cools, so theta and the cumulants drift for ever.
        none = "the restitution depends on the impact speed (the collisions grow more elastic as the gas cools)";
    else if (clusters && !st.reached)
        none = fmt::format("the box is not homogeneous from {:.4g} collisions per particle on: clusters (S = {:.3g} "
                           "at the smallest k, which a uniform gas stays below {:.3g})",
                           all_rows[clusters->row][cpp], clusters->S, clusters->bound);
    const std::string until =
        clusters ? fmt::format(", until the box stops being homogeneous at {:.4g}", all_rows[clusters->row][cpp])
                 : std::string();
    if (!none.empty()) {
        s.note = fmt::format("; no scaled state: {}; {} holds the second half's averages", none, path);
        const std::vector<double>& last = all_rows.back();
        std::vector<std::string> parts;
        for (const std::string& m : st.monitored)
            if (const auto j = static_cast<std::size_t>(std::find(names.begin(), names.end(), m) - names.begin());
                j < names.size())
                parts.push_back(fmt::format("{} = {:.5g}", m, last[j]));
        s.headline = !cools(spec) ? fmt::format("roughgas run: no scaled state: {}; {}\n", none, averages())
                                  : fmt::format("roughgas run: no scaled state: {}; the last row ({:.4g} collisions "
                                                "per particle): {}\n",
                                                none, last[cpp], fmt::join(parts, ", "));
        return s;
    }
    s.note = st.reached ? fmt::format("; scaled state from {:.4g} collisions per particle ({} rows averaged{}): {}",
                                      rows[st.first_row][cpp], st.rows, until, path)
                        : fmt::format("; scaled state NOT reached (a drift of {} resolved{}); {} holds the second "
                                      "half's averages",
                                      fmt::join(st.monitored, ", "), drift_text(st), path);
    // The headline numbers of the scaled state, last on stderr.
    s.headline = fmt::format("roughgas run: scaled state{}: {}\n",
                             st.reached ? fmt::format(" from {:.4g} collisions per particle{}", rows[st.first_row][cpp],
                                                      until)
                                        : std::string(" NOT reached; the second half's averages"),
                             averages());
    return s;
}

} // namespace roughgas::cli
