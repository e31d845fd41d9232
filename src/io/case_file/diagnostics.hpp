#pragma once
// Where the case-file checks put what they find: every issue of a pass is collected, then thrown
// at once, so that one `roughgas check` lists every problem rather than the first.
#include "roughgas/io/input_error.hpp"

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace roughgas::case_file {

// Keys set with --set say so, because the case file would not show the offending value.
class Diagnostics {
  public:
    explicit Diagnostics(std::string file) : file_(std::move(file)) {}

    void mark_override(const std::string& key) { overridden_.push_back(key); }

    // `key`: dotted display path; `node`: where to point (nullptr: no position).
    void add(const std::string& key, std::string message, const toml::node* node = nullptr);

    // In file order; issues without a position (missing keys, --set) last.
    void throw_if_any();

  private:
    bool overridden(const std::string& key) const;

    std::string file_;
    std::vector<std::string> overridden_;
    std::vector<InputIssue> issues_;
};

} // namespace roughgas::case_file
