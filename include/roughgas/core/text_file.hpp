#pragma once
// The whole text of a small system file (/proc, /sys): "" when it cannot be read, which callers
// take as "no such limit".
#include <fstream>
#include <sstream>
#include <string>

namespace roughgas {

inline std::string read_text_file(const char* path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace roughgas
