#pragma once
// One snapshot of a box's cell fields as an HDF5 file (docs/reference.md, "Fields"): written under
// a temporary name, synced and renamed (io/atomic_file.hpp), so a kill leaves the file whole or absent.
//
// Layout: root attributes t, coll_per_particle, row (of moments.csv), replica, box (L_x, L_y, L_z),
// cells (G_x, G_y, G_z); one 64-bit float dataset per quantity (observables/cell_fields.hpp), of
// shape (G_z, G_y, G_x) for scalars and (G_z, G_y, G_x, C) for the C components of vectors and of
// P: cell (i, j, l) at [l, j, i], x fastest, as ParaView's XDMF reader takes a 3-D array; each
// dataset has a string attribute `unit`.
//
// The HDF5 library of the Debian packages is built without thread safety: every call into it here
// holds one lock of the process (replicas write from their own threads).
#include "roughgas/observables/cell_fields.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace roughgas {

struct FieldsFileHeader {
    double t = 0, coll_per_particle = 0;
    std::uint64_t row = 0;
    std::int64_t replica = 0;
    std::array<double, 3> box{1, 1, 1};
    std::array<std::int64_t, 3> cells{1, 1, 1};
};

// Writes the snapshot to `path` (std::runtime_error naming the file if HDF5 or the disk fails).
void write_fields_file(const std::filesystem::path& path, const FieldsFileHeader& header, const CellFields& fields);

// The root attributes of a fields file (std::runtime_error naming the file if it cannot be read).
FieldsFileHeader read_fields_header(const std::filesystem::path& path);

// One dataset: its values (in the file's order) and shape.
struct FieldsDataset {
    std::vector<double> values;
    std::vector<std::size_t> shape;
    std::string unit;
};
FieldsDataset read_fields_dataset(const std::filesystem::path& path, const std::string& name);

} // namespace roughgas
