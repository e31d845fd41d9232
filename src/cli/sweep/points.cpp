#include "sweep/points.hpp"

#include "run/setup.hpp"

#include "roughgas/io/case_file.hpp"
#include "roughgas/io/input_error.hpp"

#include <fmt/format.h>

#include <charconv>

namespace roughgas::cli {
namespace {

// KEY=FROM:TO:COUNT
SweepPoints parse_param(const SweepOptions& o) {
    const auto bad = [&](const std::string& why) {
        return InputError(o.case_file, "--param",
                          "--param " + o.param + ": " + why +
                              " (expected KEY=FROM:TO:COUNT, e.g. collision.alpha=0.5:0.9:5)");
    };
    const std::size_t eq = o.param.find('=');
    const std::size_t c1 = o.param.find(':', eq == std::string::npos ? 0 : eq);
    const std::size_t c2 = c1 == std::string::npos ? c1 : o.param.find(':', c1 + 1);
    if (eq == std::string::npos || eq == 0 || c2 == std::string::npos) {
        throw bad("malformed");
    }
    SweepPoints s;
    s.key = o.param.substr(0, eq);
    s.from = o.param.substr(eq + 1, c1 - eq - 1);
    s.to = o.param.substr(c1 + 1, c2 - c1 - 1);
    const std::string count = o.param.substr(c2 + 1);
    const auto [ptr, ec] = std::from_chars(count.data(), count.data() + count.size(), s.count);
    if (ec != std::errc() || ptr != count.data() + count.size() || s.count < 1) {
        throw bad("COUNT must be an integer >= 1");
    }
    return s;
}

double parse_number(const SweepOptions& o, const std::string& text) {
    double x = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    if (ec != std::errc() || ptr != text.data() + text.size())
        throw InputError(o.case_file, "--param",
                         "--param " + o.param + ": FROM and TO must be numbers (expected KEY=FROM:TO:COUNT)");
    return x;
}

} // namespace

SweepPoints plan_points(const SweepOptions& o) {
    SweepPoints s = parse_param(o);
    const double from = parse_number(o, s.from), to = parse_number(o, s.to);
    for (long k = 0; k < s.count; ++k) {
        // Rounded to 15 significant digits: the decimal the user means (0.8, not the 0.7999999999999999
        // the arithmetic gives), which the CSVs and messages then show as such.
        const double x = std::stod(fmt::format(
            "{:.15g}", s.count == 1 ? from
                                    : from + (to - from) * static_cast<double>(k) / static_cast<double>(s.count - 1)));
        std::vector<std::string> sets = o.sets;
        sets.push_back(fmt::format("{}={}", s.key, x));
        try {
            s.cases.push_back(load_case(o.case_file, sets, CaseUse::run));
        } catch (const InputError& e) {
            // The swept key's value comes from --param, not from a --set of the user's: say which point.
            std::vector<InputIssue> issues = e.issues();
            const std::string suffix = " (set with --set)";
            for (InputIssue& i : issues)
                if (i.key == s.key && i.message.ends_with(suffix))
                    i.message = i.message.substr(0, i.message.size() - suffix.size()) +
                                fmt::format(" (point {} of --param {})", k + 1, o.param);
            throw InputError(std::move(issues));
        }
        if (s.cases.back().fields)
            throw InputError(o.case_file, "fields",
                             "[fields] in a sweep: a sweep writes each point's moments.csv only (run a point with "
                             "roughgas run CASE --set KEY=VALUE for its fields)");
        s.values.push_back(x);
        s.sets.push_back(sets);
    }
    for (const CaseConfig& c : s.cases) // initial.from's files checked before any work
        s.specs.push_back(plan_case(c, o.case_file).spec);
    return s;
}

} // namespace roughgas::cli
