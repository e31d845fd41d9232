// read_csv: a CSV that roughgas wrote (csv_writer.hpp: '#' lines, a header, rows of shortest
// round-trip decimals) as its '#' lines, its column names and one array of shape (columns, rows)
// whose rows are the file's columns. The numbers are parsed with std::from_chars (correctly
// rounded): each value is the double the run wrote. The buffer is moved into NumPy, never copied,
// so each column is a view of it.
#include "bindings.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <charconv>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace py = pybind11;

namespace roughgas::python {
namespace {

struct CsvTable {
    std::vector<std::string> comments; // the '#' lines without "# "
    std::vector<std::string> names;
    std::vector<double> values; // row-major while read
    std::size_t rows = 0;
};

// from_chars takes "nan", "inf", "-inf" as the writer spells them.
double parse_value(std::string_view text, const std::string& path, std::size_t line) {
    while (!text.empty() && text.front() == ' ')
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\r'))
        text.remove_suffix(1);
    double v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size())
        throw std::runtime_error(path + ":" + std::to_string(line) + ": not a number: \"" + std::string(text) + "\"");
    return v;
}

CsvTable read_table(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(path + ": cannot read");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    CsvTable t;
    std::size_t pos = 0, line = 0;
    bool header = false;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos)
            end = text.size();
        std::string_view l(text.data() + pos, end - pos);
        pos = end + 1;
        ++line;
        if (l.empty())
            continue;
        if (l.front() == '#') {
            l.remove_prefix(1);
            if (!l.empty() && l.front() == ' ')
                l.remove_prefix(1);
            t.comments.emplace_back(l);
            continue;
        }
        std::size_t fields = 0;
        for (std::size_t start = 0;;) {
            const std::size_t comma = l.find(',', start);
            const std::string_view field = l.substr(start, comma == std::string_view::npos ? l.npos : comma - start);
            if (!header) {
                std::string name(field);
                while (!name.empty() && (name.back() == ' ' || name.back() == '\r'))
                    name.pop_back();
                t.names.push_back(name);
            } else {
                t.values.push_back(parse_value(field, path, line));
            }
            ++fields;
            if (comma == std::string_view::npos)
                break;
            start = comma + 1;
        }
        if (!header) {
            header = true;
        } else {
            if (fields != t.names.size())
                throw std::runtime_error(path + ":" + std::to_string(line) + ": " + std::to_string(fields) +
                                         " values for " + std::to_string(t.names.size()) + " columns");
            ++t.rows;
        }
    }
    if (!header)
        throw std::runtime_error(path + ": no header line");
    return t;
}

} // namespace

void bind_csv(py::module_& m) {
    m.def(
        "read_csv",
        [](const std::string& path) {
            CsvTable t;
            auto columns = std::make_unique<std::vector<double>>();
            {
                py::gil_scoped_release release;
                t = read_table(path);
                const std::size_t n = t.names.size();
                columns->resize(t.values.size());
                for (std::size_t r = 0; r < t.rows; ++r) // to column-major: each column contiguous
                    for (std::size_t c = 0; c < n; ++c)
                        (*columns)[c * t.rows + r] = t.values[r * n + c];
            }
            const auto n = static_cast<py::ssize_t>(t.names.size()), rows = static_cast<py::ssize_t>(t.rows);
            double* data = columns->data();
            py::capsule owner(columns.release(), [](void* p) { delete static_cast<std::vector<double>*>(p); });
            py::array_t<double> array({n, rows}, {rows * static_cast<py::ssize_t>(sizeof(double)),
                                                  static_cast<py::ssize_t>(sizeof(double))},
                                      data, owner);
            return py::make_tuple(t.comments, t.names, array);
        },
        py::arg("path"),
        "(comments, names, values): a roughgas CSV; values[i] is the column names[i] (a view of one buffer)");
}

} // namespace roughgas::python
