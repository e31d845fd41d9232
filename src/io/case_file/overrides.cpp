// `--set KEY=VALUE` written into the parsed TOML (overrides.hpp).
#include "overrides.hpp"

#include "roughgas/io/case_schema.hpp"
#include "toml_access.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string_view>

namespace roughgas::case_file {
namespace {

std::string trim(std::string_view s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string_view::npos)
        return {};
    const auto e = s.find_last_not_of(" \t");
    return std::string(s.substr(b, e - b + 1));
}

// VALUE as TOML; a bare word (or anything for a string key) is a string, so that
// collision.model=brilliantov needs no shell-escaped quotes.
toml::table parse_override_value(const std::string& value, const KeySpec* spec) {
    toml::table wrapped;
    try {
        const std::string text = "v = " + value;
        wrapped = toml::parse(std::string_view(text), std::string_view("--set"));
    } catch (const toml::parse_error&) {
        wrapped = toml::table{};
    }
    const toml::node* v = wrapped.get("v");
    const bool wants_string = spec != nullptr && spec->type == KeyType::string;
    if (wrapped.size() != 1 || v == nullptr || (wants_string && !v->is_string())) {
        return toml::table{{"v", value}};
    }
    return wrapped;
}

// Walks to the table that holds the last segment, creating tables (and at most one new
// [[array]] element) on the way. Returns nullptr after reporting a problem.
toml::table* override_parent(toml::table& root, const std::vector<std::string>& segs, const std::string& arg,
                             Diagnostics& d) {
    const std::string& key = arg.substr(0, arg.find('='));
    toml::table* t = &root;
    for (std::size_t i = 0; i + 1 < segs.size(); ++i) {
        const std::string& seg = segs[i];
        const TableSpec* ts = t == &root ? find_table(seg) : nullptr;
        toml::node* n = t->get(seg);
        if (n != nullptr ? n->is_array() : (ts != nullptr && ts->array)) {
            if (i + 2 >= segs.size() || !is_index(segs[i + 1])) {
                d.add(key, fmt::format("--set {}: [[{}]] is an array of tables: address one as {}.N.{} "
                                       "(N = 0 for the first)",
                                       arg, seg, seg, segs.back()));
                return nullptr;
            }
            if (n == nullptr)
                n = &t->insert_or_assign(seg, toml::array{}).first->second;
            toml::array& a = *n->as_array();
            const std::size_t index = std::stoul(segs[i + 1]);
            if (index > a.size()) {
                d.add(key, fmt::format("--set {}: there are {} [[{}]] tables, so the index must be <= {} "
                                       "({} adds one)",
                                       arg, a.size(), seg, a.size(), a.size()));
                return nullptr;
            }
            if (index == a.size())
                a.push_back(toml::table{});
            t = a[index].as_table();
            ++i;
        } else {
            if (n == nullptr)
                n = &t->insert_or_assign(seg, toml::table{}).first->second;
            t = n->as_table();
        }
        if (t == nullptr || is_index(seg)) {
            d.add(key, fmt::format("--set {}: {} is not a table", arg, seg));
            return nullptr;
        }
    }
    return t;
}

} // namespace

std::vector<std::string> split_path(const std::string& key) {
    std::vector<std::string> segs;
    std::size_t start = 0;
    while (true) {
        const std::size_t dot = key.find('.', start);
        segs.push_back(key.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
        if (dot == std::string::npos)
            return segs;
        start = dot + 1;
    }
}

std::string schema_path(const std::vector<std::string>& segments) {
    std::string p;
    for (const std::string& s : segments) {
        if (!is_index(s))
            p += (p.empty() ? "" : ".") + s;
    }
    return p;
}

void apply_override(toml::table& root, const std::string& arg, Diagnostics& d) {
    const std::size_t eq = arg.find('=');
    const std::string key = trim(arg.substr(0, eq));
    if (eq == std::string::npos || key.empty()) {
        d.add(key, fmt::format("--set {}: expected KEY=VALUE, e.g. collision.alpha=0.9", arg));
        return;
    }
    const std::vector<std::string> segs = split_path(key);
    const bool empty_segment =
        std::any_of(segs.begin(), segs.end(), [](const std::string& s) { return s.empty(); });
    if (segs.size() < 2 || empty_segment || is_index(segs.back())) {
        d.add(key, fmt::format("--set {}: KEY must be a dotted path to a key, e.g. run.particles or "
                               "species.0.radius",
                               arg));
        return;
    }
    toml::table* parent = override_parent(root, segs, arg, d);
    if (parent == nullptr)
        return;
    toml::table wrapped = parse_override_value(trim(arg.substr(eq + 1)), find_key(schema_path(segs)));
    parent->insert_or_assign(segs.back(), std::move(*wrapped.get("v")));
    d.mark_override(key);
}

void switch_clock(toml::table& root, const std::vector<std::string>& overrides) {
    static constexpr std::array<std::string_view, 3> collisions{"end", "output_every", "histogram_every"};
    static constexpr std::array<std::string_view, 3> time{"end_time", "output_every_time", "histogram_every_time"};
    bool set_end = false, set_end_time = false;
    for (const std::string& arg : overrides) {
        const std::string key = trim(arg.substr(0, arg.find('=')));
        set_end = set_end || key == "run.end";
        set_end_time = set_end_time || key == "run.end_time";
    }
    toml::table* run = root["run"].as_table();
    if (set_end == set_end_time || run == nullptr)
        return; // neither end set, or both: the checks of [run] decide
    // The other clock's keys as the file has them; those set with --set stay (and are refused).
    for (std::string_view k : set_end_time ? collisions : time) {
        const std::string key = "run." + std::string(k);
        const bool overridden = std::any_of(overrides.begin(), overrides.end(), [&](const std::string& arg) {
            return trim(arg.substr(0, arg.find('='))) == key;
        });
        if (!overridden)
            run->erase(k);
    }
}

} // namespace roughgas::case_file
