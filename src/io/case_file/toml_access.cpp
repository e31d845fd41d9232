// Typed access to the parsed TOML and the node at a display path (toml_access.hpp).
#include "toml_access.hpp"

#include <cmath>

namespace roughgas::case_file {

std::optional<double> as_real(const toml::node& n) {
    if (const auto* f = n.as_floating_point())
        return f->get();
    if (const auto* i = n.as_integer())
        return static_cast<double>(i->get());
    return std::nullopt;
}

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

double Reader::real(std::string_view k) const {
    const toml::node* n = node(k);
    return n ? *as_real(*n) : std::get<double>(spec(k).default_value);
}

std::optional<double> Reader::opt_real(std::string_view k) const {
    const toml::node* n = node(k);
    return n ? as_real(*n) : std::nullopt;
}

std::int64_t Reader::integer(std::string_view k) const {
    const toml::node* n = node(k);
    return n ? *as_integer(*n) : std::get<std::int64_t>(spec(k).default_value);
}

bool Reader::boolean(std::string_view k) const {
    const toml::node* n = node(k);
    return n ? n->as_boolean()->get() : std::get<bool>(spec(k).default_value);
}

std::string Reader::string(std::string_view k) const {
    const toml::node* n = node(k);
    return n ? n->as_string()->get() : std::get<std::string>(spec(k).default_value);
}

std::array<double, 3> Reader::real3(std::string_view k) const {
    std::array<double, 3> x{};
    if (const toml::array* a = node(k) ? node(k)->as_array() : nullptr)
        for (std::size_t i = 0; i < 3; ++i)
            x[i] = *as_real(*a->get(i));
    return x;
}

std::array<std::int64_t, 3> Reader::integer3(std::string_view k) const {
    std::array<std::int64_t, 3> x{};
    if (const toml::array* a = node(k) ? node(k)->as_array() : nullptr)
        for (std::size_t i = 0; i < 3; ++i)
            x[i] = *as_integer(*a->get(i));
    return x;
}

std::array<std::string, 3> Reader::string3(std::string_view k) const {
    const toml::array* a = node(k) ? node(k)->as_array() : nullptr;
    if (a == nullptr) {
        const std::string d = std::get<std::string>(spec(k).default_value);
        return {d, d, d};
    }
    return {a->get(0)->as_string()->get(), a->get(1)->as_string()->get(), a->get(2)->as_string()->get()};
}

std::vector<std::string> Reader::strings(std::string_view k) const {
    std::vector<std::string> list;
    if (const toml::array* a = node(k) ? node(k)->as_array() : nullptr) {
        for (const toml::node& e : *a)
            list.push_back(e.as_string()->get());
        return list;
    }
    return spec(k).default_list();
}

std::vector<std::array<double, 2>> Reader::real_pairs(std::string_view k) const {
    std::vector<std::array<double, 2>> pairs;
    if (const toml::array* a = node(k) ? node(k)->as_array() : nullptr)
        for (const toml::node& e : *a)
            pairs.push_back({*as_real(*e.as_array()->get(0)), *as_real(*e.as_array()->get(1))});
    return pairs;
}

const KeySpec& Reader::spec(std::string_view k) const {
    return *find_key(table_ + "." + std::string(k));
}

} // namespace roughgas::case_file
