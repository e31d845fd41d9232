#include "sweep/sweep_table.hpp"

#include "roughgas/io/case_file.hpp"
#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/steady_csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <stdexcept>

namespace roughgas::cli {

std::size_t write_sweep_csv(const std::filesystem::path& dir, const SweepOptions& o, const SweepPoints& points,
                            const std::vector<PointResult>& results) {
    std::vector<std::string> columns = {points.key};
    const std::vector<std::string> steady_cols = steady_csv_columns(results[0].steady);
    columns.insert(columns.end(), steady_cols.begin(), steady_cols.end());
    CsvProvenance prov;
    prov.case_file = o.case_file;
    prov.overrides = o.sets;
    prov.seed = points.cases[0].run.seed;
    prov.resolved_case = emit_case(points.cases[0]);
    prov.notes = {
        fmt::format("sweep of {} from {} to {} ({} points); one row per point: the {} state, drift criterion "
                    "on {}, batch means (io/steady_csv.hpp); each point's rows in point_K/moments.csv, its "
                    "summary in point_K/{}",
                    points.key, points.from, points.to, points.count, driven(points.cases[0]) ? "steady" : "scaled",
                    fmt::join(results[0].steady.monitored, ", "),
                    driven(points.cases[0]) ? "steady.csv" : "scaled.csv"),
        unit_system_note(points.cases[0])};
    // The swept key's unit (its schema entry), then the summary's.
    const KeySpec* key_spec = find_key_of(points.key);
    prov.units = {key_spec && !key_spec->unit.empty() ? key_spec->unit : "-"};
    for (const std::string& u : steady_csv_units(results[0].steady, results[0].names, results[0].units))
        prov.units.push_back(u);
    CsvWriter csv(columns, prov);
    for (std::size_t k = 0; k < results.size(); ++k) {
        if (steady_csv_columns(results[k].steady) != steady_cols)
            throw std::runtime_error("roughgas sweep: the points have different columns (a sweep changes one "
                                     "scalar key only)");
        std::vector<double> row = {points.values[k]};
        const std::vector<double> st = steady_csv_row(results[k].steady, results[k].names, results[k].rows);
        row.insert(row.end(), st.begin(), st.end());
        csv.add_row(row);
    }
    csv.write(dir / sweep_file);
    return columns.size();
}

void print_sweep_table(const SweepPoints& points, const std::vector<PointResult>& results) {
    std::vector<std::string> headline;
    // Uniform shear: its rheology; otherwise (cooling, wall-driven boxes) the monitored columns.
    const bool shear = points.cases[0].run.kind == RunKind::shear;
    std::vector<std::string> wanted = {"a_star", "eta_star", "theta", "N1_star"};
    if (!shear) { // the species' temperature ratios first, then theta and the cumulants
        wanted = results[0].steady.monitored;
        std::stable_partition(wanted.begin(), wanted.end(),
                              [](const std::string& c) { return c.find('/') != std::string::npos; });
    }
    for (const std::string& c : wanted)
        for (const SteadyValue& v : results[0].steady.values)
            if (v.name == c && headline.size() < 6)
                headline.push_back(c);
    std::string table = fmt::format("roughgas sweep: {:>12} {:>7}", points.key, "from");
    for (const std::string& h : headline)
        table += fmt::format(" {:>22}", h);
    table += "\n";
    for (std::size_t k = 0; k < results.size(); ++k) {
        const SteadyResult& st = results[k].steady;
        const auto cpp = std::find(results[k].names.begin(), results[k].names.end(), "coll_per_particle") -
                         results[k].names.begin();
        table += fmt::format("roughgas sweep: {:>12.6g} {:>7}", points.values[k],
                             st.reached
                                 ? fmt::format("{:.3g}", results[k].rows[st.first_row][static_cast<std::size_t>(cpp)])
                                 : std::string("none"));
        for (const std::string& h : headline)
            for (const SteadyValue& v : st.values)
                if (v.name == h)
                    table += fmt::format(" {:>22}", fmt::format("{:.5g} +- {:.2g}", v.mean, v.err));
        table += "\n";
    }
    std::cerr << table;
}

} // namespace roughgas::cli
