#include "run/rank_gather.hpp"

#include "roughgas/core/bytes.hpp"
#include "roughgas/io/checkpoint_file.hpp"

#include <string>

namespace roughgas::cli {

void gather_replicas(const Communicator& comm, const RunSetup& setup, ReplicaRecords& records) {
    if (comm.size() == 1)
        return;
    ByteWriter w;
    for (int r = setup.replicas.mine_from; r < setup.replicas.mine_to; ++r) {
        const auto k = static_cast<std::size_t>(r);
        w.u64(k);
        w.u64(records.finished[k]);
        w.u64(records.final_saved[k]);
        const ReplicaSummary& s = records.summaries[k];
        w.str(s.kernel);
        w.put(s.collisions);
        w.put(s.resumed_at);
        w.put(s.overshoots);
        w.str(encode_checkpoint(
            ReplicaCheckpoint{setup.manifest.run, k, records.rows[k], records.histograms[k], {}}));
    }
    const std::vector<std::string> parts = comm.gather(w.bytes());
    if (!comm.is_root())
        return;
    for (std::size_t p = 1; p < parts.size(); ++p) {
        ByteReader in(parts[p]);
        while (in.remaining() > 0) {
            const auto k = static_cast<std::size_t>(in.u64());
            records.finished[k] = static_cast<char>(in.u64());
            records.final_saved[k] = static_cast<char>(in.u64());
            ReplicaSummary& s = records.summaries[k];
            s.kernel = in.str();
            s.collisions = in.get<std::int64_t>();
            s.resumed_at = in.get<std::int64_t>();
            s.overshoots = in.get<std::int64_t>();
            ReplicaCheckpoint c = decode_replica_checkpoint(in.str());
            records.rows[k] = std::move(c.rows);
            records.histograms[k] = std::move(c.histograms);
        }
    }
}

} // namespace roughgas::cli
