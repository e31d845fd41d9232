// What the tables' builds and checks share (build_context.hpp).
#include "build_context.hpp"

#include "messages.hpp"
#include "toml_access.hpp"

#include <fmt/format.h>

namespace roughgas::case_file {

void BuildContext::add(const std::string& key, std::string message, std::string_view at) {
    d_.add(key, std::move(message), locate(root_, at.empty() ? std::string_view(key) : at));
}

void BuildContext::require(bool present, const std::string& key, const std::string& why, std::string_view at) {
    if (!present) {
        const KeySpec* s = find_key_of(key);
        add(key, fmt::format("{}: required for {} but missing (must be {})", key, why, expectation(*s)), at);
    }
}

void BuildContext::need_material(const std::string& why, bool asperities) {
    material_users_.push_back(why);
    if (asperities)
        asperity_users_.push_back(why);
}

} // namespace roughgas::case_file
