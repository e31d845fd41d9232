#pragma once
// One point of a sweep: its replicas in turn on one thread (points run in parallel instead), the
// rows combined and summarized as `roughgas run` combines and summarizes its replicas'
// (io/moments_csv.hpp, run/summary.hpp), and its files point_K/moments.csv and its summary.
#include "stop_signals.hpp"
#include "sweep/points.hpp"

#include "roughgas/observables/steady_state.hpp"
#include "roughgas/parallel/communicator.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace roughgas::cli {

// rows[r][k]: replica r's row k.
using ReplicaRows = std::vector<std::vector<std::vector<double>>>;

struct PointResult {
    std::vector<std::string> names, units;
    std::vector<std::vector<double>> rows; // combined over the replicas
    SteadyResult steady;
};

// Every replica's rows; none when `signals` asked for a stop before the point ended (its state is
// dropped: a sweep has no checkpoints). `spec`: the point's, planned before any work.
std::optional<ReplicaRows> run_point(RunSpec spec, const StopSignals& signals);

// The point's combined rows and summary from its replicas' rows.
PointResult point_result(const CaseConfig& cfg, const ReplicaRows& rows);

// DIR/point_K/moments.csv and its summary (steady.csv or scaled.csv).
void write_point_files(const std::filesystem::path& dir, const SweepOptions& o, const SweepPoints& points, long k,
                       const PointResult& p);

// Under MPI: every rank's finished points (`done[k]`, their replicas' rows in `rows[k]`) to rank 0,
// which gets them into its own `rows` and `done`, in point order of the ranks. Collective; returns
// the points rank 0 received (none on the other ranks).
std::vector<std::size_t> gather_points(const Communicator& comm, const std::vector<long>& mine,
                                       std::vector<ReplicaRows>& rows, std::vector<char>& done);

} // namespace roughgas::cli
