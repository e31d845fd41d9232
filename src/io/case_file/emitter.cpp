// The TOML writer of the resolved case (emitter.hpp).
#include "emitter.hpp"

#include "messages.hpp"
#include "roughgas/io/case_schema.hpp"

#include <fmt/format.h>

namespace roughgas::case_file {

void Emitter::header(std::string_view h) {
    if (!text_.empty())
        text_ += '\n';
    text_.append(h).append("\n");
}

void Emitter::put(std::string_view k, double x) {
    line(k, toml_real(x));
}

void Emitter::put(std::string_view k, std::int64_t x) {
    line(k, std::to_string(x));
}

void Emitter::put(std::string_view k, std::uint64_t x) {
    line(k, std::to_string(x));
}

void Emitter::put(std::string_view k, bool b) {
    line(k, b ? "true" : "false");
}

void Emitter::put(std::string_view k, std::string_view s) {
    line(k, quote(s));
}

void Emitter::put(std::string_view k, const std::array<std::string, 2>& p) {
    line(k, fmt::format("[{}, {}]", quote(p[0]), quote(p[1])));
}

void Emitter::put(std::string_view k, const std::array<double, 3>& x) {
    line(k, fmt::format("[{}, {}, {}]", toml_real(x[0]), toml_real(x[1]), toml_real(x[2])));
}

void Emitter::put(std::string_view k, const std::array<std::int64_t, 3>& x) {
    line(k, fmt::format("[{}, {}, {}]", x[0], x[1], x[2]));
}

void Emitter::put(std::string_view k, const std::vector<std::string>& x) {
    std::string text;
    for (const std::string& s : x)
        text += (text.empty() ? "" : ", ") + quote(s);
    line(k, "[" + text + "]");
}

void Emitter::put(std::string_view k, const std::array<std::string, 3>& x) {
    line(k, fmt::format("[{}, {}, {}]", quote(x[0]), quote(x[1]), quote(x[2])));
}

void Emitter::put(std::string_view k, const std::vector<std::array<double, 2>>& x) {
    std::string text;
    for (const std::array<double, 2>& p : x)
        text += fmt::format("{}[{}, {}]", text.empty() ? "" : ", ", toml_real(p[0]), toml_real(p[1]));
    line(k, "[" + text + "]");
}

void Emitter::put(std::string_view k, const std::optional<double>& x) {
    if (x)
        put(k, *x);
}

void Emitter::line(std::string_view k, const std::string& v) {
    text_ += fmt::format("{} = {}\n", k, v);
}

} // namespace roughgas::case_file
