// Encoding and decoding state files (see state_file.hpp).
#include "roughgas/io/state_file.hpp"

#include "roughgas/core/bytes.hpp"

#include <fmt/format.h>

#include <cstring>

namespace roughgas {
namespace {

constexpr char magic[8] = {'R', 'G', 'S', 'T', 'A', 'T', 'E', '1'};

void put_vec3s(ByteWriter& w, const std::vector<Vec3>& a) {
    for (const Vec3& q : a)
        for (double c : {q.x, q.y, q.z})
            w.f64(c);
}

std::vector<Vec3> get_vec3s(ByteReader& r, std::size_t n) {
    std::vector<Vec3> a(n);
    for (Vec3& q : a) {
        q.x = r.f64();
        q.y = r.f64();
        q.z = r.f64();
    }
    return a;
}

} // namespace

std::string encode_state(std::string_view program_version, const std::vector<StateSpecies>& species,
                         const GrainState& g) {
    ByteWriter w;
    w.reserve((g.x.size() + g.v.size() + g.w.size()) * 3 * sizeof(double) + 4096);
    w.raw(std::string_view(magic, sizeof magic));
    w.u64(state_format_version);
    w.str(program_version);
    w.u64(species.size());
    for (const StateSpecies& s : species) {
        w.str(s.name);
        w.f64(s.mass);
        w.f64(s.radius);
        w.u64(s.grains);
    }
    for (double L : g.box)
        w.f64(L);
    w.f64(g.t);
    w.f64(g.coll_per_particle);
    w.u64(g.x.empty() ? 0 : 1);
    put_vec3s(w, g.x);
    put_vec3s(w, g.v);
    put_vec3s(w, g.w);
    w.u64(fnv1a(w.bytes().data(), w.size()));
    return w.take();
}

StateFile decode_state(std::string_view bytes) {
    if (bytes.size() < sizeof magic || std::memcmp(bytes.data(), magic, sizeof magic) != 0)
        throw StateFileError("not a roughgas state file (bad header)");
    if (bytes.size() < sizeof magic + 2 * sizeof(std::uint64_t))
        throw StateFileError(fmt::format("truncated ({} bytes)", bytes.size()));
    ByteReader r(bytes.substr(0, bytes.size() - sizeof(std::uint64_t)));
    r.raw(sizeof magic);
    if (const std::uint64_t v = r.u64(); v != state_format_version)
        throw StateFileError(
            fmt::format("state format version {}; this roughgas reads version {}", v, state_format_version));
    std::uint64_t stored;
    std::memcpy(&stored, bytes.data() + bytes.size() - sizeof stored, sizeof stored);
    if (stored != fnv1a(bytes.data(), bytes.size() - sizeof stored))
        throw StateFileError("checksum mismatch: the file is truncated or corrupt");
    try {
        StateFile f;
        f.program_version = r.str();
        f.species.resize(r.count(3 * sizeof(std::uint64_t)));
        std::size_t n = 0;
        for (StateSpecies& s : f.species) {
            s.name = r.str();
            s.mass = r.f64();
            s.radius = r.f64();
            s.grains = r.u64();
            n += s.grains;
        }
        GrainState& g = f.grains;
        for (double& L : g.box)
            L = r.f64();
        g.t = r.f64();
        g.coll_per_particle = r.f64();
        const bool positions = r.u64() != 0;
        // Every array is n grains long: the remaining bytes must say so before anything is allocated.
        if (r.remaining() != (positions ? 3 : 2) * n * 3 * sizeof(double))
            throw StateFileError("malformed (the arrays do not hold the grains the header counts)");
        if (positions)
            g.x = get_vec3s(r, n);
        g.v = get_vec3s(r, n);
        g.w = get_vec3s(r, n);
        return f;
    } catch (const StateFileError&) {
        throw;
    } catch (const std::exception& e) {
        throw StateFileError(std::string("malformed (") + e.what() + ")");
    }
}

std::filesystem::path state_dir(const std::filesystem::path& out) {
    return out / "state";
}

std::filesystem::path state_file_path(const std::filesystem::path& out, std::uint64_t replica) {
    return state_dir(out) / fmt::format("replica_{}.bin", replica);
}

} // namespace roughgas
