// Encoding and decoding checkpoint files (see checkpoint_file.hpp).
#include "roughgas/io/checkpoint_file.hpp"

#include "roughgas/core/bytes.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

namespace roughgas {
namespace {

constexpr char magic[8] = {'R', 'G', 'C', 'H', 'E', 'C', 'K', 'P'};
constexpr std::size_t header_bytes = sizeof magic + 2 * sizeof(std::uint64_t);
enum class Kind : std::uint64_t { run = 1, replica = 2 };

void put_run(ByteWriter& w, const CheckpointRun& r) {
    w.str(r.program_version);
    w.str(r.case_file);
    w.u64(r.overrides.size());
    for (const std::string& o : r.overrides)
        w.str(o);
    w.str(r.resolved_case);
    w.u64(r.seed);
    w.u64(r.replicas);
    w.u64(r.particles);
}

CheckpointRun get_run(ByteReader& r) {
    CheckpointRun c;
    c.program_version = r.str();
    c.case_file = r.str();
    c.overrides.resize(r.count(sizeof(std::uint64_t)));
    for (std::string& o : c.overrides)
        o = r.str();
    c.resolved_case = r.str();
    c.seed = r.u64();
    c.replicas = r.u64();
    c.particles = r.u64();
    return c;
}

// The checks every file passes, in an order that names the likeliest cause: not a checkpoint at
// all, another format version (whose checksum may be computed otherwise), then the checksum (a
// truncated or damaged file), then the kind. Returns a reader over the payload.
ByteReader open(std::string_view bytes, Kind kind) {
    if (bytes.size() < header_bytes + sizeof(std::uint64_t)) {
        if (bytes.size() >= sizeof magic && std::memcmp(bytes.data(), magic, sizeof magic) == 0)
            throw CheckpointError(fmt::format("truncated ({} bytes)", bytes.size()));
        throw CheckpointError("not a roughgas checkpoint (bad header)");
    }
    if (std::memcmp(bytes.data(), magic, sizeof magic) != 0)
        throw CheckpointError("not a roughgas checkpoint (bad header)");
    ByteReader r(bytes.substr(0, bytes.size() - sizeof(std::uint64_t)));
    r.raw(sizeof magic);
    if (const std::uint64_t v = r.u64(); v != checkpoint_format_version)
        throw CheckpointError(fmt::format("checkpoint format version {}; this roughgas reads version {}", v,
                                          checkpoint_format_version));
    std::uint64_t stored;
    std::memcpy(&stored, bytes.data() + bytes.size() - sizeof stored, sizeof stored);
    if (stored != fnv1a(bytes.data(), bytes.size() - sizeof stored))
        throw CheckpointError("checksum mismatch: the file is truncated or corrupt");
    const auto k = static_cast<Kind>(r.u64());
    if (k != kind)
        throw CheckpointError(kind == Kind::run ? "a replica's checkpoint, not the run's (run.bin)"
                                                : "not a replica's checkpoint");
    return r;
}

// A file of `kind`: the header, the run's identity, what `payload(w)` writes, the checksum.
template <class Payload>
std::string encode(Kind kind, const CheckpointRun& run, std::size_t reserve, Payload&& payload) {
    ByteWriter w;
    w.reserve(reserve + 4096);
    w.raw(std::string_view(magic, sizeof magic));
    w.u64(checkpoint_format_version);
    w.u64(static_cast<std::uint64_t>(kind));
    put_run(w, run);
    payload(w);
    w.u64(fnv1a(w.bytes().data(), w.size()));
    return w.take();
}

// The reverse: `payload(r, c)` reads what follows the identity. A payload that does not read back
// (a file that passed the checksum but was written otherwise) is refused as malformed.
template <class C, class Payload> C decode(std::string_view bytes, Kind kind, Payload&& payload) {
    ByteReader r = open(bytes, kind);
    try {
        C c;
        c.run = get_run(r);
        payload(r, c);
        if (r.remaining() != 0)
            throw CheckpointError("malformed (trailing bytes)");
        return c;
    } catch (const CheckpointError&) {
        throw;
    } catch (const std::exception& e) {
        throw CheckpointError(std::string("malformed (") + e.what() + ")");
    }
}

// The first line where two texts differ, for a readable "other case" message.
std::string first_difference(const std::string& a, const std::string& b) {
    std::istringstream ia(a), ib(b);
    std::string la, lb;
    for (int line = 1;; ++line) {
        const bool more_a = static_cast<bool>(std::getline(ia, la));
        const bool more_b = static_cast<bool>(std::getline(ib, lb));
        if (!more_a && !more_b)
            return "";
        if (!more_a || !more_b || la != lb)
            return fmt::format("line {} of the resolved case is `{}`, expected `{}`", line, more_a ? la : "",
                               more_b ? lb : "");
    }
}

} // namespace

std::string checkpoint_difference(const CheckpointRun& f, const CheckpointRun& e) {
    std::vector<std::string> d;
    if (f.program_version != e.program_version)
        d.push_back(fmt::format("written by roughgas {}, expected {}", f.program_version, e.program_version));
    if (f.seed != e.seed)
        d.push_back(fmt::format("seed {}, expected {}", f.seed, e.seed));
    if (f.replicas != e.replicas)
        d.push_back(fmt::format("{} replicas, expected {}", f.replicas, e.replicas));
    if (f.particles != e.particles)
        d.push_back(fmt::format("{} particles, expected {}", f.particles, e.particles));
    if (f.resolved_case != e.resolved_case)
        d.push_back("another case: " + first_difference(f.resolved_case, e.resolved_case));
    if (f.case_file != e.case_file)
        d.push_back(fmt::format("case file {}, expected {}", f.case_file, e.case_file));
    if (f.overrides != e.overrides)
        d.push_back(fmt::format("--set {}, expected --set {}", fmt::join(f.overrides, " --set "),
                                fmt::join(e.overrides, " --set ")));
    return fmt::format("{}", fmt::join(d, "; "));
}

std::string encode_checkpoint(const RunCheckpoint& c) {
    return encode(Kind::run, c.run, 0, [&](ByteWriter& w) {
        w.f64(c.checkpoint_every);
        w.u64(c.replica_from);
        w.u64(c.replica_to);
    });
}

std::string encode_checkpoint(const ReplicaCheckpoint& c) {
    return encode(Kind::replica, c.run, c.state.size(), [&](ByteWriter& w) {
        w.u64(c.replica);
        w.u64(c.rows.size());
        for (const std::vector<double>& row : c.rows)
            w.f64s(row);
        w.u64(c.histograms.size());
        for (const HistogramSet& h : c.histograms) {
            w.f64(h.t);
            w.f64(h.coll_per_particle);
            w.u64(h.species.size());
            for (const SpeciesHistograms& s : h.species) {
                w.f64s(s.c);
                w.f64s(s.w);
                w.f64s(s.cw);
            }
        }
        w.str(c.state);
    });
}

RunCheckpoint decode_run_checkpoint(std::string_view bytes) {
    return decode<RunCheckpoint>(bytes, Kind::run,
                                 [](ByteReader& r, RunCheckpoint& c) {
                                     c.checkpoint_every = r.f64();
                                     c.replica_from = r.u64();
                                     c.replica_to = r.u64();
                                 });
}

ReplicaCheckpoint decode_replica_checkpoint(std::string_view bytes) {
    return decode<ReplicaCheckpoint>(bytes, Kind::replica, [](ByteReader& r, ReplicaCheckpoint& c) {
        c.replica = r.u64();
        c.rows.resize(r.count(sizeof(std::uint64_t)));
        for (std::vector<double>& row : c.rows)
            row = r.f64s();
        c.histograms.resize(r.count(3 * sizeof(std::uint64_t)));
        for (HistogramSet& h : c.histograms) {
            h.t = r.f64();
            h.coll_per_particle = r.f64();
            h.species.resize(r.count(3 * sizeof(std::uint64_t)));
            for (SpeciesHistograms& s : h.species) {
                s.c = r.f64s();
                s.w = r.f64s();
                s.cw = r.f64s();
            }
        }
        c.state = r.str();
    });
}

std::filesystem::path checkpoint_dir(const std::filesystem::path& out) {
    return out / "checkpoint";
}
std::filesystem::path run_checkpoint_path(const std::filesystem::path& out) {
    return checkpoint_dir(out) / "run.bin";
}
std::filesystem::path replica_checkpoint_path(const std::filesystem::path& out, std::uint64_t replica) {
    return checkpoint_dir(out) / fmt::format("replica_{}.bin", replica);
}

std::string read_checkpoint_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in)
        throw std::system_error(errno, std::generic_category(), "cannot read " + path.string());
    std::string bytes(static_cast<std::size_t>(in.tellg()), '\0');
    in.seekg(0);
    if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
        throw std::system_error(errno, std::generic_category(), "cannot read " + path.string());
    return bytes;
}

} // namespace roughgas
