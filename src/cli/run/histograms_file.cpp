#include "run/histograms_file.hpp"

#include "run/output_files.hpp"

#include <algorithm>

namespace roughgas::cli {
namespace {

CsvProvenance histograms_provenance(const RunProvenance& run, const HistogramsTable& table) {
    CsvProvenance p = run.csv;
    p.notes = {"one row per bin at every run.histogram_every time; reduced variables per species: c* = "
               "c sqrt(m/(2 T_tr)), w* = omega sqrt(J/(2 T_rot)) (observables/histograms.hpp)",
               run.csv.notes[1], run.csv.notes[2]};
    p.units = table.units();
    return p;
}

} // namespace

HistogramsFile::HistogramsFile(const std::filesystem::path& dir, const RunSpec& spec, const RunProvenance& provenance)
    : path_(dir / histograms_file), table_(spec), csv_(table_.names(), histograms_provenance(provenance, table_)) {}

void HistogramsFile::update(const std::vector<std::vector<HistogramSet>>& sets) {
    std::size_t complete = sets[0].size();
    for (const auto& r : sets)
        complete = std::min(complete, r.size());
    if (complete == written_)
        return;
    for (; written_ < complete; ++written_) {
        std::vector<HistogramSet> same_time;
        for (const auto& r : sets)
            same_time.push_back(r[written_]);
        for (const std::vector<double>& row : table_.combine(same_time))
            csv_.add_row(row);
    }
    csv_.write(path_);
}

} // namespace roughgas::cli
