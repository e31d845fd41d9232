#pragma once
// What every CSV of a run says of itself in its '#' lines: the case, overrides and seed it was
// started with (kept in the checkpoint, so that a resumed run writes the same bytes), the replicas,
// the units, the shear, the start, the box and its cells, and the warnings of the case; the notes
// of the box and the warnings go to stderr as well.
#include "run/setup.hpp"

#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/moments_csv.hpp"

#include <string>

namespace roughgas::cli {

struct RunProvenance {
    CsvProvenance csv; // moments.csv's; notes[1] (the replicas) and notes[2] (the units) serve every file
    std::string box_note; // the box's description, also in walls.csv and profiles.csv ("" without a box)
};

// The notes and the set-up's warnings (run/setup_warnings.hpp) go to stderr from rank 0 (`root`).
RunProvenance run_provenance(const RunSetup& setup, const MomentsTable& table, bool root);

// The provenance of another file of the run: `what` it holds first, then the replicas, the units,
// and the box.
CsvProvenance file_provenance(const RunProvenance& run, std::string what, const std::vector<std::string>& units);

} // namespace roughgas::cli
