#pragma once
// Pass 2 of a case file builds CaseConfig table by table and checks the rules that involve several
// keys. What every table's build and checks share is here: the parsed case, what it must be complete
// for, where the issues go, and which collision models need [material].
#include "diagnostics.hpp"
#include "roughgas/io/case_file.hpp"

#include <toml++/toml.h>

#include <string>
#include <string_view>
#include <vector>

namespace roughgas::case_file {

class BuildContext {
  public:
    BuildContext(const toml::table& root, CaseUse use, Diagnostics& d) : root_(root), use_(use), d_(d) {}

    const toml::table& root() const { return root_; }
    CaseUse use() const { return use_; }

    // An issue of `key`, placed at the node of the display path `at` (default: `key` itself).
    void add(const std::string& key, std::string message, std::string_view at = {});

    // "x: required for <why> but missing (must be <expectation>)", placed at `at`, unless `present`.
    void require(bool present, const std::string& key, const std::string& why, std::string_view at);

    // `why` ("collision.model = \"brilliantov\"") needs [material]; with `asperities` also its friction
    // and asperity. The checks of [material] name every reason.
    void need_material(const std::string& why, bool asperities);
    const std::vector<std::string>& material_users() const { return material_users_; }
    const std::vector<std::string>& asperity_users() const { return asperity_users_; }

  private:
    const toml::table& root_;
    CaseUse use_;
    Diagnostics& d_;
    std::vector<std::string> material_users_; // why [material] is needed
    std::vector<std::string> asperity_users_; // why friction and asperity are needed
};

} // namespace roughgas::case_file
