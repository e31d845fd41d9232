#include "sweep/point_run.hpp"

#include "run/output_files.hpp"
#include "run/summary.hpp"

#include "roughgas/core/bytes.hpp"
#include "roughgas/io/case_file.hpp"
#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/moments_csv.hpp"
#include "roughgas/io/run_spec_from_case.hpp"
#include "roughgas/io/run_tables.hpp"
#include "roughgas/io/steady_csv.hpp"

#include <fmt/format.h>

namespace roughgas::cli {

namespace fs = std::filesystem;

PointResult point_result(const CaseConfig& cfg, const ReplicaRows& rows) {
    const RunSpec spec = run_spec_from_case(cfg);
    MomentsTable table(spec);
    PointResult p{table.names(), table.units(), {}, {}};
    for (std::size_t k = 0; k < rows[0].size(); ++k) {
        std::vector<std::span<const double>> spans;
        for (const auto& r : rows)
            spans.emplace_back(r[k]);
        p.rows.push_back(table.combine(spans));
    }
    p.steady = steady_summary(p.names, p.rows, driven(cfg), static_cast<int>(rows.size()));
    return p;
}

std::optional<ReplicaRows> run_point(RunSpec spec, const StopSignals& signals) {
    spec.threads = 1;
    MomentsTable table(spec);
    const auto tables = build_run_tables(spec);
    // No checkpoints: only the stop is polled at the replica's boundaries (the state it hands over
    // on a stop is not kept).
    ReplicaCheckpoints stop;
    stop.save = [](std::string) {};
    stop.stop = [&] { return signals.requested(); };
    ReplicaRows rows(static_cast<std::size_t>(spec.replicas));
    for (int r = 0; r < spec.replicas; ++r) {
        const auto sink = [&](std::span<const double> row) {
            table.check(row); // NonFiniteValue: stop, naming the column and t
            rows[static_cast<std::size_t>(r)].emplace_back(row.begin(), row.end());
        };
        if (signals.requested() ||
            run_replica(spec, *tables, r, sink, {}, nullptr, {}, &stop) == ReplicaEnd::stopped)
            return std::nullopt;
    }
    return rows;
}

void write_point_files(const fs::path& dir, const SweepOptions& o, const SweepPoints& points, long k,
                       const PointResult& p) {
    const auto K = static_cast<std::size_t>(k);
    CsvProvenance prov;
    prov.case_file = o.case_file;
    prov.overrides = points.sets[K];
    prov.seed = points.cases[K].run.seed;
    prov.resolved_case = emit_case(points.cases[K]);
    prov.notes = {fmt::format("sweep point {} of {}: {} = {}", k, points.count, points.key, points.values[K]),
                  unit_system_note(points.cases[K])};
    prov.units = p.units;
    CsvWriter csv(p.names, prov);
    for (const auto& row : p.rows)
        csv.add_row(row);
    const fs::path pd = dir / fmt::format("point_{}", k);
    fs::create_directories(pd);
    csv.write(pd / moments_file);
    // Its summary beside it: steady.csv for a driven gas (shear, heating walls), scaled.csv for cooling.
    write_summary_csv(pd, driven(points.cases[K]), p.steady, p.names, p.units, p.rows, prov);
}

std::vector<std::size_t> gather_points(const Communicator& comm, const std::vector<long>& mine,
                                       std::vector<ReplicaRows>& rows, std::vector<char>& done) {
    std::vector<std::size_t> received;
    ByteWriter w;
    for (long k : mine) {
        const auto K = static_cast<std::size_t>(k);
        if (!done[K])
            continue;
        w.u64(K);
        w.u64(rows[K].size());
        for (const auto& replica : rows[K]) {
            w.u64(replica.size());
            for (const auto& row : replica)
                w.f64s(row);
        }
    }
    const std::vector<std::string> parts = comm.gather(w.bytes());
    if (!comm.is_root())
        return received;
    for (std::size_t p = 1; p < parts.size(); ++p) {
        ByteReader in(parts[p]);
        while (in.remaining() > 0) {
            const auto K = static_cast<std::size_t>(in.u64());
            ReplicaRows point(in.count(sizeof(std::uint64_t)));
            for (auto& replica : point) {
                replica.resize(in.count(sizeof(std::uint64_t)));
                for (auto& row : replica)
                    row = in.f64s();
            }
            rows[K] = std::move(point);
            done[K] = 1;
            received.push_back(K);
        }
    }
    return received;
}

} // namespace roughgas::cli
