// Case files with toml++: parse, apply --set, validate (schema pass, then cross-key pass), build.
#include "roughgas/io/case_file.hpp"
#include "roughgas/io/nearest_word.hpp"

#include "roughgas/io/case_schema.hpp"

#include <numbers>

#include "roughgas/dsmc/species.hpp"
#include "roughgas/observables/theory.hpp"
#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

namespace roughgas {
namespace {

// ---------------------------------------------------------------------------------------------
// Messages

// Collects issues so that one pass reports every problem; keys set with --set say so, because
// the case file would not show the offending value.
class Diagnostics {
  public:
    explicit Diagnostics(std::string file) : file_(std::move(file)) {}

    void mark_override(const std::string& key) { overridden_.push_back(key); }

    // `key`: dotted display path; `node`: where to point (nullptr: no position).
    void add(const std::string& key, std::string message, const toml::node* node = nullptr) {
        std::optional<SourcePosition> where;
        if (overridden(key)) {
            message += " (set with --set)";
        } else if (node != nullptr && node->source().begin) {
            const toml::source_position p = node->source().begin;
            where = SourcePosition{static_cast<int>(p.line), static_cast<int>(p.column)};
        }
        issues_.push_back({file_, key, std::move(message), where});
    }

    // In file order; issues without a position (missing keys, --set) last.
    void throw_if_any() {
        if (issues_.empty())
            return;
        std::stable_sort(issues_.begin(), issues_.end(), [](const InputIssue& a, const InputIssue& b) {
            const auto rank = [](const InputIssue& i) {
                return i.where ? std::pair(i.where->line, i.where->column)
                               : std::pair(std::numeric_limits<int>::max(), 0);
            };
            return rank(a) < rank(b);
        });
        throw InputError(std::move(issues_));
    }

  private:
    // `key`, a key below it, or the table or array it is in ("domain.cells[0]" of --set
    // domain.cells=[...]) was given with --set.
    bool overridden(const std::string& key) const {
        return std::any_of(overridden_.begin(), overridden_.end(), [&](const std::string& o) {
            return o == key || o.rfind(key + ".", 0) == 0 || key.rfind(o + ".", 0) == 0 || key.rfind(o + "[", 0) == 0;
        });
    }

    std::string file_;
    std::vector<std::string> overridden_;
    std::vector<InputIssue> issues_;
};

std::string quote(std::string_view s);

std::string value_text(const toml::node& n) {
    if (const auto* f = n.as_floating_point()) {
        return fmt::format("{}", f->get()); // toml++ would print 1e10 as 10000000000.0
    }
    if (const auto* str = n.as_string()) {
        return quote(str->get()); // as the "allowed" lists print them
    }
    std::ostringstream os;
    n.visit([&](const auto& v) { os << v; });
    return os.str();
}

std::string unit_suffix(const KeySpec& s) {
    return s.unit.empty() ? "" : " (" + s.unit + ")";
}

std::string type_phrase(KeyType t) {
    switch (t) {
    case KeyType::boolean:
        return "true or false";
    case KeyType::integer:
        return "an integer";
    case KeyType::real:
        return "a real number";
    case KeyType::string:
        return "a string";
    case KeyType::string_pair:
        return "an array of two strings";
    case KeyType::real3:
        return "an array of three real numbers";
    case KeyType::integer3:
        return "an array of three integers";
    case KeyType::string3:
        return "an array of three strings";
    case KeyType::string_list:
        return "an array of distinct strings";
    }
    return "?";
}

// "a real number > 0 (Pa)", "one of \"eq24\", \"eq25\"": what a key accepts, for messages.
std::string expectation(const KeySpec& s) {
    if (!s.choices.empty()) {
        return s.allowed();
    }
    const std::string allowed = s.allowed();
    return type_phrase(s.type) + (allowed.empty() ? "" : " " + allowed) + unit_suffix(s);
}

std::vector<std::string> key_names(std::string_view table) {
    std::vector<std::string> names;
    for (const KeySpec& k : case_schema()) {
        if (k.table() == table)
            names.emplace_back(k.name());
    }
    return names;
}

std::string table_header(const TableSpec& t) {
    return t.array ? "[[" + t.name + "]]" : "[" + t.name + "]";
}

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v)
        s += (s.empty() ? "" : ", ") + x;
    return s;
}

// A key of this name in another table: the user put a right key in the wrong place.
std::optional<std::string> misplaced(std::string_view name, std::string_view table) {
    for (const KeySpec& k : case_schema()) {
        if (k.name() == name && k.table() != table) {
            return std::string(k.name()) + " in " + table_header(*find_table(k.table()));
        }
    }
    return std::nullopt;
}

// ---------------------------------------------------------------------------------------------
// Typed access

std::optional<double> as_real(const toml::node& n) {
    if (const auto* f = n.as_floating_point())
        return f->get();
    if (const auto* i = n.as_integer())
        return static_cast<double>(i->get());
    return std::nullopt;
}

// Integers may be written as integral floats (particles = 1e5).
std::optional<std::int64_t> as_integer(const toml::node& n) {
    if (const auto* i = n.as_integer())
        return i->get();
    if (const auto* f = n.as_floating_point()) {
        const double x = f->get();
        if (std::isfinite(x) && x == std::floor(x) && std::abs(x) < 9.0e18)
            return static_cast<std::int64_t>(x);
    }
    return std::nullopt;
}

bool is_string_pair(const toml::node& n) {
    const toml::array* a = n.as_array();
    return a != nullptr && a->size() == 2 && (*a)[0].is_string() && (*a)[1].is_string();
}

bool is_index(std::string_view s) {
    return !s.empty() && s.size() < 10 &&
           std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The node at a display path ("species.1.name"), for message positions.
const toml::node* locate(const toml::table& root, std::string_view path) {
    const toml::node* n = &root;
    std::size_t start = 0;
    while (n != nullptr && start <= path.size()) {
        const std::size_t dot = std::min(path.find('.', start), path.size());
        const std::string seg(path.substr(start, dot - start));
        if (const toml::table* t = n->as_table()) {
            n = t->get(seg);
        } else if (const toml::array* a = n->as_array(); a != nullptr && is_index(seg)) {
            n = a->get(std::stoul(seg));
        } else {
            return nullptr;
        }
        start = dot + 1;
    }
    return n;
}

// Reads keys of one validated table, with the schema's defaults for missing ones.
class Reader {
  public:
    Reader(const toml::table* t, std::string schema_table) : t_(t), table_(std::move(schema_table)) {}

    bool has(std::string_view k) const { return node(k) != nullptr; }
    double real(std::string_view k) const {
        const toml::node* n = node(k);
        return n ? *as_real(*n) : std::get<double>(spec(k).default_value);
    }
    std::optional<double> opt_real(std::string_view k) const {
        const toml::node* n = node(k);
        return n ? as_real(*n) : std::nullopt;
    }
    std::int64_t integer(std::string_view k) const {
        const toml::node* n = node(k);
        return n ? *as_integer(*n) : std::get<std::int64_t>(spec(k).default_value);
    }
    bool boolean(std::string_view k) const {
        const toml::node* n = node(k);
        return n ? n->as_boolean()->get() : std::get<bool>(spec(k).default_value);
    }
    std::string string(std::string_view k) const {
        const toml::node* n = node(k);
        return n ? n->as_string()->get() : std::get<std::string>(spec(k).default_value);
    }
    std::array<double, 3> real3(std::string_view k) const {
        std::array<double, 3> x{};
        if (const toml::array* a = node(k) ? node(k)->as_array() : nullptr)
            for (std::size_t i = 0; i < 3; ++i)
                x[i] = *as_real(*a->get(i));
        return x;
    }
    std::array<std::int64_t, 3> integer3(std::string_view k) const {
        std::array<std::int64_t, 3> x{};
        if (const toml::array* a = node(k) ? node(k)->as_array() : nullptr)
            for (std::size_t i = 0; i < 3; ++i)
                x[i] = *as_integer(*a->get(i));
        return x;
    }
    std::array<std::string, 3> string3(std::string_view k) const {
        const toml::array* a = node(k) ? node(k)->as_array() : nullptr;
        if (a == nullptr) {
            const std::string d = std::get<std::string>(spec(k).default_value);
            return {d, d, d};
        }
        return {a->get(0)->as_string()->get(), a->get(1)->as_string()->get(), a->get(2)->as_string()->get()};
    }
    std::vector<std::string> strings(std::string_view k) const {
        std::vector<std::string> list;
        if (const toml::array* a = node(k) ? node(k)->as_array() : nullptr) {
            for (const toml::node& e : *a)
                list.push_back(e.as_string()->get());
            return list;
        }
        return spec(k).default_list();
    }
    template <class E, std::size_t N>
    E choice(std::string_view k, const std::array<std::string_view, N>& names) const {
        const std::string s = string(k);
        return static_cast<E>(std::find(names.begin(), names.end(), s) - names.begin());
    }

  private:
    const toml::node* node(std::string_view k) const { return t_ ? t_->get(k) : nullptr; }
    const KeySpec& spec(std::string_view k) const { return *find_key(table_ + "." + std::string(k)); }
    const toml::table* t_;
    std::string table_;
};

// ---------------------------------------------------------------------------------------------
// --set

std::string trim(std::string_view s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string_view::npos)
        return {};
    const auto e = s.find_last_not_of(" \t");
    return std::string(s.substr(b, e - b + 1));
}

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

std::string schema_path(const std::vector<std::string>& segs) {
    std::string p;
    for (const std::string& s : segs) {
        if (!is_index(s))
            p += (p.empty() ? "" : ".") + s;
    }
    return p;
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

// ---------------------------------------------------------------------------------------------
// Pass 1: structure, names, types and ranges against the schema

class SchemaCheck {
  public:
    explicit SchemaCheck(Diagnostics& d) : d_(d) {}

    void root(const toml::table& root) {
        for (auto&& [k, node] : root) {
            top_level(std::string(k.str()), node);
        }
        for (const std::string name : {"run", "collision"}) {
            if (!root.contains(name)) {
                missing_keys(nullptr, name, name); // each required key of the absent table
            }
        }
        if (!root.contains("species")) {
            d_.add("species", "species: at least one [[species]] table is required");
        }
    }

  private:
    void top_level(const std::string& name, const toml::node& node) {
        const TableSpec* ts = find_table(name);
        if (ts == nullptr) {
            unknown_top_level(name, node);
        } else if (ts->array) {
            const toml::array* a = node.as_array();
            if (a == nullptr || a->empty() || !a->is_array_of_tables()) {
                d_.add(name, fmt::format("{}: must be one or more tables written [[{}]]", name, name), &node);
                return;
            }
            for (std::size_t i = 0; i < a->size(); ++i) {
                table(*(*a)[i].as_table(), name, fmt::format("{}.{}", name, i));
            }
        } else if (const toml::table* t = node.as_table()) {
            table(*t, name, name);
        } else {
            d_.add(name, fmt::format("{}: must be a table written [{}]", name, name), &node);
        }
    }

    void unknown_top_level(const std::string& name, const toml::node& node) {
        std::vector<std::string> tables;
        for (const TableSpec& t : case_tables())
            tables.push_back(t.name);
        std::string hint;
        if (auto m = misplaced(name, "")) {
            hint = "did you mean " + *m + "?";
        } else if (auto s = nearest(name, tables)) {
            hint = "did you mean " + table_header(*find_table(*s)) + "?";
        } else {
            std::vector<std::string> headers;
            for (const TableSpec& t : case_tables())
                headers.push_back(table_header(t));
            hint = "the tables are " + join(headers);
        }
        d_.add(name, fmt::format("{}: unknown {} ({})", name, node.is_table() ? "table" : "key", hint),
               &node);
    }

    void table(const toml::table& t, const std::string& schema_table, const std::string& prefix) {
        for (auto&& [k, node] : t) {
            const std::string name(k.str());
            const KeySpec* spec = find_key(schema_table + "." + name);
            if (spec == nullptr) {
                unknown_key(name, schema_table, prefix, node);
            } else {
                value(*spec, node, prefix + "." + name);
            }
        }
        missing_keys(&t, schema_table, prefix);
    }

    void missing_keys(const toml::table* t, const std::string& schema_table, const std::string& prefix) {
        for (const KeySpec& s : case_schema()) {
            if (s.table() == schema_table && s.need == Need::required &&
                (t == nullptr || !t->contains(s.name()))) {
                const std::string key = prefix + "." + std::string(s.name());
                d_.add(key, fmt::format("{}: required key is missing (must be {})", key, expectation(s)), t);
            }
        }
    }

    void unknown_key(const std::string& name, const std::string& schema_table, const std::string& prefix,
                     const toml::node& node) {
        const std::string key = prefix + "." + name;
        std::string hint;
        if (auto s = nearest(name, key_names(schema_table))) {
            hint = "did you mean " + prefix + "." + *s + "?";
        } else if (auto m = misplaced(name, schema_table)) {
            hint = "did you mean " + *m + "?";
        } else {
            hint = table_header(*find_table(schema_table)) + " allows " + join(key_names(schema_table));
        }
        d_.add(key, fmt::format("{}: unknown key ({})", key, hint), &node);
    }

    void value(const KeySpec& s, const toml::node& n, const std::string& key) {
        const std::string shown = key + " = " + value_text(n);
        switch (s.type) {
        case KeyType::real:
        case KeyType::integer: {
            const std::optional<double> x =
                s.type == KeyType::real ? as_real(n) : [&]() -> std::optional<double> {
                if (auto i = as_integer(n))
                    return static_cast<double>(*i);
                return std::nullopt;
            }();
            if (!x || !std::isfinite(*x)) {
                d_.add(key, fmt::format("{}: must be {}", shown, expectation(s)), &n);
            } else if (!s.allows(*x)) {
                d_.add(key, fmt::format("{}: must be {}{}", shown, s.allowed(), unit_suffix(s)), &n);
            }
            return;
        }
        case KeyType::boolean:
            if (!n.is_boolean())
                d_.add(key, fmt::format("{}: must be true or false", shown), &n);
            return;
        case KeyType::string_pair:
            if (!is_string_pair(n))
                d_.add(key, fmt::format("{}: must be {}", shown, expectation(s)), &n);
            return;
        case KeyType::real3:
        case KeyType::integer3:
        case KeyType::string3: {
            // Three elements, each checked as a key of the element type (bounds, choices).
            const toml::array* a = n.as_array();
            if (a == nullptr || a->size() != 3) {
                d_.add(key, fmt::format("{}: must be {}", shown, type_phrase(s.type)), &n);
                return;
            }
            KeySpec element = s;
            element.type = s.type == KeyType::real3      ? KeyType::real
                           : s.type == KeyType::integer3 ? KeyType::integer
                                                         : KeyType::string;
            for (std::size_t i = 0; i < 3; ++i)
                value(element, *a->get(i), fmt::format("{}[{}]", key, i));
            return;
        }
        case KeyType::string_list: {
            // At least one element, each a string of the choices, none twice.
            const toml::array* a = n.as_array();
            if (a == nullptr || a->empty()) {
                d_.add(key, fmt::format("{}: must be {} ({})", shown, type_phrase(s.type), s.allowed()), &n);
                return;
            }
            KeySpec element = s;
            element.type = KeyType::string;
            for (std::size_t i = 0; i < a->size(); ++i) {
                value(element, *a->get(i), fmt::format("{}[{}]", key, i));
                for (std::size_t j = 0; j < i; ++j)
                    if (a->get(i)->is_string() && a->get(j)->is_string() &&
                        a->get(i)->as_string()->get() == a->get(j)->as_string()->get())
                        d_.add(key, fmt::format("{}: \"{}\" is given twice", shown, a->get(i)->as_string()->get()),
                               &n);
            }
            return;
        }
        case KeyType::string: {
            const auto* str = n.as_string();
            if (str == nullptr) {
                d_.add(
                    key,
                    fmt::format("{}: must be a string{}", shown, s.choices.empty() ? "" : ", " + s.allowed()),
                    &n);
            } else if (!s.allows(str->get())) {
                const auto near = nearest(str->get(), s.choices);
                d_.add(key,
                       fmt::format("{}: must be {}{}", shown, s.allowed(),
                                   near ? " (did you mean \"" + *near + "\"?)" : ""),
                       &n);
            }
            return;
        }
        }
    }

    Diagnostics& d_;
};

// ---------------------------------------------------------------------------------------------
// Pass 2: build the config and check what involves several keys

class Builder {
  public:
    Builder(const toml::table& root, CaseUse use, Diagnostics& d) : root_(root), use_(use), d_(d) {}

    CaseConfig build() {
        CaseConfig c;
        c.run = run(Reader(root_["run"].as_table(), "run"));
        if (const toml::array* a = root_["species"].as_array()) {
            for (const toml::node& n : *a)
                c.species.push_back(species(Reader(n.as_table(), "species")));
        }
        const toml::table* coll = root_["collision"].as_table();
        c.collision = collision(Reader(coll, "collision"));
        if (const toml::array* a = root_["pair"].as_array()) {
            for (const toml::node& n : *a)
                c.pairs.push_back(pair(*n.as_table(), coll));
        }
        if (const toml::table* m = root_["material"].as_table())
            c.material = material(Reader(m, "material"));
        c.contact = contact(Reader(root_["contact"].as_table(), "contact"));
        if (const toml::table* s = root_["shear"].as_table(); s != nullptr && s->contains("rate")) {
            const Reader r(s, "shear");
            c.shear = ShearConfig{r.real("rate"), r.real("time_step")};
        }
        if (const toml::table* t = root_["domain"].as_table()) {
            for (const char* k : {"size", "cells"})
                if (!t->contains(k))
                    add(std::string("domain.") + k,
                        fmt::format("[domain] without domain.{}: give {}", k,
                                    std::string_view(k) == "size" ? "the box lengths [L_x, L_y, L_z]"
                                                                  : "the cells per axis [n_x, n_y, n_z]"));
            const Reader r(t, "domain");
            DomainConfig d;
            d.size = r.real3("size");
            d.cells = r.integer3("cells");
            const std::array<std::string, 3> b = r.string3("boundary");
            for (std::size_t i = 0; i < 3; ++i)
                d.boundary[i] = static_cast<Boundary>(
                    std::find(boundary_names.begin(), boundary_names.end(), b[i]) - boundary_names.begin());
            d.gravity = r.real3("gravity");
            if (r.has("profile_axis")) {
                d.profile_axis = static_cast<int>(r.string("profile_axis")[0] - 'x');
            } else if (root_["run"]["kind"].value_or(std::string()) == "shear") {
                d.profile_axis = 1; // the Lees-Edwards gradient
            } else {
                const auto walled = std::find(d.boundary.begin(), d.boundary.end(), Boundary::walls);
                d.profile_axis = walled == d.boundary.end() ? 0 : static_cast<int>(walled - d.boundary.begin());
            }
            d.time_step = r.real("time_step");
            d.allow_coarse = r.boolean("allow_coarse");
            d.partners = r.choice<PartnerSelection>("partners", partner_names);
            c.domain = d;
        }
        for (const WallTable& table : wall_tables())
            if (const toml::table* t = root_[table.name].as_table()) {
                const Reader r(t, table.name);
                WallConfig w;
                w.kind = r.choice<WallKind>("kind", wall_kind_names);
                w.temperature = r.opt_real("temperature");
                w.velocity = r.real3("velocity");
                w.alpha = r.opt_real("alpha");
                w.beta = r.opt_real("beta");
                wall_config(c, table) = w;
            }
        if (const toml::table* t = root_["initial"].as_table()) {
            const Reader r(t, "initial");
            InitialConfig w;
            w.mode = r.choice<Perturbation>("mode", perturbation_names);
            w.amplitude = r.real("amplitude");
            if (r.has("wave"))
                w.wave = r.integer3("wave");
            if (r.has("from"))
                w.from = r.string("from");
            c.initial = w;
        }
        if (const toml::table* t = root_["spectra"].as_table()) {
            const Reader r(t, "spectra");
            SpectraConfig s;
            s.modes = r.integer("modes");
            c.spectra = s;
        }
        if (const toml::table* t = root_["fields"].as_table()) {
            const Reader r(t, "fields");
            FieldsConfig f;
            for (const std::string& q : r.strings("quantities"))
                f.quantities.push_back(static_cast<FieldQuantity>(
                    std::find(field_quantity_names.begin(), field_quantity_names.end(), q) -
                    field_quantity_names.begin()));
            f.every = r.integer("every");
            f.replicas = r.integer("replicas");
            c.fields = f;
        }
        c.restitution = grid(Reader(root_["restitution"].as_table(), "restitution"));
        check(c);
        note_unused(c);
        return c;
    }

  private:
    static RunConfig run(const Reader& r) {
        RunConfig c;
        c.kind = r.choice<RunKind>("kind", run_kind_names);
        c.particles = r.integer("particles");
        c.density = r.real("density");
        c.replicas = r.integer("replicas");
        c.groups = r.integer("groups");
        c.kernel = r.choice<CollisionKernel>("kernel", kernel_names);
        c.seed = static_cast<std::uint64_t>(r.integer("seed"));
        c.end = r.real("end");
        c.output_every = r.real("output_every");
        c.output_spacing = r.choice<OutputSpacing>("output_spacing", output_spacing_names);
        c.histogram_every = r.real("histogram_every");
        c.histogram_spacing = r.choice<OutputSpacing>("histogram_spacing", output_spacing_names);
        c.histogram_bins = r.integer("histogram_bins");
        c.histogram_max = r.real("histogram_max");
        c.save_state = r.boolean("save_state");
        return c;
    }

    SpeciesConfig species(const Reader& r) {
        SpeciesConfig s;
        s.name = r.string("name");
        s.radius = r.real("radius");
        s.density = r.opt_real("density");
        s.mass = mass(r, s);
        s.inertia = r.real("inertia");
        s.fraction = r.real("fraction");
        s.temperature = r.real("temperature");
        s.rotational_temperature = r.real("rotational_temperature");
        return s;
    }

    static CollisionConfig collision(const Reader& r) {
        CollisionConfig c;
        c.model = r.choice<CollisionModel>("model", collision_model_names);
        c.alpha = r.opt_real("alpha");
        c.beta = r.opt_real("beta");
        c.beta0 = r.opt_real("beta0");
        c.friction = r.opt_real("friction");
        c.direct = r.boolean("direct");
        return c;
    }

    // m is given directly or from the density of a uniform sphere: never both, never neither.
    double mass(const Reader& r, const SpeciesConfig& s) {
        if (r.has("mass")) {
            if (s.density)
                add("species.mass", "species.mass: give either mass or density, not both");
            return r.real("mass");
        }
        if (!s.density) {
            add("species.mass", fmt::format("species.mass: required key is missing (must be {}; or give density)",
                                            expectation(*find_key("species.mass"))));
            return 0;
        }
        return 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius * *s.density;
    }

    // A [[pair]] is [collision] with the pair's own keys on top.
    static PairConfig pair(const toml::table& t, const toml::table* coll) {
        toml::table merged = coll ? *coll : toml::table{};
        for (auto&& [k, v] : t) {
            if (k.str() != "species")
                merged.insert_or_assign(k.str(), v);
        }
        PairConfig p;
        const toml::array& names = *t["species"].as_array();
        p.species = {names[0].as_string()->get(), names[1].as_string()->get()};
        p.collision = collision(Reader(&merged, "collision"));
        return p;
    }

    MaterialConfig material(const Reader& r) {
        MaterialConfig m;
        m.young_modulus = r.real("young_modulus");
        m.poisson_ratio = r.real("poisson_ratio");
        m.eta1 = r.opt_real("eta1");
        m.eta2 = r.opt_real("eta2");
        m.friction = r.opt_real("friction");
        m.asperity = r.opt_real("asperity");
        m.dissipation = dissipation(r, m);
        return m;
    }

    // A is given directly or, by Brilliantov et al. (1996) eq. 23, from both viscosities: never both,
    // never neither.
    double dissipation(const Reader& r, const MaterialConfig& m) {
        const KeySpec& a_spec = *find_key("material.dissipation");
        const bool viscous = m.eta1 || m.eta2;
        if (r.has("dissipation")) {
            if (viscous) {
                add("material.dissipation",
                    "material.dissipation: give either dissipation or eta1 and eta2, not both");
            }
            return r.real("dissipation");
        }
        if (!viscous) {
            add("material.dissipation",
                fmt::format("material.dissipation: required key is missing (must be {}; "
                            "or give eta1 and eta2)",
                            expectation(a_spec)),
                "material");
            return 0;
        }
        if (!m.eta1 || !m.eta2) {
            const std::string missing = m.eta1 ? "material.eta2" : "material.eta1";
            add(missing,
                fmt::format("{}: required with {} (A follows from both viscosities, Brilliantov et al. "
                            "1996 eq. 23; must be >= 0 (Pa s))",
                            missing, m.eta1 ? "eta1" : "eta2"),
                "material");
            return 0;
        }
        if (m.poisson_ratio == 0 || 3 * *m.eta2 + 2 * *m.eta1 <= 0) {
            add("material.eta1", "material.eta1, material.eta2: Brilliantov et al. 1996 eq. 23 needs "
                                 "poisson_ratio != 0 and 3 eta2 + 2 eta1 > 0");
            return 0;
        }
        return dissipation_from_viscosities(*m.eta1, *m.eta2, m.young_modulus, m.poisson_ratio);
    }

    static ContactConfig contact(const Reader& r) {
        ContactConfig c;
        c.model.form = r.choice<NormalForm>("form", normal_form_names);
        c.model.end = r.choice<ContactEnd>("end", contact_end_names);
        c.cache = r.boolean("cache");
        c.cache_file = r.string("cache_file");
        const double tol = r.real("tolerance");
        c.tolerance = Tolerance{tol, tol / 100}; // the Hertz-scaled state is O(1)
        return c;
    }

    static RestitutionGridConfig grid(const Reader& r) {
        RestitutionGridConfig g;
        g.g_n_min = r.real("g_n_min");
        g.g_n_max = r.real("g_n_max");
        g.g_n_points = r.integer("g_n_points");
        g.g_t_min = r.real("g_t_min");
        g.g_t_max = r.real("g_t_max");
        g.g_t_points = r.integer("g_t_points");
        g.spacing = r.choice<GridSpacing>("spacing", grid_spacing_names);
        return g;
    }

    void add(const std::string& key, std::string message, std::string_view at = {}) {
        d_.add(key, std::move(message), locate(root_, at.empty() ? std::string_view(key) : at));
    }

    // "x: required for <why> but missing (must be <expectation>)"
    void require(bool present, const std::string& key, const std::string& why, std::string_view at) {
        if (!present) {
            const KeySpec* s = find_key_of(key);
            add(key, fmt::format("{}: required for {} but missing (must be {})", key, why, expectation(*s)),
                at);
        }
    }

    // What a collision model reads of its table (case_schema.cpp's collision keys).
    static bool model_uses(CollisionModel m, std::string_view key) {
        switch (m) {
        case CollisionModel::constant:
            return key == "alpha" || key == "beta";
        case CollisionModel::coulomb:
            return key == "alpha" || key == "beta0" || key == "friction";
        case CollisionModel::viscoelastic:
            return key == "beta" || key == "direct";
        case CollisionModel::brilliantov:
            return key == "direct";
        }
        return true;
    }

    // Keys and tables the run will not read: kept in the case (a --set may switch the model or the
    // run kind), reported as warnings (CaseConfig::unused).
    void note_unused(CaseConfig& c) const {
        const auto table_keys = [&](const toml::table* t, const CollisionConfig& cc, const std::string& prefix) {
            if (t == nullptr)
                return;
            // (direct, a defaulted flag that emit_case always writes, is left out: a resumed run
            // parses the emitted case and must report exactly what the first one did)
            for (const char* k : {"alpha", "beta", "beta0", "friction"})
                if (t->contains(k) && !model_uses(cc.model, k))
                    c.unused.push_back(fmt::format("{}.{} is not used by {}.model = \"{}\"", prefix, k, prefix,
                                                   name(cc.model)));
        };
        table_keys(root_["collision"].as_table(), c.collision, "collision");
        if (const toml::array* a = root_["pair"].as_array())
            for (std::size_t i = 0; i < a->size() && i < c.pairs.size(); ++i)
                table_keys(a->get(i)->as_table(), c.pairs[i].collision, fmt::format("pair.{}", i));
        for (const WallTable& table : wall_tables()) {
            const std::optional<WallConfig>& w = wall_config(c, table);
            const std::string& side = table.name;
            if (!w)
                continue;
            if (!c.domain || !c.domain->has_walls()) {
                c.unused.push_back(fmt::format("[{}] is not used: no axis of domain.boundary has \"walls\"", side));
                continue;
            }
            if (wall_axes(c, table).empty()) {
                c.unused.push_back(
                    table.axis >= 0
                        ? fmt::format("[{}] is not used: axis {} of domain.boundary is not \"walls\"", side,
                                      "xyz"[table.axis])
                        : fmt::format("[{}] is not used: every walled axis has a [{}_x], [{}_y] or [{}_z] of its own",
                                      side, side, side, side));
                continue;
            }
            const toml::table* t = root_[side].as_table();
            for (const char* k : {"alpha", "beta"})
                if (t->contains(k) && w->kind != WallKind::rough)
                    c.unused.push_back(fmt::format("{}.{} is not used by {}.kind = \"{}\"", side, k, side,
                                                   name(w->kind)));
            if (t->contains("temperature") && w->kind != WallKind::diffuse)
                c.unused.push_back(fmt::format("{}.temperature is not used by {}.kind = \"{}\"", side, side,
                                               name(w->kind)));
        }
        if (root_["shear"].as_table() != nullptr && c.run.kind != RunKind::shear)
            c.unused.push_back(fmt::format("[shear] is not used by run.kind = \"{}\"", name(c.run.kind)));
        if (use_ == CaseUse::run && material_users_.empty() && root_["material"].as_table() != nullptr)
            c.unused.push_back("[material] is not used: no species pair has model = \"viscoelastic\" or "
                               "\"brilliantov\"");
    }

    void check(const CaseConfig& c) {
        check_species(c);
        check_collision(c.collision, "collision");
        for (std::size_t i = 0; i < c.pairs.size(); ++i) {
            check_pair(c, i);
            check_collision(c.pairs[i].collision, fmt::format("pair.{}", i));
        }
        check_material(c);
        if (c.run.kind == RunKind::shear) {
            require(c.shear.has_value(), "shear.rate", "run.kind = \"shear\"", "shear");
        }
        if (c.domain)
            check_domain(c);
        if (c.initial && !c.initial->from.empty() && !c.domain)
            add("initial.from", fmt::format("initial.from = \"{}\" without [domain]: a saved state starts a box "
                                            "run (give the box in [domain])",
                                            c.initial->from));
        if (c.initial && !c.initial->from.empty() && c.run.kernel == CollisionKernel::maxwell)
            add("initial.from",
                fmt::format("initial.from = \"{}\" with run.kernel = \"maxwell\": the kernel's rates come from "
                            "the species' temperatures in this case, not from the saved grains' (start a Maxwell "
                            "box from its Maxwellian)",
                            c.initial->from));
        if (c.initial && c.initial->mode != Perturbation::none) {
            if (!c.domain)
                add("initial.mode", fmt::format("initial.mode = \"{}\" without [domain]: a wave needs positions "
                                                "(give the box in [domain])",
                                                name(c.initial->mode)));
            const auto& k = c.initial->wave;
            if (k[0] == 0 && k[1] == 0 && k[2] == 0)
                add("initial.wave", "initial.wave = [0, 0, 0]: a wave needs a wave number other than 0");
        }
        if (c.spectra) {
            if (!c.domain)
                add("spectra", "[spectra] without [domain]: spectra are of a box's fields (give the box in [domain])");
            else if (c.domain->has_walls())
                add("domain.boundary", "[spectra] with walls: the Fourier modes need a periodic box (every "
                                       "domain.boundary \"periodic\")");
            else if (c.run.kind == RunKind::shear)
                add("spectra", "[spectra] with run.kind = \"shear\": the Lees-Edwards box is periodic only in its "
                               "sheared frame, which the spectra do not follow");
        }
        if (c.fields) {
            if (!c.domain)
                add("fields", "[fields] without [domain]: fields are of a box's cells (give the box in [domain])");
            else if (c.fields->replicas > c.run.replicas)
                add("fields.replicas", fmt::format("fields.replicas = {}: more than the run's replicas (must be "
                                                   "<= run.replicas = {})",
                                                   c.fields->replicas, c.run.replicas));
        }
        if (c.run.kernel == CollisionKernel::maxwell)
            check_maxwell_kernel(c);
        else if (c.run.kind == RunKind::cooling && use_ == CaseUse::run && !driven(c) &&
                 !(c.initial && !c.initial->from.empty()))
            check_cooling_reach(c); // from a saved state: its own temperatures (io/run_states.cpp)
        if (c.run.histogram_every > c.run.end) {
            add("run.histogram_every",
                fmt::format("run.histogram_every = {}: after the end of the run (must be <= run.end = {})",
                            c.run.histogram_every, c.run.end));
        }
        check_grid(c.restitution);
    }

    // The shortest mean free path of the gas, 1/(sqrt(2) pi n sigma^2) with the largest diameter
    // sigma = 2 max R: the length the cells must resolve.
    static double mean_free_path(const CaseConfig& c) {
        double R = 0;
        for (const SpeciesConfig& s : c.species)
            R = std::max(R, s.radius);
        return roughgas::mean_free_path(c.run.density, 2 * R);
    }

    // A spatially resolved run: keys the homogeneous engine has and the box has not, and cells
    // that resolve the mean free path.
    void check_domain(const CaseConfig& c) {
        const DomainConfig& d = *c.domain;
        if (c.run.kind == RunKind::shear) // Lees-Edwards along y: x and y periodic
            for (std::size_t a : {0, 1})
                if (d.boundary[a] == Boundary::walls)
                    add("domain.boundary",
                        fmt::format("domain.boundary[{}] = \"walls\" with run.kind = \"shear\": a sheared box has "
                                    "Lees-Edwards boundaries along y and flows along x, both periodic (walls "
                                    "along z only)",
                                    a));
        if (c.run.histogram_every > 0)
            add("run.histogram_every", "run.histogram_every with [domain]: histograms are written for the "
                                       "homogeneous gas only (set it to 0)");
        const double cells = static_cast<double>(d.cells[0]) * static_cast<double>(d.cells[1]) *
                              static_cast<double>(d.cells[2]);
        if (cells > 1e8)
            add("domain.cells", fmt::format("domain.cells = [{}, {}, {}]: {:.3g} cells, at most 1e8", d.cells[0],
                                            d.cells[1], d.cells[2], cells));
        if (d.has_walls()) {
            for (int a = 0; a < 3; ++a)
                for (const bool upper : {false, true})
                    if (d.boundary[static_cast<std::size_t>(a)] == Boundary::walls &&
                        !wall_config(c, wall_table_of(c, a, upper))) {
                        const std::string side = upper ? "wall_upper" : "wall_lower";
                        add(side, fmt::format("domain.boundary has \"walls\" but [{}] is missing: give the wall at "
                                              "{} of each walled axis (kind = \"diffuse\", \"specular\" or "
                                              "\"rough\"), or axis {}'s own [{}_{}]",
                                              side, upper ? "L" : "0", "xyz"[a], side, "xyz"[a]));
                    }
            for (const WallTable& table : wall_tables()) {
                const std::optional<WallConfig>& w = wall_config(c, table);
                const std::vector<int> axes = wall_axes(c, table);
                if (!w || axes.empty())
                    continue;
                const std::string& side = table.name;
                if (w->kind == WallKind::diffuse)
                    require(w->temperature.has_value(), side + ".temperature", side + ".kind = \"diffuse\"", side);
                for (const int a : axes)
                    if (w->velocity[static_cast<std::size_t>(a)] != 0)
                        add(side + ".velocity",
                            fmt::format("{}.velocity = [{}, {}, {}]: a wall of axis {} moves along itself only "
                                        "(component {} must be 0)",
                                        side, w->velocity[0], w->velocity[1], w->velocity[2], "xyz"[a], "xyz"[a]));
            }
        }
        double lambda = mean_free_path(c);
        // A density wave's crest is denser by 1 + |A|: its mean free path shorter by that.
        if (c.initial && c.initial->mode == Perturbation::density)
            lambda /= 1 + std::abs(c.initial->amplitude);
        if (c.initial && c.initial->mode != Perturbation::none)
            for (std::size_t i = 0; i < 3; ++i) {
                const double n = std::abs(static_cast<double>(c.initial->wave[i]));
                if (n > 0 && d.size[i] / n < 2 * d.size[i] / static_cast<double>(d.cells[i]))
                    add("initial.wave",
                        fmt::format("initial.wave = [{}, {}, {}]: a wavelength along {} of {:.4g} spans fewer than two "
                                    "cells of {:.4g} (collisions inside a cell ignore positions)",
                                    c.initial->wave[0], c.initial->wave[1], c.initial->wave[2], "xyz"[i],
                                    d.size[i] / n, d.size[i] / static_cast<double>(d.cells[i])));
            }
        double edge = 0;
        for (std::size_t i = 0; i < 3; ++i)
            edge = std::max(edge, d.size[i] / static_cast<double>(d.cells[i]));
        if (edge > lambda && !d.allow_coarse)
            add("domain.cells",
                fmt::format("domain.cells = [{}, {}, {}]: cells of {:.3g} mean free paths (edge {:.4g}, mean free "
                            "path {:.4g} at run.density = {:.4g}): at most 1, or set domain.allow_coarse = true",
                            d.cells[0], d.cells[1], d.cells[2], edge / lambda, edge, lambda, c.run.density));
    }

    // A hard-sphere gas cooling with constant restitution loses the share zeta* of its translational
    // temperature per collision per particle once its temperatures' ratios have settled (the reduced
    // cooling rate of its cooling state, docs/model.md §5): T_tr falls as exp(-zeta* s). Below about
    // 1e-300 m (in the case's units) the squares of the velocities underflow and the run would stop
    // with an error partway; refused before any work (cooling_reach: the theory's trajectory from the
    // species' temperatures). Not for a box whose walls drive the gas (a diffuse or moving wall holds
    // it at a steady state); with initial.from, run_states.cpp checks it from the saved state's.
    void check_cooling_reach(const CaseConfig& c) {
        const std::size_t S = c.species.size();
        std::vector<HcsSpecies> species;
        std::vector<ConstantRestitution> pairs(S * (S + 1) / 2);
        HcsTemperatures T;
        for (std::size_t a = 0; a < S; ++a) {
            const SpeciesConfig& s = c.species[a];
            if (!(s.mass > 0 && s.radius > 0 && s.temperature > 0 && s.rotational_temperature >= 0))
                return; // refused elsewhere
            species.push_back({s.mass, s.radius, s.inertia, s.fraction});
            T.T_tr.push_back(s.temperature);
            T.T_rot.push_back(s.rotational_temperature);
            for (std::size_t b = a; b < S; ++b) {
                const CollisionConfig& cc = collision_for(c, a, b);
                if (cc.model != CollisionModel::constant || !cc.alpha || !cc.beta)
                    return; // restitution that depends on the impact speed: the gas cools ever slower
                pairs[pair_index(a, b, S)] = ConstantRestitution{*cc.alpha, *cc.beta};
            }
        }
        double reach = HUGE_VAL;
        try {
            reach = cooling_reach(HcsTheory(species, pairs, c.run.density), T, underflow_temperature_per_mass);
        } catch (const std::invalid_argument&) {
            return; // refused elsewhere
        }
        if (c.run.end > reach)
            add("run.end",
                fmt::format("run.end = {}: a gas cooling with constant restitution loses a fixed share of its "
                            "temperature per collision and reaches T_tr = 1e-300 m, where the squares of the "
                            "velocities underflow, at about {:.4g} collisions per particle: end it before "
                            "(run.end < {:.4g})",
                            c.run.end, reach, reach));
    }

    // The Maxwell kernel is the reference model with a known answer for constant alpha, beta
    // (docs/model.md); it is compiled for constant restitution only.
    void check_maxwell_kernel(const CaseConfig& c) {
        for (std::size_t a = 0; a < c.species.size(); ++a) {
            for (std::size_t b = a; b < c.species.size(); ++b) {
                const CollisionModel m = collision_for(c, a, b).model;
                if (m == CollisionModel::constant)
                    continue;
                add("run.kernel",
                    fmt::format("run.kernel = \"maxwell\": needs model = \"constant\" for every pair, but "
                                "species \"{}\" and \"{}\" collide with model = \"{}\" (the Maxwell kernel is "
                                "the reference model of constant restitution; must be \"hard_sphere\" here)",
                                c.species[a].name, c.species[b].name, name(m)));
                return; // one message
            }
        }
    }

    void check_species(const CaseConfig& c) {
        double sum = 0;
        for (std::size_t i = 0; i < c.species.size(); ++i) {
            const SpeciesConfig& s = c.species[i];
            sum += s.fraction;
            for (std::size_t j = 0; j < i; ++j) {
                if (c.species[j].name == s.name) {
                    add(fmt::format("species.{}.name", i),
                        fmt::format("species.{}.name = \"{}\": must be unique (species.{} has it)", i, s.name,
                                    j),
                        fmt::format("species.{}", i));
                }
            }
            // Each species needs at least one simulated particle.
            if (static_cast<double>(c.run.particles) * s.fraction < 1) {
                add("run.particles",
                    fmt::format("run.particles = {}: species \"{}\" (fraction {}) gets no particle "
                                "(must be >= 1/fraction = {})",
                                c.run.particles, s.name, s.fraction, std::ceil(1 / s.fraction)));
            }
        }
        if (!c.species.empty() && std::abs(sum - 1) > 1e-9) {
            add("species.fraction",
                fmt::format("species.fraction: the fractions sum to {}, must sum to 1 (within "
                            "1e-9)",
                            sum),
                "species.0.fraction");
        }
    }

    void check_pair(const CaseConfig& c, std::size_t i) {
        const std::string key = fmt::format("pair.{}.species", i);
        std::vector<std::string> names;
        for (const SpeciesConfig& s : c.species)
            names.push_back("\"" + s.name + "\"");
        const auto& p = c.pairs[i].species;
        for (const std::string& n : p) {
            const bool known = std::any_of(c.species.begin(), c.species.end(),
                                           [&](const SpeciesConfig& s) { return s.name == n; });
            if (!known) {
                add(key, fmt::format("{} = [\"{}\", \"{}\"]: \"{}\" is not a species (must be one of {})",
                                     key, p[0], p[1], n, join(names)));
            }
        }
        for (std::size_t j = 0; j < i; ++j) {
            const auto& q = c.pairs[j].species;
            if ((q[0] == p[0] && q[1] == p[1]) || (q[0] == p[1] && q[1] == p[0])) {
                add(key, fmt::format(
                             "{} = [\"{}\", \"{}\"]: pair.{} already sets this pair (one [[pair]] per pair)",
                             key, p[0], p[1], j));
            }
        }
    }

    void check_collision(const CollisionConfig& c, const std::string& prefix) {
        const std::string why = fmt::format("{}.model = \"{}\"", prefix, name(c.model));
        switch (c.model) {
        case CollisionModel::constant:
            require(c.alpha.has_value(), prefix + ".alpha", why, prefix);
            require(c.beta.has_value(), prefix + ".beta", why, prefix);
            break;
        case CollisionModel::coulomb:
            require(c.alpha.has_value(), prefix + ".alpha", why, prefix);
            require(c.beta0.has_value(), prefix + ".beta0", why, prefix);
            require(c.friction.has_value(), prefix + ".friction", why, prefix);
            break;
        case CollisionModel::viscoelastic:
        case CollisionModel::brilliantov:
            material_users_.push_back(why);
            if (c.model == CollisionModel::brilliantov)
                asperity_users_.push_back(why);
            break;
        }
    }

    void check_material(const CaseConfig& c) {
        if (use_ == CaseUse::restitution) {
            material_users_.push_back("roughgas restitution");
            asperity_users_.push_back("roughgas restitution");
        }
        if (material_users_.empty())
            return;
        if (!c.material) {
            add("material",
                fmt::format("material: the [material] table is required for {} but missing "
                            "(young_modulus, poisson_ratio, dissipation{})",
                            join(material_users_), asperity_users_.empty() ? "" : ", friction, asperity"));
            return;
        }
        if (!asperity_users_.empty()) {
            require(c.material->friction.has_value(), "material.friction", join(asperity_users_), "material");
            require(c.material->asperity.has_value(), "material.asperity", join(asperity_users_), "material");
        }
    }

    void check_grid(const RestitutionGridConfig& g) {
        if (g.g_n_max < g.g_n_min) {
            add("restitution.g_n_max",
                fmt::format("restitution.g_n_max = {}: must be >= restitution.g_n_min = {} (m/s)", g.g_n_max,
                            g.g_n_min));
        }
        if (g.g_t_max < g.g_t_min) {
            add("restitution.g_t_max",
                fmt::format("restitution.g_t_max = {}: must be >= restitution.g_t_min = {} (m/s)", g.g_t_max,
                            g.g_t_min));
        }
    }

    const toml::table& root_;
    CaseUse use_;
    Diagnostics& d_;
    std::vector<std::string> material_users_; // why [material] is needed
    std::vector<std::string> asperity_users_; // why friction and asperity are needed
};

// ---------------------------------------------------------------------------------------------
// Emission

std::string quote(std::string_view s) {
    std::string out = "\"";
    for (const char c : s) {
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\t':
            out += "\\t";
            break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                out += fmt::format("\\u{:04x}", static_cast<int>(c));
            } else {
                out += c;
            }
        }
    }
    return out + "\"";
}

class Emitter {
  public:
    void header(std::string_view h) {
        if (!text_.empty())
            text_ += '\n';
        text_.append(h).append("\n");
    }
    void put(std::string_view k, double x) { line(k, toml_real(x)); }
    void put(std::string_view k, std::int64_t x) { line(k, std::to_string(x)); }
    void put(std::string_view k, std::uint64_t x) { line(k, std::to_string(x)); }
    void put(std::string_view k, bool b) { line(k, b ? "true" : "false"); }
    void put(std::string_view k, std::string_view s) { line(k, quote(s)); }
    void put(std::string_view k, const std::array<std::string, 2>& p) {
        line(k, fmt::format("[{}, {}]", quote(p[0]), quote(p[1])));
    }
    void put(std::string_view k, const std::array<double, 3>& x) {
        line(k, fmt::format("[{}, {}, {}]", toml_real(x[0]), toml_real(x[1]), toml_real(x[2])));
    }
    void put(std::string_view k, const std::array<std::int64_t, 3>& x) {
        line(k, fmt::format("[{}, {}, {}]", x[0], x[1], x[2]));
    }
    void put(std::string_view k, const std::vector<std::string>& x) {
        std::string text;
        for (const std::string& s : x)
            text += (text.empty() ? "" : ", ") + quote(s);
        line(k, "[" + text + "]");
    }
    void put(std::string_view k, const std::array<std::string, 3>& x) {
        line(k, fmt::format("[{}, {}, {}]", quote(x[0]), quote(x[1]), quote(x[2])));
    }
    void put(std::string_view k, const std::optional<double>& x) {
        if (x)
            put(k, *x);
    }
    void collision(const CollisionConfig& c) {
        put("model", name(c.model));
        put("alpha", c.alpha);
        put("beta", c.beta);
        put("beta0", c.beta0);
        put("friction", c.friction);
        put("direct", c.direct);
    }
    std::string str() const { return text_; }

  private:
    void line(std::string_view k, const std::string& v) { text_ += fmt::format("{} = {}\n", k, v); }
    std::string text_;
};

} // namespace

// ---------------------------------------------------------------------------------------------

CaseConfig parse_case(std::string_view toml_text, const std::string& file,
                      const std::vector<std::string>& overrides, CaseUse use) {
    toml::table root;
    try {
        root = toml::parse(toml_text, std::string_view(file));
    } catch (const toml::parse_error& e) {
        const toml::source_position p = e.source().begin;
        throw InputError(
            file, "", "TOML syntax error: " + std::string(e.description()),
            p ? std::optional(SourcePosition{static_cast<int>(p.line), static_cast<int>(p.column)})
              : std::nullopt);
    }
    Diagnostics d(file);
    for (const std::string& arg : overrides) {
        apply_override(root, arg, d);
    }
    d.throw_if_any();
    SchemaCheck(d).root(root);
    d.throw_if_any(); // the builder relies on every present value having the right type
    CaseConfig cfg = Builder(root, use, d).build();
    d.throw_if_any();
    return cfg;
}

CaseConfig load_case(const std::string& file, const std::vector<std::string>& overrides, CaseUse use) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw InputError(file, "", fmt::format("cannot read the case file ({})", std::strerror(errno)));
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parse_case(text.str(), file, overrides, use);
}

const KeySpec* find_key_of(const std::string& key) {
    return find_key(schema_path(split_path(key)));
}

std::string emit_case(const CaseConfig& c) {
    Emitter e;
    e.header("[run]");
    e.put("kind", name(c.run.kind));
    e.put("particles", c.run.particles);
    e.put("density", c.run.density);
    e.put("replicas", c.run.replicas);
    e.put("groups", c.run.groups);
    e.put("kernel", kernel_names[static_cast<int>(c.run.kernel)]);
    e.put("seed", c.run.seed);
    e.put("end", c.run.end);
    e.put("output_every", c.run.output_every);
    e.put("output_spacing", name(c.run.output_spacing));
    e.put("histogram_every", c.run.histogram_every);
    e.put("histogram_spacing", name(c.run.histogram_spacing));
    e.put("histogram_bins", c.run.histogram_bins);
    e.put("histogram_max", c.run.histogram_max);
    e.put("save_state", c.run.save_state);
    for (const SpeciesConfig& s : c.species) {
        e.header("[[species]]");
        e.put("name", s.name);
        if (s.density) { // the mass was derived: echo what the user gave, so that it reads back the same
            e.put("density", s.density);
        } else {
            e.put("mass", s.mass);
        }
        e.put("radius", s.radius);
        e.put("inertia", s.inertia);
        e.put("fraction", s.fraction);
        e.put("temperature", s.temperature);
        e.put("rotational_temperature", s.rotational_temperature);
    }
    e.header("[collision]");
    e.collision(c.collision);
    for (const PairConfig& p : c.pairs) {
        e.header("[[pair]]");
        e.put("species", p.species);
        e.collision(p.collision);
    }
    if (c.material) {
        const MaterialConfig& m = *c.material;
        e.header("[material]");
        e.put("young_modulus", m.young_modulus);
        e.put("poisson_ratio", m.poisson_ratio);
        if (m.eta1 && m.eta2) { // A was derived: echo what the user gave, so that it reads back the same
            e.put("eta1", m.eta1);
            e.put("eta2", m.eta2);
        } else {
            e.put("dissipation", m.dissipation);
        }
        e.put("friction", m.friction);
        e.put("asperity", m.asperity);
    }
    e.header("[contact]");
    e.put("form", name(c.contact.model.form));
    e.put("end", name(c.contact.model.end));
    e.put("cache", c.contact.cache);
    e.put("cache_file", c.contact.cache_file);
    e.put("tolerance", c.contact.tolerance.rel);
    if (c.shear) {
        e.header("[shear]");
        e.put("rate", c.shear->rate);
        e.put("time_step", c.shear->time_step);
    }
    if (c.initial) {
        e.header("[initial]");
        e.put("mode", name(c.initial->mode));
        e.put("amplitude", c.initial->amplitude);
        e.put("wave", c.initial->wave);
        if (!c.initial->from.empty())
            e.put("from", c.initial->from);
    }
    if (c.domain) {
        e.header("[domain]");
        e.put("size", c.domain->size);
        e.put("cells", c.domain->cells);
        e.put("boundary", std::array<std::string, 3>{std::string(name(c.domain->boundary[0])),
                                                      std::string(name(c.domain->boundary[1])),
                                                      std::string(name(c.domain->boundary[2]))});
        e.put("gravity", c.domain->gravity);
        e.put("profile_axis", std::string_view(&"xyz"[c.domain->profile_axis], 1));
        e.put("time_step", c.domain->time_step);
        e.put("allow_coarse", c.domain->allow_coarse);
        e.put("partners", name(c.domain->partners));
    }
    if (c.spectra) {
        e.header("[spectra]");
        e.put("modes", c.spectra->modes);
    }
    if (c.fields) {
        e.header("[fields]");
        std::vector<std::string> names;
        for (const FieldQuantity q : c.fields->quantities)
            names.emplace_back(field_quantity_names[static_cast<std::size_t>(q)]);
        e.put("quantities", names);
        e.put("every", c.fields->every);
        e.put("replicas", c.fields->replicas);
    }
    for (const WallTable& table : wall_tables()) {
        const std::optional<WallConfig>& w = wall_config(c, table);
        if (!w)
            continue;
        e.header("[" + table.name + "]");
        e.put("kind", name(w->kind));
        if (w->temperature)
            e.put("temperature", *w->temperature);
        e.put("velocity", w->velocity);
        e.put("alpha", w->alpha);
        e.put("beta", w->beta);
    }
    e.header("[restitution]");
    e.put("g_n_min", c.restitution.g_n_min);
    e.put("g_n_max", c.restitution.g_n_max);
    e.put("g_n_points", c.restitution.g_n_points);
    e.put("g_t_min", c.restitution.g_t_min);
    e.put("g_t_max", c.restitution.g_t_max);
    e.put("g_t_points", c.restitution.g_t_points);
    e.put("spacing", name(c.restitution.spacing));
    return e.str();
}

} // namespace roughgas
