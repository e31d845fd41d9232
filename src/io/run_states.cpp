// initial.from and run.save_state (see run_states.hpp).
#include "roughgas/io/run_states.hpp"

#include "roughgas/dsmc/species.hpp"
#include "roughgas/io/atomic_file.hpp"
#include "roughgas/io/checkpoint_file.hpp"
#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/input_error.hpp"
#include "roughgas/io/state_file.hpp"
#include "roughgas/observables/moments.hpp"
#include "roughgas/observables/theory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <system_error>

namespace roughgas {
namespace fs = std::filesystem;

namespace {

std::string describe(const StateSpecies& s) {
    return fmt::format("{} (m = {}, R = {}, {} grains)", s.name, s.mass, s.radius, s.grains);
}

// The species the case asks for, as a state file would list them.
std::vector<StateSpecies> case_species(const RunSpec& spec) {
    const std::vector<SpeciesBlock> blocks = make_species_blocks(spec.species, spec.particles);
    std::vector<StateSpecies> s;
    for (std::size_t k = 0; k < blocks.size(); ++k)
        s.push_back({spec.species[k].name, blocks[k].grain.mass, blocks[k].grain.radius, blocks[k].count});
    return s;
}

StateFile read_state(const fs::path& path) {
    return decode_state(read_checkpoint_bytes(path));
}

// The species' temperatures of a saved state, as the run's rows define them.
HcsTemperatures state_temperatures(const StateFile& state, const RunSpec& spec) {
    const Moments m = compute_moments(column_of(state.grains.v.data(), 0), column_of(state.grains.w.data(), 0),
                                      species_slices(make_species_blocks(spec.species, spec.particles)));
    HcsTemperatures T;
    for (const GroupMoments& g : m.species) {
        T.T_tr.push_back(g.T_tr);
        T.T_rot.push_back(g.T_rot);
    }
    return T;
}

// A cooling run from a saved state: the state's temperatures, not the species', set where T_tr/m
// reaches 1e-300 (case_file/run_table.cpp checks the reach of a run from a Maxwellian at the species'
// temperatures; an aged state is much colder and reaches it sooner). Replica 0's state stands for
// the others'.
void check_cooling_reach_from(const StateFile& state, const RunSpec& spec, const CaseConfig& cfg,
                              const std::string& case_file, const std::string& dir) {
    if (spec.shear || spec.kernel != CollisionKernel::hard_sphere || driven(cfg))
        return;
    const std::optional<HcsTheory> theory = hcs_theory(spec);
    if (!theory)
        return; // restitution that depends on the impact speed: the gas cools ever slower
    const HcsTemperatures T = state_temperatures(state, spec);
    if (!std::all_of(T.T_tr.begin(), T.T_tr.end(), [](double t) { return t > 0 && std::isfinite(t); }))
        return; // a gas at rest does not cool
    const bool time = spec.clock == Clock::time;
    double reach = HUGE_VAL;
    try {
        reach = time ? cooling_reach_time(*theory, T, underflow_temperature_per_mass)
                     : cooling_reach(*theory, T, underflow_temperature_per_mass);
    } catch (const std::invalid_argument&) {
        return;
    }
    if (spec.end > reach) {
        const char* key = time ? "run.end_time" : "run.end";
        const std::string when = time ? fmt::format("at about t = {:.4g} from its start (Haff's law: T_tr ~ 1/t^2)", reach)
                                      : fmt::format("at about {:.4g} collisions per particle from its start", reach);
        throw InputError(case_file, key,
                         fmt::format("{} = {}: the state of initial.from = \"{}\" (T_tr = {:.3g} for the first "
                                     "species) cools with constant restitution and reaches T_tr/m = 1e-300 "
                                     "(velocities squared underflow) {}: end it before ({} < {:.4g})",
                                     key, spec.end, dir, T.T_tr[0], when, key, reach));
    }
}

} // namespace

std::string attach_initial_state(RunSpec& spec, const CaseConfig& cfg, const std::string& case_file) {
    if (!cfg.initial || cfg.initial->from.empty())
        return "";
    const std::string& dir = cfg.initial->from;
    const auto refuse = [&](const std::string& why) {
        return InputError(case_file, "initial.from", fmt::format("initial.from = \"{}\": {}", dir, why));
    };
    std::uint64_t files = 0;
    while (fs::exists(state_file_path(dir, files)))
        ++files;
    if (files == 0)
        throw refuse(fmt::format("no {} (a run with run.save_state = true writes it)", state_file_path(dir, 0).string()));
    StateFile first;
    try {
        first = read_state(state_file_path(dir, 0));
    } catch (const StateFileError& e) {
        throw refuse(fmt::format("{}: {}", state_file_path(dir, 0).string(), e.what()));
    } catch (const std::system_error& e) {
        throw refuse(e.what());
    }
    const std::vector<StateSpecies> want = case_species(spec);
    if (first.species != want) {
        std::string have, asked;
        for (const StateSpecies& s : first.species)
            have += (have.empty() ? "" : ", ") + describe(s);
        for (const StateSpecies& s : want)
            asked += (asked.empty() ? "" : ", ") + describe(s);
        throw refuse(fmt::format("{} holds {}; the case has {} (the species and run.particles must be the same)",
                                 state_file_path(dir, 0).string(), have, asked));
    }
    check_cooling_reach_from(first, spec, cfg, case_file, dir);
    const bool positions = !first.grains.x.empty();
    const bool placed = positions && spec.domain && first.grains.box == spec.domain->size;
    if (placed && spec.domain->initial.mode == Perturbation::density)
        throw InputError(case_file, "initial.mode",
                         fmt::format("initial.mode = \"density\" needs fresh positions, but initial.from = \"{}\" "
                                     "gives them (a box of the same size)",
                                     dir));
    // A homogeneous run's theory columns (io/moments_csv.cpp) start from the species' temperatures:
    // those of replica 0's state, where its grains start, not the case's.
    if (!spec.domain) {
        const HcsTemperatures T = state_temperatures(first, spec);
        for (std::size_t i = 0; i < spec.species.size() && i < T.T_tr.size(); ++i) {
            if (std::isfinite(T.T_tr[i]) && std::isfinite(T.T_rot[i]) && T.T_tr[i] >= 0 && T.T_rot[i] >= 0) {
                spec.species[i].temperature = T.T_tr[i];
                spec.species[i].rotational_temperature = T.T_rot[i];
            }
        }
    }
    const std::string d = dir;
    spec.initial_state = [d, files, want](int replica) {
        const fs::path path = state_file_path(d, static_cast<std::uint64_t>(replica) % files);
        StateFile f;
        try {
            f = read_state(path);
        } catch (const StateFileError& e) {
            throw std::runtime_error(path.string() + ": " + e.what());
        }
        if (f.species != want)
            throw std::runtime_error(path.string() + ": other species or grain counts than replica 0's file");
        return std::move(f.grains);
    };
    // The homogeneous gas takes the velocities and spins only (dsmc/init.hpp init_from_state).
    const char* const how = spec.domain ? (placed ? "with their positions" : "at uniform random positions")
                            : positions ? "their velocities and spins only (the homogeneous gas has no positions), "
                                          "the mean velocity removed; time and collisions count from 0"
                                        : "their velocities and spins, the mean velocity removed; time and "
                                          "collisions count from 0";
    return fmt::format("initial state: the grains of {} ({} file{}, replica r takes file r mod {}; replica 0's at "
                       "t = {:.6g}, {:.6g} collisions per particle), {}",
                       state_dir(dir).string(), files, files > 1 ? "s" : "", files, first.grains.t,
                       first.grains.coll_per_particle, how);
}

void attach_final_state(RunSpec& spec, const CaseConfig& cfg, const fs::path& out) {
    if (!cfg.run.save_state)
        return;
    const std::vector<StateSpecies> species = case_species(spec);
    spec.final_state = [out, species](int replica, const GrainState& g) {
        std::error_code ignored; // another replica may be creating it at the same time
        fs::create_directories(state_dir(out), ignored);
        write_file_atomically(state_file_path(out, static_cast<std::uint64_t>(replica)),
                              encode_state(roughgas_version(), species, g));
    };
}

} // namespace roughgas
