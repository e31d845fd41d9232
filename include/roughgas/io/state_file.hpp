#pragma once
// The grains a run leaves for a later one (run.save_state, initial.from; docs/reference.md, "State
// files"): DIR/state/replica_R.bin holds replica R's grains at the end of the run.
//
// Layout (this machine's byte order, core/bytes.hpp):
//   "RGSTATE1" | u64 format version | str program version | u64 species, each: str name, f64 mass,
//   f64 radius, u64 grains | f64 box L_x, L_y, L_z (0 without a box) | f64 t | f64 coll_per_particle |
//   u64 1 if positions follow | f64 x, y, z per grain (if so) | f64 v per grain | f64 omega per grain |
//   u64 FNV-1a-64 of all before
// Written atomically (io/atomic_file.hpp).
#include "roughgas/dsmc/grain_state.hpp"

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace roughgas {

struct StateSpecies {
    std::string name;
    double mass = 0, radius = 0;
    std::uint64_t grains = 0;
    friend bool operator==(const StateSpecies&, const StateSpecies&) = default;
};

struct StateFile {
    std::string program_version;
    std::vector<StateSpecies> species; // in the run's order; the grains follow in it
    GrainState grains;
};

inline constexpr std::uint64_t state_format_version = 1;

// A file that cannot be used: the message says why (the caller names the file).
struct StateFileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::string encode_state(std::string_view program_version, const std::vector<StateSpecies>& species,
                         const GrainState& grains);
// Throws StateFileError: not a state file, another format version, checksum mismatch, malformed.
StateFile decode_state(std::string_view bytes);

std::filesystem::path state_dir(const std::filesystem::path& out);
std::filesystem::path state_file_path(const std::filesystem::path& out, std::uint64_t replica);

} // namespace roughgas
