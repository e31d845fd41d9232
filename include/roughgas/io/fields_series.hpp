#pragma once
// A replica's cell fields over a run (docs/reference.md, "Fields"): one HDF5 file per snapshot,
// DIR/fields/replica_R/row_NNNNNN.h5 (NNNNNN: the row of moments.csv), and the XDMF sidecar
// DIR/fields/replica_R.xmf that ParaView opens as a time series (its "XDMF Reader", the Xdmf2
// format: a temporal collection of uniform grids, 3DCoRectMesh with ORIGIN_DXDYDZ, every value
// in z, y, x order, the fields cell-centred). The sidecar names each HDF5 file relative to its own
// folder (replica_R/row_NNNNNN.h5), as ParaView's reader resolves it, so that a run directory
// opens wherever it is copied to; it is rewritten, atomically, after every snapshot, so that it
// lists every file written so far (a run stopped at any point opens as far as it went).
// The files are written on a thread of the series' own, one snapshot behind the run: building the
// HDF5 image, writing it and syncing it to disk overlap the steps that follow, and a run that
// writes every quantity of every cell at every row waits for the disk only when the disk is slower
// than the run.
#include "roughgas/dsmc/run.hpp"

#include <array>
#include <filesystem>
#include <future>
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
    std::filesystem::path file; // in the replica's directory, fields_replica_dir
};

// The sidecar's text for these snapshots of one replica's cells, each named by the file name of
// its `file` in the replica's directory.
std::string fields_xdmf(const std::vector<FieldsEntry>& entries, const std::array<int, 3>& cells,
                        const std::array<double, 3>& box, const std::vector<FieldQuantity>& quantities, int replica);

class FieldsSeries {
  public:
    // `resuming`: the run continues from a checkpoint; the snapshots already in the replica's
    // directory stay listed until the run writes their rows again. Otherwise the directory must
    // not hold snapshots (the run's start removes an earlier run's with --force).
    FieldsSeries(const std::filesystem::path& run_dir, int replica, const DomainSpec& domain, bool resuming);
    FieldsSeries(const FieldsSeries&) = delete;
    FieldsSeries& operator=(const FieldsSeries&) = delete;
    // Waits for the snapshot being written; an error of its writing is lost here (flush reports it).
    ~FieldsSeries();
    // Starts writing the snapshot's file and then the sidecar, once the snapshot before it is
    // written (rethrowing that one's error). A row at or before the last one listed (a resumed run
    // going over rows again) replaces it and drops those after it.
    void add(FieldSnapshot s);
    // Waits until every snapshot added is on disk with the sidecar listing it; rethrows an error of
    // the writing. A checkpoint waits for it, so that a run resumed from it finds every snapshot
    // before it, and so does the end of the run.
    void flush();

  private:
    void write(const FieldSnapshot& s);

    std::filesystem::path dir_, xdmf_;
    int replica_;
    std::array<double, 3> box_;
    std::vector<FieldsEntry> entries_; // written only by the snapshot being written
    std::future<void> writing_;
};

} // namespace roughgas
