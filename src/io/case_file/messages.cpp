// The shared wording of the case-file messages (messages.hpp).
#include "messages.hpp"

#include <fmt/format.h>

#include <sstream>

namespace roughgas::case_file {

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
    case KeyType::real_pairs:
        return "an array of [real, real] pairs";
    }
    return "?";
}

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

std::optional<std::string> misplaced(std::string_view name, std::string_view table) {
    for (const KeySpec& k : case_schema()) {
        if (k.name() == name && k.table() != table) {
            return std::string(k.name()) + " in " + table_header(*find_table(k.table()));
        }
    }
    return std::nullopt;
}

} // namespace roughgas::case_file
