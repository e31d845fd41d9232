#include "run/summary.hpp"

#include "run/output_files.hpp"

#include <fmt/format.h>

#include <algorithm>
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
    const std::vector<std::vector<double>>& rows = files.combined();
    const SteadyResult st = steady_summary(names, rows, steady);
    const char* file = steady ? steady_file : scaled_file;
    write_summary_csv(dir, steady, st, names, table.units(), rows, provenance.csv);
    if (steady && files.has_profiles() && files.profile_blocks().size() == rows.size())
        write_steady_profiles(dir, st, files, provenance);
    const auto cpp = std::find(names.begin(), names.end(), "coll_per_particle") - names.begin();
    const char* what = steady ? "steady" : "scaled state";
    // With restitution that depends on the impact speed, a cooling gas has no scaled state: its
    // collisions grow more elastic as it cools, so theta and the cumulants drift for ever.
    const bool speed_dependent = std::any_of(spec.pairs.begin(), spec.pairs.end(), [](const PairRestitution& p) {
        return std::holds_alternative<ViscoelasticRestitution>(p) || std::holds_alternative<BrilliantovRestitution>(p);
    });
    const bool no_scaled_state = !steady && speed_dependent;
    const std::string not_reached =
        no_scaled_state ? std::string(" NOT reached: none exists for restitution that depends on the impact "
                                      "speed (the collisions grow more elastic as the gas cools)")
                        : std::string(" NOT reached");
    // Such a run's window is where the drift fell below the noise, not where it ended.
    const std::string caveat = no_scaled_state ? " (the restitution depends on the impact speed: no true "
                                                 "scaled state exists; the drift fell below the noise here)"
                                               : "";
    RunSummary s;
    s.note = st.reached ? fmt::format("; {} from {:.4g} collisions per particle ({} rows averaged){}: {}", what,
                                      rows[st.first_row][static_cast<std::size_t>(cpp)], st.rows, caveat,
                                      (dir / file).string())
                        : fmt::format("; {}{} (a drift of {} resolved); {} holds the second half's averages", what,
                                      not_reached, fmt::join(st.monitored, ", "), (dir / file).string());
    if (!steady) { // the headline numbers of the scaled state, last on stderr
        std::vector<std::string> parts;
        for (const SteadyValue& v : st.values)
            if (std::find(st.monitored.begin(), st.monitored.end(), v.name) != st.monitored.end())
                parts.push_back(fmt::format("{} = {:.5g} +- {:.2g}", v.name, v.mean, v.err));
        s.headline = fmt::format(
            "roughgas run: scaled state{}: {}\n",
            st.reached ? fmt::format(" from {:.4g} collisions per particle{}",
                                     rows[st.first_row][static_cast<std::size_t>(cpp)], caveat)
                       : not_reached + "; the second half's averages",
            fmt::join(parts, ", "));
    }
    return s;
}

} // namespace roughgas::cli
