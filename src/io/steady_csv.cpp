#include "roughgas/io/steady_csv.hpp"

#include <algorithm>

namespace roughgas {

std::vector<std::string> steady_csv_columns(const SteadyResult& r) {
    std::vector<std::string> c = {"steady", "steady_from", "steady_rows"};
    for (const SteadyValue& v : r.values) {
        c.push_back(v.name);
        c.push_back(v.name + "_err");
    }
    return c;
}

std::vector<double> steady_csv_row(const SteadyResult& r, const std::vector<std::string>& names,
                                   const std::vector<std::vector<double>>& rows) {
    const std::size_t cpp =
        static_cast<std::size_t>(std::find(names.begin(), names.end(), "coll_per_particle") - names.begin());
    const double from = r.first_row < rows.size() && cpp < names.size() ? rows[r.first_row][cpp] : 0.0;
    std::vector<double> out = {r.reached ? 1.0 : 0.0, from, static_cast<double>(r.rows)};
    for (const SteadyValue& v : r.values) {
        out.push_back(v.mean);
        out.push_back(v.err);
    }
    return out;
}

SteadyResult steady_summary(const std::vector<std::string>& names,
                            const std::vector<std::vector<double>>& rows, bool shear) {
    SteadyOptions o;
    o.monitored = steady_monitored(names, shear);
    return find_steady_state(names, rows, o);
}

} // namespace roughgas
