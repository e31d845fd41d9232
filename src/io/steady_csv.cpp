#include "roughgas/io/steady_csv.hpp"

#include <algorithm>

namespace roughgas {
namespace {

// A theory column is a function of the row's t (*_theory) or a constant (*_sonine), not a
// measurement: its window mean has no statistical error, so it gets no X_err column.
bool has_error(const std::string& name) {
    return name.find("_theory") == std::string::npos && !name.ends_with("_sonine");
}

} // namespace

std::vector<std::string> steady_csv_columns(const SteadyResult& r) {
    std::vector<std::string> c = {"steady", "steady_from", "steady_rows"};
    for (const SteadyValue& v : r.values) {
        c.push_back(v.name);
        if (has_error(v.name))
            c.push_back(v.name + "_err");
    }
    return c;
}

std::vector<std::string> steady_csv_units(const SteadyResult& r, const std::vector<std::string>& names,
                                          const std::vector<std::string>& units) {
    std::vector<std::string> u = {"-", "-", "-"};
    for (const SteadyValue& v : r.values) {
        const auto it = std::find(names.begin(), names.end(), v.name);
        const std::string unit =
            it != names.end() && static_cast<std::size_t>(it - names.begin()) < units.size()
                ? units[static_cast<std::size_t>(it - names.begin())]
                : "-";
        u.push_back(unit);
        if (has_error(v.name))
            u.push_back(unit);
    }
    return u;
}

std::vector<double> steady_csv_row(const SteadyResult& r, const std::vector<std::string>& names,
                                   const std::vector<std::vector<double>>& rows) {
    const std::size_t cpp =
        static_cast<std::size_t>(std::find(names.begin(), names.end(), "coll_per_particle") - names.begin());
    const double from = r.first_row < rows.size() && cpp < names.size() ? rows[r.first_row][cpp] : 0.0;
    std::vector<double> out = {r.reached ? 1.0 : 0.0, from, static_cast<double>(r.rows)};
    for (const SteadyValue& v : r.values) {
        out.push_back(v.mean);
        if (has_error(v.name))
            out.push_back(v.err);
    }
    return out;
}

SteadyResult steady_summary(const std::vector<std::string>& names,
                            const std::vector<std::vector<double>>& rows, bool shear, int replicas) {
    SteadyOptions o;
    o.replicas = replicas;
    o.monitored = steady_monitored(names, shear, &rows);
    // A transient at the window's start is what a steady average must not contain: the window's
    // first three rows are tested against its second half too.
    o.head_rows = 3;
    // Each of those rows within its own replicas' error: for the scaled state, whose log-spaced
    // rows are few; a steady state's window has rows enough for the means to show a transient
    // (and its 8 monitored columns x 3 rows against errors from as few as 2 replicas would refuse
    // steady windows by chance).
    o.head_each_row = !shear;
    if (!shear) {
        // The scaled cooling state: often from log-spaced rows (ten per decade of collisions per
        // particle), whose late-time window is a minority of the rows but whose rows, far apart
        // in collisions, are nearly independent samples: a window of 10 rows anywhere.
        o.min_rows = 10;
        o.max_start = 1.0;
        // zeta_star's rows are as noisy as 1/(their spacing): tested through ln T_tr's lines.
        o.decay_rates = {{"zeta_star", "T_tr", "coll_per_particle"}};
    }
    SteadyResult r = find_steady_state(names, rows, o);
    r.monitored = o.monitored;
    return r;
}

} // namespace roughgas
