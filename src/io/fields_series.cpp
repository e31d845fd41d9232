// A replica's cell fields over a run: io/fields_series.hpp.
#include "roughgas/io/fields_series.hpp"

#include "roughgas/io/atomic_file.hpp"
#include "roughgas/io/fields_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace roughgas {
namespace fs = std::filesystem;
namespace {

std::string file_name(std::size_t row) { return fmt::format("row_{:06d}.h5", row); }

// XML's five special characters, for a path in element text.
std::string escaped(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&apos;"; break;
        default: out += c;
        }
    }
    return out;
}

} // namespace

fs::path fields_dir(const fs::path& run_dir) { return run_dir / "fields"; }
fs::path fields_replica_dir(const fs::path& run_dir, int replica) {
    return fields_dir(run_dir) / ("replica_" + std::to_string(replica));
}
fs::path fields_xdmf_path(const fs::path& run_dir, int replica) {
    return fields_dir(run_dir) / ("replica_" + std::to_string(replica) + ".xmf");
}

std::string fields_xdmf(const std::vector<FieldsEntry>& entries, const std::array<int, 3>& cells,
                        const std::array<double, 3>& box, const std::vector<FieldQuantity>& quantities, int replica) {
    // Xdmf2 lists every dimension slowest first: z, y, x (the datasets' order, fields_file.hpp).
    const std::string cells_zyx = fmt::format("{} {} {}", cells[2], cells[1], cells[0]);
    const std::string nodes_zyx = fmt::format("{} {} {}", cells[2] + 1, cells[1] + 1, cells[0] + 1);
    const std::string spacing_zyx =
        fmt::format("{} {} {}", box[2] / cells[2], box[1] / cells[1], box[0] / cells[0]);
    // Each file by its path from the sidecar's folder (replica_R/row_NNNNNN.h5), so that the run
    // directory opens wherever it is copied or moved to.
    const fs::path folder = fields_replica_dir(fs::path(), replica).filename();
    std::string x = "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n"
                    "  <Domain>\n";
    x += fmt::format("    <Grid Name=\"replica {}\" GridType=\"Collection\" CollectionType=\"Temporal\">\n", replica);
    for (const FieldsEntry& e : entries) {
        x += fmt::format("      <Grid Name=\"row {}\" GridType=\"Uniform\">\n", e.row);
        x += fmt::format("        <Time Value=\"{}\"/>\n", e.t);
        x += fmt::format("        <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"{}\"/>\n", nodes_zyx);
        x += "        <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
             "          <DataItem Name=\"Origin\" Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
             "Format=\"XML\">0 0 0</DataItem>\n";
        x += fmt::format("          <DataItem Name=\"Spacing\" Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
                         "Format=\"XML\">{}</DataItem>\n        </Geometry>\n",
                         spacing_zyx);
        for (const FieldQuantity q : quantities) {
            const int C = field_components(q);
            const std::string name(field_quantity_names[static_cast<std::size_t>(q)]);
            x += fmt::format("        <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"Cell\">\n", name,
                             C == 1 ? "Scalar" : C == 3 ? "Vector" : "Tensor6");
            x += fmt::format("          <DataItem Dimensions=\"{}{}\" NumberType=\"Float\" Precision=\"8\" "
                             "Format=\"HDF\">{}:/{}</DataItem>\n        </Attribute>\n",
                             cells_zyx, C == 1 ? std::string() : fmt::format(" {}", C),
                             escaped((folder / e.file.filename()).generic_string()), name);
        }
        x += "      </Grid>\n";
    }
    x += "    </Grid>\n  </Domain>\n</Xdmf>\n";
    return x;
}

FieldsSeries::FieldsSeries(const fs::path& run_dir, int replica, const DomainSpec& domain, bool resuming)
    : dir_(fields_replica_dir(run_dir, replica)), xdmf_(fields_xdmf_path(run_dir, replica)),
      replica_(replica), box_(domain.size) {
    fs::create_directories(dir_);
    if (!resuming)
        return;
    // The snapshots of the run so far, in row order.
    for (const fs::directory_entry& f : fs::directory_iterator(dir_)) {
        const std::string name = f.path().filename().string();
        if (!f.is_regular_file() || !name.starts_with("row_") || !name.ends_with(".h5"))
            continue;
        const FieldsFileHeader h = read_fields_header(f.path());
        entries_.push_back({static_cast<std::size_t>(h.row), h.t, f.path()});
    }
    std::sort(entries_.begin(), entries_.end(), [](const FieldsEntry& a, const FieldsEntry& b) { return a.row < b.row; });
}

FieldsSeries::~FieldsSeries() {
    if (writing_.valid())
        writing_.wait();
}

void FieldsSeries::add(FieldSnapshot s) {
    if (!s.fields)
        throw std::invalid_argument("FieldsSeries::add: a snapshot without fields");
    flush();
    writing_ = std::async(std::launch::async, [this, s = std::move(s)] { write(s); });
}

void FieldsSeries::flush() {
    if (writing_.valid())
        writing_.get();
}

void FieldsSeries::write(const FieldSnapshot& s) {
    const fs::path file = dir_ / file_name(s.row);
    FieldsFileHeader h;
    h.t = s.t;
    h.coll_per_particle = s.coll_per_particle;
    h.row = s.row;
    h.replica = replica_;
    h.box = box_;
    for (std::size_t a = 0; a < 3; ++a)
        h.cells[a] = s.fields->cells[a];
    write_fields_file(file, h, *s.fields);
    while (!entries_.empty() && entries_.back().row >= s.row) {
        if (entries_.back().row > s.row) {
            std::error_code ec;
            fs::remove(entries_.back().file, ec);
        }
        entries_.pop_back();
    }
    entries_.push_back({s.row, s.t, file});
    write_file_atomically(xdmf_, fields_xdmf(entries_, s.fields->cells, box_, s.fields->quantities, replica_));
}

} // namespace roughgas
