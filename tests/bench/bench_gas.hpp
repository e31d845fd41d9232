#pragma once
// The gases the DSMC benchmarks time (dsmc_bench.cpp: Google Benchmark; slices_bench.cpp: kernels
// alternated in short slices within one process). Both time the same thing: chunks of collisions of
// a homogeneous cooling gas, rescaled to its initial temperatures between chunks (not timed).
//
// Each gas: Maxwellian start (seed 1), T = 1, n = 1/sigma^3 (sigma = 2R), unit grains; the ice cases
// in SI units with speeds ~0.1 m/s; steps of one mean free time; warmed up for half a collision per
// particle (steps, rings and pages warm) before anything is timed.
#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/dsmc/engine.hpp"
#include "roughgas/dsmc/init.hpp"
#include "roughgas/dsmc/particles.hpp"
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/dsmc/tables.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>
#include <tuple>
#include <utility>

namespace roughgas::bench {

constexpr std::int64_t bench_chunk = 100000;

template <class Store, class Policy, bool Mixture>
Engine<Store, Policy, Mixture> make_bench_engine(std::int64_t N, const SpeciesSpec& species,
                                                 const Policy& policy, int classes, int groups, int threads) {
    const auto blocks = make_species_blocks({species}, N);
    Store store(static_cast<std::size_t>(N));
    init_maxwellian(store, blocks, 1, 0);
    return Engine<Store, Policy, Mixture>(
        blocks, {policy}, std::move(store),
        EngineOptions{1.0 / std::pow(2 * species.radius, 3), 1.0, 1, 0, classes, groups, threads});
}

// An engine on a benchmark gas, warmed up, with the chunked run the benchmarks time.
template <class Store, class Policy, bool Mixture = false> class BenchGas {
  public:
    // groups = 0: auto_groups(N), what roughgas run uses (run_spec.hpp).
    BenchGas(std::int64_t N, const SpeciesSpec& species, const Policy& policy, int classes = 2,
             int groups = 0, int threads = 1, std::optional<ThermostatSpec> thermostat = std::nullopt)
        : e_(make_bench_engine<Store, Policy, Mixture>(N, species, policy, classes,
                                                       groups == 0 ? auto_groups(N) : groups, threads)),
          // A grouped run meets a collision target in parallel phases and a short serial tail
          // (engine.hpp): chunks of at least a step (N/2 collisions), as run_replica uses.
          chunk_(e_.groups() > 1 ? std::max<std::int64_t>(bench_chunk, N / 2) : bench_chunk) {
        if (thermostat)
            e_.set_thermostat(*thermostat);
        e_.run_collisions(N / 4); // half a collision per particle
        std::tie(v2_0_, w2_0_) = temperatures();
    }

    // One timed chunk, as run_replica runs between two rows (dsmc/drive_impl.hpp): about `chunk()`
    // collisions (Engine::run_about). Returns the collisions done.
    std::int64_t run_chunk() {
        const std::int64_t c0 = e_.collisions();
        e_.run_about(chunk_, std::numeric_limits<std::int64_t>::max(), IgnoreCollisions{});
        return e_.collisions() - c0;
    }
    std::int64_t chunk() const { return chunk_; }

    // The gas cools; velocity-dependent restitution would drift out of its regime (and out of the
    // tangential table's range), so v and omega are scaled back to the initial translational and
    // rotational temperatures whenever one of them has halved (or doubled: a driven gas). Call between
    // timed chunks.
    void rescale_if_cooled() {
        const auto [v2, w2] = temperatures();
        if (v2 >= 0.5 * v2_0_ && w2 >= 0.5 * w2_0_ && v2 <= 2 * v2_0_ && w2 <= 2 * w2_0_)
            return; // (a driven gas may heat instead)
        const double fv = std::sqrt(v2_0_ / v2), fw = w2 > 0 ? std::sqrt(w2_0_ / w2) : 1.0;
        for (std::size_t i = 0; i < e_.store().size(); ++i) {
            e_.store().v(i) *= fv;
            e_.store().w(i) *= fw;
        }
        e_.restart_step();
    }

    Engine<Store, Policy, Mixture>& engine() { return e_; }

  private:
    std::pair<double, double> temperatures() const { // proportional to T_tr and T_rot
        double v2 = 0, w2 = 0;
        for (std::size_t i = 0; i < e_.store().size(); ++i) {
            v2 += norm2(e_.store().v(i));
            w2 += norm2(e_.store().w(i));
        }
        return {v2, w2};
    }

    Engine<Store, Policy, Mixture> e_;
    std::int64_t chunk_;
    double v2_0_ = 0, w2_0_ = 0;
};

inline SpeciesSpec unit_grain() {
    return SpeciesSpec{};
}

// Ice (Brilliantov et al. (1996) Fig. 2c, the restitution benchmark's pair): R = 1 cm, A = 5.3e-5 s,
// zeta_0 = 1e-3 R_eff, mu = sqrt(1e-3); T such that each velocity component has rms 0.1 m/s.
inline ContactPair ice_pair() {
    const double R = 0.01, m = 4.0 / 3.0 * std::numbers::pi * R * R * R * 1000.0;
    const Material mat{1e10, 0.3, 5.3e-5, std::sqrt(1e-3), 1e-3 * R / 2};
    return make_contact_pair(mat, {}, m, R, 0.4, m, R, 0.4);
}
inline SpeciesSpec ice_grain() {
    const ContactPair p = ice_pair();
    SpeciesSpec s;
    s.mass = 2 * p.m_eff;
    s.radius = 2 * p.R_eff;
    s.temperature = s.rotational_temperature = s.mass * 0.01;
    return s;
}
inline const NormalTable& normal_table() {
    static const NormalTable t = NormalTable::build({});
    return t;
}
inline const TangentialTable& tangential_table() {
    static const TangentialTable t = [] {
        // g_N from 1e-6 m/s (as `roughgas run`, RunSpec::table_g_min) to 1 m/s (7 thermal speeds):
        // no collision of this gas falls back to the direct integrator (measured over 4e5). The
        // range below 1e-3 m/s adds nothing measurable to the build (0.7 s), but with g_min = 1e-3
        // 1.5e-4 of the collisions were integrated directly, at ~1 ms each: half the run time.
        TangentialTableOptions opt;
        opt.g_min = 1e-6;
        opt.g_max = 1.0;
        return TangentialTable::build(ice_pair(), opt);
    }();
    return t;
}

// The kernels run_replica selects, as BM_Case_<name> (dsmc_bench.cpp) and slices_bench name them:
// a gas and a restitution policy each; the store is StoreFor<policy>.
struct RoughConstantCase {
    static constexpr std::string_view name = "RoughConstant";
    static SpeciesSpec species() { return unit_grain(); }
    static RoughConstant policy() { return make_rough_constant(0.9, 0.5); }
};
struct SmoothConstantCase {
    static constexpr std::string_view name = "SmoothConstant";
    static SpeciesSpec species() { return unit_grain(); }
    static SmoothConstant policy() { return make_smooth_constant(0.9); }
};
struct SmoothElasticCase {
    static constexpr std::string_view name = "SmoothElastic";
    static SpeciesSpec species() { return unit_grain(); }
    static SmoothConstant policy() { return make_smooth_constant(1.0); }
};
struct CoulombCase {
    static constexpr std::string_view name = "Coulomb";
    static SpeciesSpec species() { return unit_grain(); }
    static Coulomb policy() {
        return make_coulomb(0.9, 0.5, 0.2, make_pair_constants({1, 0.5, 0.4}, {1, 0.5, 0.4}).kappa);
    }
};
struct ViscoelasticSmoothCase {
    static constexpr std::string_view name = "ViscoelasticSmooth";
    static SpeciesSpec species() { return ice_grain(); }
    static ViscoelasticSmooth policy() { return make_viscoelastic_smooth(normal_table(), ice_pair()); }
};
struct ViscoelasticCase {
    static constexpr std::string_view name = "Viscoelastic";
    static SpeciesSpec species() { return ice_grain(); }
    static Viscoelastic policy() { return make_viscoelastic(normal_table(), ice_pair(), 0.5); }
};
struct BrilliantovCase {
    static constexpr std::string_view name = "Brilliantov";
    static SpeciesSpec species() { return ice_grain(); }
    static Brilliantov policy() { return make_brilliantov(normal_table(), tangential_table(), ice_pair()); }
};
// The constant kernels on the particle layouts run_replica does not use (particles.hpp): a case with
// its own `store`.
struct SmoothAoS32Case : SmoothConstantCase {
    static constexpr std::string_view name = "Layout_SmoothAoS32";
    using store = SmoothAoS;
};
struct SmoothPacked24Case : SmoothConstantCase {
    static constexpr std::string_view name = "Layout_SmoothPacked24";
    using store = SmoothPacked;
};
struct RoughAoS64Case : RoughConstantCase {
    static constexpr std::string_view name = "Layout_RoughAoS64";
    using store = RoughAoS;
};
// Driven gases (dsmc/thermostat.hpp): the constant kernels' gases heated by a thermostat whose power
// about balances their cooling at T = 1 (Maxwellian estimate: smooth alpha = 0.9 loses
// (1 - alpha^2)/3 x 4 sqrt(pi) ~ 0.45 of T per unit time; the rough gas some twice that), so that
// they stay near the cooling gases' temperatures: what a driven run's kicks add to the same loop.
inline ThermostatSpec bench_white_noise(double strength) {
    ThermostatSpec t;
    t.species.resize(1);
    t.species[0].drive.value = {strength};
    return t;
}
struct DrivenRoughConstantCase : RoughConstantCase {
    static constexpr std::string_view name = "DrivenRoughConstant";
    static ThermostatSpec thermostat() { return bench_white_noise(1.0); }
};
struct DrivenSmoothConstantCase : SmoothConstantCase {
    static constexpr std::string_view name = "DrivenSmoothConstant";
    static ThermostatSpec thermostat() { return bench_white_noise(0.45); }
};
struct LangevinRoughConstantCase : RoughConstantCase {
    static constexpr std::string_view name = "LangevinRoughConstant";
    static ThermostatSpec thermostat() {
        ThermostatSpec t = bench_white_noise(1.0); // a bath at T_b = 1
        t.kind = ThermostatKind::langevin;
        t.species[0].friction = 1.0;
        t.species[0].rotational_friction = 1.0;
        return t;
    }
};
using Cases =
    std::tuple<RoughConstantCase, SmoothConstantCase, SmoothElasticCase, CoulombCase, ViscoelasticSmoothCase,
               ViscoelasticCase, BrilliantovCase, SmoothAoS32Case, SmoothPacked24Case, RoughAoS64Case,
               DrivenRoughConstantCase, DrivenSmoothConstantCase, LangevinRoughConstantCase>;

// The store of a case: its own, else the one run_replica uses for its policy.
template <class Case> struct CaseStore { using type = StoreFor<decltype(Case::policy())>; };
template <class Case>
requires requires {
    typename Case::store;
}
struct CaseStore<Case> {
    using type = typename Case::store;
};

// The benchmark gas of Case on N grains and `threads` threads.
template <class Case> auto make_case_gas(std::int64_t N, int threads) {
    using Policy = decltype(Case::policy());
    std::optional<ThermostatSpec> thermostat;
    if constexpr (requires { Case::thermostat(); })
        thermostat = Case::thermostat();
    return BenchGas<typename CaseStore<Case>::type, Policy>(N, Case::species(), Case::policy(), 2, 0,
                                                            threads, thermostat);
}

} // namespace roughgas::bench
