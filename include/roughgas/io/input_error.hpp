#pragma once
// Invalid user input: the CLI maps it to exit status 2 (docs/reference.md). One error may carry several
// issues, so a user fixing a case file sees every problem of a validation pass at once.
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace roughgas {

struct SourcePosition {
    int line = 0;   // 1-based
    int column = 0; // 1-based
    friend bool operator==(const SourcePosition&, const SourcePosition&) = default;
};

// One problem: `file:line:column: message`, where message starts with the key,
// e.g. "material.young_modulus = -1: must be > 0 (Pa)".
struct InputIssue {
    std::string file;                    // as the user wrote it ("" when not about a file)
    std::string key;                     // dotted path, "species.0.radius" ("" when not about a key)
    std::string message;                 // complete, starting with the key where there is one
    std::optional<SourcePosition> where; // unknown for keys set with --set or missing keys

    std::string text() const {
        std::string s = file;
        if (where) {
            s += ':' + std::to_string(where->line) + ':' + std::to_string(where->column);
        }
        return s.empty() ? message : s + ": " + message;
    }
};

class InputError : public std::runtime_error {
  public:
    explicit InputError(InputIssue issue) : InputError(std::vector<InputIssue>{std::move(issue)}) {}
    explicit InputError(std::vector<InputIssue> issues)
        : std::runtime_error(join(issues)), issues_(std::move(issues)) {
        if (issues_.empty()) {
            issues_.push_back({"", "", "invalid input", std::nullopt});
        }
    }
    InputError(std::string file, std::string key, std::string message,
               std::optional<SourcePosition> where = std::nullopt)
        : InputError(InputIssue{std::move(file), std::move(key), std::move(message), where}) {}

    const std::vector<InputIssue>& issues() const { return issues_; }
    // The first issue's parts (there is always at least one).
    const std::string& file() const { return issues_.front().file; }
    const std::string& key() const { return issues_.front().key; }
    const std::string& message() const { return issues_.front().message; }
    const std::optional<SourcePosition>& where() const { return issues_.front().where; }

  private:
    static std::string join(const std::vector<InputIssue>& issues) {
        std::string s;
        for (const InputIssue& i : issues) {
            if (!s.empty())
                s += '\n';
            s += i.text();
        }
        return s.empty() ? "invalid input" : s;
    }
    std::vector<InputIssue> issues_;
};

} // namespace roughgas
