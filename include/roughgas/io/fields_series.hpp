#pragma once
// A replica's cell fields over a run (docs/reference.md, "Fields"): one HDF5 file per snapshot,
// DIR/fields/replica_R/row_NNNNNN.h5 (NNNNNN: the row of moments.csv), and the XDMF sidecar
// DIR/fields/replica_R.xmf that ParaView opens as a time series (its "XDMF Reader", the Xdmf2
// format: a temporal collection of uniform grids, 3DCoRectMesh with ORIGIN_DXDYDZ, every value
// in z, y, x order, the fields cell-centred). The sidecar names the HDF5 files by absolute path,
// as ParaView's reader resolves them; it is rewritten, atomically, after every snapshot, so that
// it lists every file written so far (a run stopped at any point opens as far as it went).
#include "roughgas/dsmc/run.hpp"

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace roughgas {

std::filesystem::path fields_dir(const std::filesystem::path& run_dir);
std::filesystem::path fields_replica_dir(const std::filesystem::path& run_dir, int replica);
std::filesystem::path fields_xdmf_path(const std::filesystem::path& run_dir, int replica);

// A snapshot the sidecar lists.
struct FieldsEntry {
    std::size_t row = 0;
    double t = 0;
    std::filesystem::path file; // absolute
};

// The sidecar's text for these snapshots of one replica's cells.
std::string fields_xdmf(const std::vector<FieldsEntry>& entries, const std::array<int, 3>& cells,
                        const std::array<double, 3>& box, const std::vector<FieldQuantity>& quantities, int replica);

class FieldsSeries {
  public:
    // `resuming`: the run continues from a checkpoint; the snapshots already in the replica's
    // directory stay listed until the run writes their rows again. Otherwise the directory must
    // not hold snapshots (the run's start removes an earlier run's with --force).
    FieldsSeries(const std::filesystem::path& run_dir, int replica, const DomainSpec& domain, bool resuming);
    // Writes the snapshot's file and the sidecar. A row at or before the last one listed (a resumed
    // run going over rows again) replaces it and drops those after it.
    void add(const FieldSnapshot& s);

  private:
    std::filesystem::path dir_, xdmf_;
    int replica_;
    std::array<double, 3> box_;
    std::vector<FieldsEntry> entries_;
};

} // namespace roughgas
