// Pass 1 of a case file: structure, names, types and ranges against the schema (io/case_schema.cpp),
// key by key. Cross-key rules are pass 2 (case_builder.cpp), which relies on what this pass accepted.
#include "schema_check.hpp"

#include "messages.hpp"
#include "roughgas/io/case_schema.hpp"
#include "roughgas/io/nearest_word.hpp"
#include "toml_access.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace roughgas::case_file {
namespace {

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
                d_.add(key,
                       fmt::format("{}: must be {}{}{}", shown, s.allowed(), unit_suffix(s),
                                   s.range_reason.empty() ? std::string() : " (" + s.range_reason + ")"),
                       &n);
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
        case KeyType::real_pairs: {
            // At least one pair, each of two reals checked as a key of type real (bounds).
            const toml::array* a = n.as_array();
            const auto is_pair = [](const toml::node& e) { return e.is_array() && e.as_array()->size() == 2; };
            if (a == nullptr || a->empty() || !std::all_of(a->begin(), a->end(), is_pair)) {
                d_.add(key, fmt::format("{}: must be {}, at least one", shown, type_phrase(s.type)), &n);
                return;
            }
            KeySpec element = s;
            element.type = KeyType::real;
            for (std::size_t i = 0; i < a->size(); ++i)
                for (std::size_t j = 0; j < 2; ++j)
                    value(element, *a->get(i)->as_array()->get(j), fmt::format("{}[{}][{}]", key, i, j));
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

} // namespace

void check_schema(const toml::table& root, Diagnostics& d) {
    SchemaCheck(d).root(root);
}

} // namespace roughgas::case_file
