#pragma once
// The DSMC of the spatially resolved gas (docs/model.md §8): the Boltzmann equation with its
// streaming term, (d/dt + v.grad) f = J[f, f] (Brilliantov, Spahn, Hertzsch & Poeschel 1996,
// eq. 40), for grains with positions in a box, split into steps of length dt:
//
//   1. free flight: x += v dt + g dt^2/2, v += g dt (omega unchanged), wrapped into [0, L_a) along a
//      periodic axis; along a walled axis the grain meets the wall at 0 or L_a at the exact time of
//      its parabola's crossing, collides with it (collision/wall_rule.hpp) and flies on for the rest
//      of the step (any number of walls per step);
//   2. the grains sorted by collision cell (a uniform grid of n_x x n_y x n_z cells; within each
//      species, so that a species stays one contiguous range of the store and the observables'
//      species slices apply unchanged);
//   3. collisions inside each cell for a time dt, with the collision rule and restitution policies
//      of the homogeneous engine (collision/rule.hpp, collision/sampling.hpp).
//
// Kernel in a cell. The box holds n V physical grains (n = run.density, V = L_x L_y L_z) represented
// by N simulated ones, each standing for F = n V / N. A pair (i, j) of species (a, b) in a cell of
// volume V_c collides at the rate pi sigma_ab^2 |v_i - v_j| F / V_c: the rate of the homogeneous
// engine with the cell for the volume (V_c / F = N / (n C) for C equal cells), so a grain's collision
// frequency is n pi sigma^2 <g> whatever the cell size, in a uniform gas exactly. Sampled without
// approximation (sequential thinning, as the homogeneous engine does): with u_c the cell's mean
// velocity at the step's start and b = max |v_k - u_c| over its grains, g_max = 2 b bounds every
// |v_i - v_j| of the cell; candidates form a Poisson process of rate
// Lambda = N_c (N_c - 1)/2 pi sigma_max^2 g_max F / V_c (sigma_max: the largest pair diameter), each a
// uniformly random pair, accepted with probability sigma_ab^2 |v_i - v_j| / (sigma_max^2 g_max); a
// collision that makes a grain's |v - u_c| exceed b raises b at once (the next increment is drawn
// at the new rate: memoryless, so the majorant is never exceeded). A grain may collide any number
// of times in a step (the once-per-step variant has a first-order time-step error in the
// viscosity). The candidate that would fall after dt is discarded (memoryless again).
// With domain.partners = "nearest" the candidate's first grain is uniform in the cell and its
// partner the nearest other grain of the cell but the first grain's most recent partner, in this
// step or an earlier one, when the cell holds more than two (grains carry an identity and their
// last partner's for this). Without that rule two neighbours, still neighbours a step later,
// collide again and again: repeated collisions relax the stress less than collisions with fresh
// partners, and the viscosity comes out too large (Bird 2007; Gallis, Torczynski, Rader & Bird
// 2009). The rate and the acceptance are unchanged: where velocities do not depend on positions (a
// uniform gas) the pair's |g| has the random pair's distribution and the collision frequency stays
// exact, and the separation of the colliding grains, which sets the cell-size error of the
// transport coefficients, shrinks from the cell's size to the spacing of its grains.
//
// Threads. Each step's collisions run over work units of a fixed number of cells, claimed
// dynamically by the replica's WorkerTeam; unit u draws from the stream (seed, cell_collisions,
// replica, step, u) and has its own observer copy, merged in unit order: the results depend on
// the cells per unit (fixed), never on the thread count. The flight runs over fixed chunks of
// grains, the sort over chunks fixed by the grain and cell counts (sort_into_cells).
//
// Spins. Rough grains' spins move with them in the sort, beside positions and velocities, since
// every collision reads and changes them. Smooth grains never change theirs (no collision, flight
// or wall of a smooth gas acts on them): they stay in place, indexed by the grain's identity, and
// the sort moves the 4-byte identity instead of the 24-byte spin. The rows that read the spins
// gather them into store order (angular_velocities()), so every output is the same, bit for bit,
// as if the spins had moved with their grains.
//
// Thermostat (set_thermostat; dsmc/thermostat.hpp): a uniformly heated gas. Each step starts with
// the kicks, in the flight's pass over the grains: each chunk of the flight (65536 grains of one
// species) kicks its grains' velocities (and spins) before flying them, so the kicks cost no pass of
// their own (with exact energy, one pass more that sums what the kicks would inject). The kicks of
// the step starting at t0 cover [kicked_until(), t0 + dt/2], as in the homogeneous engine: half a step
// ahead at the step's start, half a step behind at its end. The law, the per-species zero-sum bridge
// over the chunks and the streams (seed, thermostat, replica, step, species and chunk) are the
// homogeneous engine's, with the flight's chunks: fixed by the species' grain counts, so the kicks
// depend neither on the threads nor on the cells. A kick changes velocities and spins only: a heated
// box keeps its positions, walls and gravity; each species' kicks of a step sum to zero momentum, so
// they never push the gas, walls or not. A sheared box (Lees-Edwards) takes no thermostat: uniform shear flow
// heats the gas itself.
//
// Enskog collisions (set_enskog; docs/model.md, "The Enskog equation in a box"). The Enskog equation
// (Enskog 1922) collides grain i at r with grains at r + sigma_ab k^, its collision operator's loss
// term for i being sigma_ab^2 Int dk^ chi_ab(r + sigma_ab k^/2) Int dv_j f_b(r + sigma_ab k^, v_j)
// Theta(g.k^) (g.k^), g = v_i - v_j. Its DSMC (Montanero & Santos 1996; Frezzotti 1997): f_b at the
// point r + sigma_ab k^ is the cell holding that point, N'_b grains standing for F N'_b / V_c of
// density. A candidate is a grain i of cell c (uniform), a species b (uniform), a direction k^, and a
// grain j of species b in the cell of r_i + sigma_ab k^ (uniform; none beyond a wall). With U(c) the
// smoothed flow of dsmc/enskog_cells.hpp and B a bound of |v - U(c)| over the grains of c and of
// every cell a partner can lie in, (g.k^)+ <= B + a.k^ with a = v_i - U(c): k^ is drawn with the
// density (B + a.k^)/(4 pi B) (uniform with probability 1 - |a|/B, else with density (1 + a^.k^)/4 pi),
// and the candidate accepted with probability sigma_ab^2 chi_ab N'_b (g.k^)+ / (W N_max (B + a.k^)),
// chi_ab that of the cell holding the pair's midpoint, W and N_max the largest sigma_ab^2 chi_ab and
// N'_b over the cells a partner of c can lie in. Candidates of cell c then form a Poisson process of
// rate (1/2) N_c S 4 pi W N_max B F / V_c (the a.k^ term integrates to zero): each pair's collisions
// are sampled half from each grain's cell. The collision is the rule's with the normal n = -k^ (from
// j to i), whatever the grains' actual separation within their cells, and the impulse times that
// separation (through the periodic images) is the virial of the pressure and the profiles: momentum
// and energy move across sigma. B = max |v_j - U(c')| + max |U(c) - U(c')| + eps over the reach:
// eps is the largest excess of a grain over its cell's floor (the least bound of the cells whose
// reach holds it) that a collision has made so far in the step, so B stays a bound as collisions
// speed grains up (a rise in one block reaches the blocks of later colours through eps). The blocks
// of cells of dsmc/enskog_cells.hpp collide colour by colour, each block on one worker with the
// stream (seed, cell_collisions, replica, step, block): the collisions depend on the blocks (fixed by
// the cells and sigma), never on the threads. A pair's virial goes to the profile slabs its segment crosses, in proportion to the
// length in each (Irving & Kirkwood 1950), so the profiles' collisional stress balances the walls'.
//
// Compiled twice: `General` = false for a periodic box without gravity (a flight that only adds and
// wraps), true for walls or gravity (the exact crossing times, the walls' random emission from the
// stream (seed, wall_emission, replica, step, chunk) and their momentum and energy tallies).
#include "roughgas/collision/pair_constants.hpp"
#include "roughgas/collision/record.hpp"
#include "roughgas/collision/rule.hpp"
#include "roughgas/collision/sampling.hpp"
#include "roughgas/collision/wall_rule.hpp"
#include "roughgas/core/bytes.hpp"
#include "roughgas/core/huge_page_buffer.hpp"
#include "roughgas/core/own_lines.hpp"
#include "roughgas/core/prefetch.hpp"
#include "roughgas/core/rng.hpp"
#include "roughgas/core/vec.hpp"
#include "roughgas/core/worker_team.hpp"
#include "roughgas/dsmc/enskog_cells.hpp"
#include "roughgas/dsmc/init.hpp"
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/dsmc/species.hpp"
#include "roughgas/dsmc/thermostat.hpp"
#include "roughgas/observables/moments.hpp"

#include <boost/random/exponential_distribution.hpp>
#include "roughgas/observables/profiles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace roughgas {

// What the grains gave one wall since the start: hits, momentum (sum of m (v_before - v_after)) and
// energy (translational and rotational kinetic energy lost by the grains).
struct WallFlux {
    double hits = 0;
    Vec3 momentum{};
    double energy = 0;
    WallFlux& operator+=(const WallFlux& o) {
        hits += o.hits;
        momentum += o.momentum;
        energy += o.energy;
        return *this;
    }
};
// Wall 2a is the lower wall of axis a (at 0, normal +e_a into the gas), wall 2a + 1 the upper one
// (at L_a, normal -e_a).
using WallFluxes = std::array<WallFlux, 6>;

inline void save(ByteWriter& out, const WallFluxes& fluxes) {
    for (const WallFlux& f : fluxes)
        for (double c : {f.hits, f.momentum.x, f.momentum.y, f.momentum.z, f.energy})
            out.f64(c);
}
inline void load(ByteReader& in, WallFluxes& fluxes) {
    for (WallFlux& f : fluxes) {
        f.hits = in.f64();
        f.momentum.x = in.f64();
        f.momentum.y = in.f64();
        f.momentum.z = in.f64();
        f.energy = in.f64();
    }
}

template <class Policy, bool General = false> class SpatialEngine {
  public:
    static constexpr bool rough = Policy::needs_rotation;
    // A grain that would meet a wall more often in one step (an inelastic grain coming to rest on
    // a floor under gravity meets it infinitely often in a finite time) stays where the last wall
    // left it for the rest of the step.
    static constexpr int max_wall_hits_per_step = 64;
    // Cells per work unit of the collision phase: enough work per unit to amortise claiming it and
    // seeding its stream (a few hundred grains), small enough to balance two threads on small boxes.
    static constexpr std::size_t cells_per_unit = 64;

    // `policies[k]` is the restitution policy of species pair k (pair_index order, run_spec.hpp).
    // The initial state: positions uniform in the box (stream initial_position, one per species),
    // velocities and spins Maxwellian (dsmc/init.hpp), the total momentum removed.
    // `kernel`: hard spheres, or the Maxwell kernel of the homogeneous engine (every pair of species
    // (a, b) in a cell collides at the constant rate pi sigma_ab^2 u_ab F / V_c, u_ab from the
    // species' initial temperatures, the impact normal uniform on the approaching hemisphere).
    // `initial_state` set: the grains start from initial_state(replica) instead (RunSpec::initial_state).
    SpatialEngine(const DomainSpec& domain, std::vector<SpeciesBlock> blocks, std::vector<Policy> policies,
                  double density, std::uint64_t seed, std::uint64_t replica, int threads,
                  CollisionKernel kernel = CollisionKernel::hard_sphere,
                  const GrainStateSource& initial_state = {})
        : domain_(domain), blocks_(std::move(blocks)), types_(make_pair_types(blocks_)),
          policies_(std::move(policies)), density_(density), seed_(seed), replica_(replica),
          team_(std::make_unique<WorkerTeam>(std::max(1, threads))), maxwell_(kernel == CollisionKernel::maxwell) {
        if (policies_.size() != types_.size())
            throw std::invalid_argument("SpatialEngine: one policy per species pair needed");
        if (!General && domain_.general_flight())
            throw std::invalid_argument("SpatialEngine: walls, gravity and Lees-Edwards need the General flight");
        if (domain_.lees_edwards() && (domain_.walled(0) || domain_.walled(1)))
            throw std::invalid_argument("SpatialEngine: Lees-Edwards boundaries need x and y periodic");
        for (const SpeciesBlock& b : blocks_)
            wall_pc_.push_back(wall_pair_constants(b.grain));
        for (const WallSpec* w : domain_.walls_in_use()) {
            if (w->kind == WallKind::rough && !rough && w->beta != -1)
                throw std::invalid_argument("SpatialEngine: a rough wall (beta > -1) needs rough grains");
            if (w->kind == WallKind::rough && !(w->alpha > 0 && w->alpha <= 1 && std::abs(w->beta) <= 1))
                throw std::invalid_argument("SpatialEngine: a rough wall needs 0 < alpha <= 1, |beta| <= 1");
        }
        for (int a = 0; a < 3; ++a)
            if (!(domain_.size[a] > 0) || domain_.cells[a] < 1)
                throw std::invalid_argument("SpatialEngine: box sizes must be > 0 and cells >= 1");
        cells_ = static_cast<std::size_t>(domain_.cells[0]) * domain_.cells[1] * domain_.cells[2];
        for (int a = 0; a < 3; ++a)
            cells_per_length_[a] = domain_.cells[a] / domain_.size[a];
        for (const SpeciesBlock& b : blocks_)
            particles_ += b.count;
        if (particles_ < 2)
            throw std::invalid_argument("SpatialEngine: at least two particles needed");
        if (particles_ >= (std::size_t{1} << 32) || cells_ >= (std::size_t{1} << 32))
            throw std::invalid_argument("SpatialEngine: at most 2^32 - 1 grains and cells (32-bit offsets)");
        for (const PairType& t : types_) {
            cs_max_ = std::max(cs_max_, t.pc.cross_section);
            // u_ab = sqrt((8/pi)(T_a/m_a + T_b/m_b)) at the initial temperatures (observables/theory.hpp).
            const double u = std::sqrt(8.0 / std::numbers::pi *
                                       (blocks_[t.a].temperature / blocks_[t.a].grain.mass +
                                        blocks_[t.b].temperature / blocks_[t.b].grain.mass));
            maxwell_rate_.push_back(t.pc.cross_section * u);
            maxwell_rate_max_ = std::max(maxwell_rate_max_, maxwell_rate_.back());
        }
        for (std::vector<Vec3>* a : {&x_, &v_, &w_})
            resize_on_huge_pages(*a, particles_);
        if (domain_.profile_axis < 0 || domain_.profile_axis > 2)
            throw std::invalid_argument("SpatialEngine: the profile axis must be 0, 1 or 2");
        cell_virial_.assign(cells_, Virial{});
        cell_tally_.assign(cells_ * blocks_.size() * cell_sum_fields, 0.0);
        bin_virial_.assign(static_cast<std::size_t>(domain_.cells[domain_.profile_axis]), Virial{});
        const InitialSpec& wave = domain_.initial;
        for (int a = 0; a < 3; ++a)
            k_[a] = 2.0 * std::numbers::pi * wave.wave[a] / domain_.size[a];
        const bool density_wave = wave.mode == Perturbation::density;
        GrainState from;
        const bool from_state = static_cast<bool>(initial_state);
        if (from_state) {
            from = initial_state(static_cast<int>(replica));
            if (from.v.size() != particles_ || from.w.size() != particles_ ||
                (!from.x.empty() && from.x.size() != particles_))
                throw std::invalid_argument("SpatialEngine: the initial state has another number of grains");
        }
        // An earlier box of the same size gives the positions too (x is then kept as it was).
        const bool placed = !from.x.empty() && from.box == domain_.size;
        // Copied, not moved in: the engine's own arrays are on huge pages (resize_on_huge_pages).
        if (placed)
            std::copy(from.x.begin(), from.x.end(), x_.begin());
        for (std::size_t s = 0; s < blocks_.size() && !placed; ++s) {
            Rng r = make_stream(StreamKey{seed, Stream::initial_position, replica, 0, s});
            for (std::size_t i = blocks_[s].offset; i < blocks_[s].offset + blocks_[s].count; ++i) {
                for (;;) { // a density wave by rejection: accepted with (1 + A sin(k.x))/(1 + |A|)
                    x_[i] = {domain_.size[0] * uniform01(r), domain_.size[1] * uniform01(r),
                             domain_.size[2] * uniform01(r)};
                    if (!density_wave ||
                        uniform01(r) * (1 + std::abs(wave.amplitude)) < 1 + wave.amplitude * std::sin(phase(x_[i])))
                        break;
                }
            }
        }
        nearest_ = domain_.partners == PartnerSelection::nearest;
        if (nearest_ || !rough) { // identities = initial store indices, so spin(i) = w_[i] until the first sort
            id_.resize(particles_);
            for (std::size_t i = 0; i < particles_; ++i)
                id_[i] = static_cast<std::uint32_t>(i);
        }
        if (nearest_)
            last_.assign(particles_, no_partner);
        if (from_state) {
            std::copy(from.v.begin(), from.v.end(), v_.begin());
            std::copy(from.w.begin(), from.w.end(), w_.begin());
        } else {
            init_maxwellian(*this, blocks_, seed, replica);
        }
        perturb_velocities(from_state);
        if (domain_.lees_edwards()) { // the uniform shear flow u_x = a (y - L_y/2) of the images
            for (std::size_t i = 0; i < particles_; ++i)
                v_[i].x += domain_.shear_rate * (x_[i].y - 0.5 * domain_.size[1]);
            remove_mean_velocity(*this, blocks_);
        }
        sort_into_cells();
    }

    // The wave's amplitudes in the current state (InitialSpec's k; the velocity direction e of a
    // transverse wave, k/|k| for the others), each (2/N) sum over the
    // grains of a grain's quantity times sin(k.x): u_wave = that of v.e; n_wave = of 1 (the
    // relative density wave); e_wave = of (1/2) m |v|^2 over the mean of it (the relative wave of
    // the translational energy density).
    std::array<double, 3> wave_amplitudes() const {
        const Vec3 e = wave_direction();
        double u = 0, n = 0, en = 0, E = 0;
        for (const SpeciesBlock& b : blocks_)
            for (std::size_t i = b.offset; i < b.offset + b.count; ++i) {
                const double s = std::sin(phase(x_[i])), ei = 0.5 * b.grain.mass * norm2(v_[i]);
                u += dot(v_[i], e) * s;
                n += s;
                en += ei * s;
                E += ei;
            }
        const double f = 2.0 / static_cast<double>(particles_);
        return {f * u, f * n, E > 0 ? 2.0 * en / E : 0.0};
    }

    // The store interface of dsmc/init.hpp, for the initial state only: a velocity changed between
    // steps would not reach the cells' sums of collision_frequency(), taken in the last step.
    Vec3& v(std::size_t i) { return v_[i]; }
    Vec3& w(std::size_t i) { return spin(i); }

    // The thermostat that drives the gas (see "Thermostat"): set before the first step, and before
    // restore() (its state holds the time the kicks reached).
    void set_thermostat(ThermostatSpec th) {
        if (th.species.size() != blocks_.size())
            throw std::invalid_argument("SpatialEngine: one thermostat entry per species");
        if (domain_.lees_edwards())
            throw std::invalid_argument("SpatialEngine: a sheared box (Lees-Edwards) takes no thermostat: uniform "
                                        "shear flow heats the gas itself");
        thermostat_ = std::move(th);
        kicks_.assign(blocks_.size(), {});
    }
    const std::optional<ThermostatSpec>& thermostat() const { return thermostat_; }
    // The time up to which the thermostat's kicks have been given (see "Thermostat").
    double kicked_until() const { return t_kick_; }

    // Collide by the Enskog equation (see "Enskog collisions"), before the first step: `chi` the pair
    // correlation of every pair type at the box's mean density (the step length's collision frequency),
    // `chi_constant` > 0 for a constant chi (else BMCSL's of the local densities), `smoothing` the
    // smoothing cube's cells per side (odd). Random partners and hard spheres only; a periodic side
    // must be at least two diameters long (a grain never meets its own image).
    void set_enskog(const std::vector<double>& chi, double chi_constant, int smoothing) {
        if (maxwell_ || nearest_)
            throw std::invalid_argument("SpatialEngine: Enskog collisions need hard spheres and random partners");
        if (chi.size() != types_.size())
            throw std::invalid_argument("SpatialEngine: one chi per species pair");
        std::vector<double> sigma;
        double sigma_max = 0;
        for (const SpeciesBlock& b : blocks_) {
            sigma.push_back(2 * b.grain.radius);
            sigma_max = std::max(sigma_max, sigma.back());
        }
        CellGrid grid;
        std::array<double, 3> h{};
        for (int a = 0; a < 3; ++a) {
            const auto k = static_cast<std::size_t>(a);
            grid.n[k] = domain_.cells[k];
            grid.periodic[k] = !domain_.walled(a);
            h[k] = domain_.size[k] / domain_.cells[k];
            if (grid.periodic[k] && domain_.size[k] < 2 * sigma_max)
                throw std::invalid_argument("SpatialEngine: a periodic side of an Enskog box must be at least two "
                                            "grain diameters long");
        }
        for (std::size_t t = 0; t < types_.size(); ++t)
            types_[t].chi = chi[t];
        enskog_.emplace(grid, std::move(sigma), h, smoothing, chi_constant, domain_.shear_rate);
        chi_uniform_ = chi_constant > 0;
        speed_start_.assign(cells_, 0.0);
        speed_now_.assign(cells_, 0.0);
    }
    bool enskog() const { return enskog_.has_value(); }
    // The blocks of the Enskog collisions (dsmc/enskog_cells.hpp).
    const EnskogCells* enskog_cells() const { return enskog_ ? &*enskog_ : nullptr; }

    // One step of length dt: kicks and flight, sort, collisions. `obs(record, pair_type)` sees every
    // collision (ForkableObserver of dsmc/engine.hpp: a copy per work unit, merged in unit order).
    template <class Observer> void step(double dt, Observer& obs) {
        plan_kicks(dt);
        if constexpr (General)
            stream_general(dt);
        else
            stream(dt);
        sort_into_cells();
        if (enskog_) {
            collide_enskog(dt, obs);
            add_cell_virials();
            t_ += dt;
            ++steps_;
            return; // the cells' sums are taken on demand: a cell's grains change after it collided
        }
        const std::size_t units = (cells_ + cells_per_unit - 1) / cells_per_unit;
        const bool nearest = nearest_;
        // Each unit's observer and count in cache lines of their own (core/own_lines.hpp says why).
        struct alignas(64) Unit {
            Observer observer;
            std::int64_t collisions = 0;
        };
        std::vector<Unit> local;
        local.reserve(units);
        for (std::size_t u = 0; u < units; ++u)
            local.push_back(Unit{obs.fork(), 0}); // fork()'s own, not copies of one (Tally::fork's spacing)
        team_->for_each(units, [&](std::size_t u) {
            CollisionRng rng = make_collision_stream(StreamKey{seed_, Stream::cell_collisions, replica_, static_cast<std::uint64_t>(steps_), u});
            const std::size_t end = std::min(cells_, (u + 1) * cells_per_unit);
            Unit& unit = local[u];
            for (std::size_t c = u * cells_per_unit; c < end; ++c) {
                if (maxwell_)
                    unit.collisions += nearest ? collide_cell<true, true>(c, dt, rng, unit.observer)
                                               : collide_cell<false, true>(c, dt, rng, unit.observer);
                else
                    unit.collisions += nearest ? collide_cell<true, false>(c, dt, rng, unit.observer)
                                               : collide_cell<false, false>(c, dt, rng, unit.observer);
                tally_cell(c);
            }
        });
        for (const Unit& unit : local) {
            obs.merge(unit.observer);
            collisions_ += unit.collisions;
        }
        add_cell_virials();
        t_ += dt;
        ++steps_;
        tallies_valid_ = true;
    }
    // A step that ends at t_end exactly (the time clock's rows: every replica's at the same t), not
    // at t + (t_end - t), which may differ from t_end in the last bit.
    template <class Observer> void step_to(double t_end, Observer& obs) {
        step(t_end - t_, obs);
        t_ = t_end;
    }

    // Per (cell, species), cells x fastest (i_x + n_x (i_y + n_y i_z)): the count of the grains as they
    // are now, the sum of their velocities and the sum of |v|^2 (cell_sum_fields numbers, in store
    // order). Those the last step's collisions left (tally_cell, while each cell was in the cache),
    // else one pass over the cells: either way the same sums in the same order, so a resumed run
    // takes the same steps and writes the same rows.
    static constexpr std::size_t cell_sum_fields = 5;
    const std::vector<double>& cell_sums() {
        if (!tallies_valid_) {
            for_each_cell([&](std::size_t c) { tally_cell(c); });
            tallies_valid_ = true;
        }
        return cell_tally_;
    }

    // Per (cell, species), cells x fastest: the sum of |omega|^2 of the cell's grains, in store order
    // (modes.csv's T_rot; a pass over the spins at the rows that need it, not at every step).
    std::vector<double> cell_spin_sums() {
        const std::size_t S = blocks_.size();
        std::vector<double> sums(cells_ * S, 0.0);
        const std::vector<Vec3>& w = angular_velocities();
        for_each_cell([&](std::size_t c) {
            for (std::size_t s = 0; s < S; ++s) {
                const auto [first, last] = cell_range(s, c);
                double w2 = 0;
                for (std::size_t i = first; i < last; ++i)
                    w2 += norm2(w[i]);
                sums[c * S + s] = w2;
            }
        });
        return sums;
    }

    // f(c) for every cell, in work units of cells_per_unit cells on the team (each cell by one
    // worker: what f sums per cell does not depend on the threads).
    template <class F> void for_each_cell(F&& f) {
        const std::size_t units = (cells_ + cells_per_unit - 1) / cells_per_unit;
        team_->for_each(units, [&](std::size_t u) {
            const std::size_t end = std::min(cells_, (u + 1) * cells_per_unit);
            for (std::size_t c = u * cells_per_unit; c < end; ++c)
                f(c);
        });
    }

    // The largest local collision frequency per grain: over the profile bins (the slabs of
    // profiles.csv), the Maxwellian n_b pi sigma^2 <g> per pair type at the slab's densities and
    // species temperatures (m <|v - u_b|^2>/3 about the species' mean velocity in the slab). The
    // unit of the step length (domain.time_step): the densest, hottest slab keeps its steps per
    // collision (a heated bed's floor, a cluster's slab), where the box's mean frequency would give
    // it steps of several of its mean free times. In a uniform gas the slabs' sampling noise makes
    // it a few per cent above the mean.
    double collision_frequency() {
        const std::size_t S = blocks_.size(), B = bin_virial_.size();
        const int a = domain_.profile_axis;
        constexpr std::size_t fields = cell_sum_fields;
        cell_sums();
        // Per (bin, species): the cells' sums in cell order (never the threads').
        const std::size_t nx = static_cast<std::size_t>(domain_.cells[0]), ny = static_cast<std::size_t>(domain_.cells[1]),
                          nz = static_cast<std::size_t>(domain_.cells[2]), row = S * fields;
        std::vector<double> total(B * row, 0.0); // (bin, species, field)
        const double* from = cell_tally_.data();
        for (std::size_t z = 0; z < nz; ++z)
            for (std::size_t y = 0; y < ny; ++y)
                for (std::size_t x = 0; x < nx; ++x, from += row) {
                    double* to = total.data() + (a == 0 ? x : a == 1 ? y : z) * row;
                    for (std::size_t k = 0; k < row; ++k)
                        to[k] += from[k];
                }
        double nu_max = 0;
        std::vector<double> T_over_m(S);
        std::vector<PairType> types = types_;
        const double bin_volume = volume() / static_cast<double>(B);
        for (std::size_t b = 0; b < B; ++b) {
            double in_bin = 0;
            for (std::size_t s = 0; s < S; ++s) {
                const double* f = &total[(b * S + s) * fields];
                const double n = f[0];
                in_bin += n;
                // About the species' mean velocity in the slab (walls and gravity make flows); the
                // Maxwell kernel's rates stay those of the initial temperatures.
                const Vec3 mean = n > 0 ? (1.0 / n) * Vec3{f[1], f[2], f[3]} : Vec3{};
                T_over_m[s] = maxwell_            ? blocks_[s].temperature / blocks_[s].grain.mass
                              : n > 0 ? std::max(0.0, f[4] / n - norm2(mean)) / 3.0
                                      : 0.0;
            }
            if (in_bin < 2)
                continue;
            for (PairType& t : types) {
                const double na = total[(b * S + t.a) * fields], nb = total[(b * S + t.b) * fields];
                t.pairs = t.a == t.b ? 0.5 * na * (na - 1) : na * nb;
            }
            nu_max = std::max(nu_max, maxwellian_collision_frequency(types, T_over_m, bin_volume, in_bin));
        }
        return nu_max;
    }

    // The peculiar velocity of grain i after a free flight of s: v minus the uniform shear flow of
    // the Lees-Edwards images, a (y - L_y/2) along x, at its position then (a crossing of y = L_y
    // changes v_x and the flow there alike); v itself without them.
    Vec3 peculiar_velocity(std::size_t i, double s = 0) const {
        const double y = x_[i].y + s * v_[i].y + 0.5 * s * s * domain_.gravity[1];
        return {v_[i].x - domain_.shear_rate * (y - 0.5 * domain_.size[1]), v_[i].y + s * domain_.gravity[1],
                v_[i].z};
    }

    // The simulated volume N/n (the homogeneous engine's): energies per unit volume use it.
    double volume() const { return static_cast<double>(particles_) / density_; }
    double time() const { return t_; }
    std::int64_t collisions() const { return collisions_; }
    std::int64_t steps() const { return steps_; }
    std::size_t particles() const { return particles_; }
    std::size_t cells() const { return cells_; }
    const WallFluxes& wall_fluxes() const { return wall_flux_; }
    // The collisional virial sums of each profile bin since the last call (observables/profiles.hpp),
    // in the simulated grains' units; zeroed.
    std::vector<Virial> take_virial() {
        std::vector<Virial> v(bin_virial_.size(), Virial{});
        v.swap(bin_virial_);
        return v;
    }
    const DomainSpec& domain() const { return domain_; }
    const std::vector<SpeciesBlock>& species() const { return blocks_; }
    const std::vector<PairType>& pair_types() const { return types_; }
    // The store's bytes per grain: positions and velocities twice (the sort), rough grains' spins
    // twice or smooth grains' once with their identity twice, the cell key, with nearest partners
    // the identities and last partners twice.
    std::size_t bytes_per_particle() const {
        return 4 * sizeof(Vec3) + (rough ? 2 * sizeof(Vec3) : sizeof(Vec3)) + sizeof(std::uint32_t) +
               (id_.empty() ? 0 : 2 * sizeof(std::uint32_t)) + (last_.empty() ? 0 : 2 * sizeof(std::uint32_t));
    }
    const std::vector<Vec3>& positions() const { return x_; }
    const std::vector<Vec3>& velocities() const { return v_; }
    // The spins in store order (valid until the next step). Smooth grains': gathered once per state
    // into the positions' free second copy. With random partners the identities mean nothing else,
    // so the gathered copy becomes the spins and the identities are renumbered to the store's
    // order: the next gather then follows only the grains' moves since this one (mostly to nearby
    // cells, within the cache) instead of a random permutation of the whole store.
    const std::vector<Vec3>& angular_velocities() {
        if constexpr (rough) {
            return w_;
        } else {
            if (spins_gathered_ != steps_) {
                const std::size_t chunk = 65536, units = (particles_ + chunk - 1) / chunk;
                team_->for_each(units, [&](std::size_t u) {
                    const std::size_t end = std::min(particles_, (u + 1) * chunk);
                    for (std::size_t i = u * chunk; i < end; ++i) {
                        if (i + 16 < end)
                            prefetch_line(&w_[id_[i + 16]]);
                        x2_[i] = w_[id_[i]];
                    }
                });
                if (!nearest_) {
                    w_.swap(x2_);
                    for (std::size_t i = 0; i < particles_; ++i)
                        id_[i] = static_cast<std::uint32_t>(i);
                }
                spins_gathered_ = steps_;
            }
            return nearest_ ? x2_ : w_;
        }
    }
    WorkerTeam& team() { return *team_; }
    // Grains of species s in cell c: the store's range [first, last) (valid until the next step).
    std::pair<std::size_t, std::size_t> cell_range(std::size_t s, std::size_t c) const {
        const std::size_t k = s * (cells_ + 1) + c;
        return {cell_start_[k], cell_start_[k + 1]};
    }
    // The cell of a position (the last cell for a coordinate that rounds onto the upper face).
    std::size_t cell_of(const Vec3& x) const {
        const auto index = [&](double q, int a) {
            const int k = static_cast<int>(q * cells_per_length_[a]);
            return static_cast<std::size_t>(std::clamp(k, 0, domain_.cells[a] - 1));
        };
        return (index(x.z, 2) * domain_.cells[1] + index(x.y, 1)) * domain_.cells[0] + index(x.x, 0);
    }

    // The grains as they are now, for a later run to start from (dsmc/grain_state.hpp); in a sheared
    // box their velocities about the flow u_x = a (y - L_y/2) at their positions, as the rows see them.
    GrainState grain_state() const {
        GrainState g;
        g.box = domain_.size;
        g.t = t_;
        g.x = x_;
        g.v = v_;
        g.w.resize(particles_);
        for (std::size_t i = 0; i < particles_; ++i)
            g.w[i] = spin(i);
        if (domain_.lees_edwards())
            for (std::size_t i = 0; i < particles_; ++i)
                g.v[i].x -= domain_.shear_rate * (x_[i].y - 0.5 * domain_.size[1]);
        return g;
    }

    // The complete state (positions, velocities, spins, time, step and collision counts, with
    // nearest partners the identities and last partners, with a thermostat the time its kicks
    // reached): a run continued from it draws the same numbers as one without the stop (the streams
    // are keyed by the step).
    void save(ByteWriter& out) const {
        for (int a = 0; a < 3; ++a) { // positions, velocities, spins (in store order)
            out.u64(particles_);
            for (std::size_t i = 0; i < particles_; ++i) {
                const Vec3& q = a == 0 ? x_[i] : a == 1 ? v_[i] : spin(i);
                for (double c : {q.x, q.y, q.z})
                    out.f64(c);
            }
        }
        out.f64(t_);
        out.put(steps_);
        out.put(collisions_);
        if (domain_.has_walls())
            roughgas::save(out, wall_flux_);
        for (const Virial& b : bin_virial_)
            for (double c : b)
                out.f64(c);
        if (nearest_)
            for (const std::vector<std::uint32_t>* a : {&id_, &last_})
                for (std::uint32_t q : *a)
                    out.put(q);
        if (thermostat_)
            out.f64(t_kick_);
    }
    void restore(ByteReader& in) {
        // Smooth grains' spins arrive in store order: into x2_ until the identities are known.
        for (std::vector<Vec3>* a : {&x_, &v_, rough ? &w_ : &x2_}) {
            if (in.count(3 * sizeof(double)) != particles_)
                throw std::runtime_error("the state has another number of particles");
            for (Vec3& q : *a) {
                q.x = in.f64();
                q.y = in.f64();
                q.z = in.f64();
            }
        }
        t_ = in.f64();
        steps_ = in.get<std::int64_t>();
        collisions_ = in.get<std::int64_t>();
        if (domain_.has_walls())
            roughgas::load(in, wall_flux_);
        for (Virial& b : bin_virial_)
            for (double& c : b)
                c = in.f64();
        if (nearest_) {
            for (std::vector<std::uint32_t>* a : {&id_, &last_})
                for (std::uint32_t& q : *a)
                    q = in.get<std::uint32_t>();
        } else if constexpr (!rough) {
            for (std::size_t i = 0; i < particles_; ++i)
                id_[i] = static_cast<std::uint32_t>(i);
        }
        if (thermostat_)
            t_kick_ = in.f64();
        if constexpr (!rough)
            for (std::size_t i = 0; i < particles_; ++i)
                w_[id_[i]] = x2_[i];
        sort_into_cells();
    }

  private:
    // The spin of the grain at store index i.
    Vec3& spin(std::size_t i) {
        if constexpr (rough)
            return w_[i];
        else
            return w_[id_[i]];
    }
    const Vec3& spin(std::size_t i) const {
        if constexpr (rough)
            return w_[i];
        else
            return w_[id_[i]];
    }

    double phase(const Vec3& x) const { return k_[0] * x.x + k_[1] * x.y + k_[2] * x.z; }

    Vec3 wave_direction() const {
        const Vec3 k{k_[0], k_[1], k_[2]};
        const double kk = std::sqrt(norm2(k));
        switch (domain_.initial.mode) {
        case Perturbation::longitudinal:
            return kk > 0 ? (1.0 / kk) * k : Vec3{1, 0, 0};
        case Perturbation::transverse: {
            if (k.y == 0)
                return {0, 1, 0};
            if (k.z == 0)
                return {0, 0, 1};
            const Vec3 e = cross(k, Vec3{1, 0, 0});
            return (1.0 / std::sqrt(norm2(e))) * e;
        }
        default: // density and temperature waves: the flow they set up runs along k
            return kk > 0 ? (1.0 / kk) * k : Vec3{1, 0, 0};
        }
    }

    // The initial wave of InitialSpec on the Maxwellian velocities (after the total momentum was
    // removed: a whole number of wavelengths carries none), or on those of a state the run starts
    // from (`from_state`).
    void perturb_velocities(bool from_state) {
        const InitialSpec& wave = domain_.initial;
        if (wave.mode == Perturbation::none || wave.mode == Perturbation::density)
            return;
        // c = sqrt(T/m) of the mean T and m: the species' temperatures, or the translational
        // temperature of a state the run starts from (an aged cooling state is much colder).
        double T = 0, m = 0;
        for (const SpeciesBlock& b : blocks_) {
            m += b.grain.mass * static_cast<double>(b.count);
            if (!from_state) {
                T += b.temperature * static_cast<double>(b.count);
                continue;
            }
            for (std::size_t i = b.offset; i < b.offset + b.count; ++i)
                T += b.grain.mass * norm2(v_[i]) / 3;
        }
        const double c = std::sqrt(T / m);
        const Vec3 e = wave_direction();
        for (std::size_t i = 0; i < particles_; ++i) {
            const double s = std::sin(phase(x_[i]));
            if (wave.mode == Perturbation::temperature) {
                const double f = std::sqrt(1 + wave.amplitude * s);
                v_[i] = f * v_[i];
                spin(i) = f * spin(i);
            } else {
                v_[i] += (wave.amplitude * c * s) * e;
            }
        }
        remove_mean_velocity(*this, blocks_); // what the random positions left of sin(k.x)
    }

    // Wraps q into [0, L) and returns how many periods it moved down (the images crossed upwards).
    // q - L floor(q/L) can round to L for a q just below 0: that point is the periodic image of 0
    // to within the rounding (one crossing more); a result rounded below 0 is 0 too.
    static double wrap_periodic(double& q, double L) {
        if (!(q < 0 || q >= L))
            return 0;
        double k = std::floor(q / L);
        q -= L * k;
        if (q >= L) {
            q = 0;
            k += 1;
        } else if (q < 0) {
            q = 0;
        }
        return k;
    }

    // The flight's chunks: flight_chunk grains of one species (the last of each species shorter),
    // species after species; chunk ch of species s is the species' ch-th.
    static constexpr std::size_t flight_chunk = 65536;
    struct FlightChunk {
        std::size_t species, index, first, last;
    };
    std::vector<FlightChunk> flight_chunks() const {
        std::vector<FlightChunk> chunks;
        for (std::size_t s = 0; s < blocks_.size(); ++s)
            for (std::size_t f = blocks_[s].offset, ch = 0; f < blocks_[s].offset + blocks_[s].count;
                 f += flight_chunk, ++ch)
                chunks.push_back({s, ch, f, std::min(f + flight_chunk, blocks_[s].offset + blocks_[s].count)});
        return chunks;
    }

    // The thermostat's kicks of the step [t_, t_ + dt] (see "Thermostat"): over [t_kick_, t_ + dt/2],
    // per species what they do, the bridge's scales, the chunks' sums and, with exact energy, the
    // factors on the kicks (a pass over the grains that sums what the kicks would inject). kicking_
    // says whether any grain is kicked.
    void plan_kicks(double dt) {
        kicking_ = false;
        if (!thermostat_)
            return;
        kicking_ = plan_species_kicks(*thermostat_, blocks_, t_ + 0.5 * dt, t_kick_, kicks_);
        if (!kicking_)
            return;
        const std::vector<FlightChunk> chunks = flight_chunks();
        for (std::size_t s = 0; s < blocks_.size(); ++s) {
            if (!kicks_[s].kick.moves())
                continue;
            std::vector<std::size_t> sizes;
            std::size_t first = 0; // the species' first chunk
            for (std::size_t u = 0; u < chunks.size(); ++u)
                if (chunks[u].species == s) {
                    if (sizes.empty())
                        first = u;
                    sizes.push_back(chunks[u].last - chunks[u].first);
                }
            prepare_step_kick(
                kick_source(s), sizes, thermostat_->exact_energy, kicks_[s],
                [&](std::size_t C, auto&& f) { team_->for_each(C, f); },
                [&](std::size_t ch, KickEnergy* e) {
                    const FlightChunk& c = chunks[first + ch];
                    kick_chunk(s, ch, c.first, c.last, kicks_[s], e);
                });
        }
    }

    // Where species s's kicks of this step come from (dsmc/thermostat.hpp).
    KickSource kick_source(std::size_t s) const {
        return KickSource::of(seed_, replica_, static_cast<std::uint64_t>(steps_), s, blocks_[s]);
    }

    // Species s's kicks in its chunk ch (grains lo .. hi - 1): applied (energy == nullptr) or only
    // summed into *energy. Never inlined: the team runs chunks inline on one thread and through its
    // workers on several, and inlined copies may be contracted into FMAs differently (the
    // homogeneous engine's kick_chunk says what that broke).
    [[gnu::noinline]] void kick_chunk(std::size_t s, std::size_t ch, std::size_t lo, std::size_t hi, const StepKick& k,
                                      KickEnergy* energy) {
        kick_grains(
            kick_source(s), ch, hi - lo, k, [&](std::size_t q) -> Vec3& { return v_[lo + q]; },
            [&](std::size_t q) -> Vec3& { return spin(lo + q); }, energy);
    }

    // The kicks of a flight chunk, if the step has any for its species.
    void kick(const FlightChunk& c) {
        if (kicking_ && kicks_[c.species].kick.moves())
            kick_chunk(c.species, c.index, c.first, c.last, kicks_[c.species], nullptr);
    }

    // Free flight, wrapped into the box, after the chunk's kicks. A pass of its own: folded into the
    // sort's first pass, which reads every position too, the step is no faster (N = 1e6, one thread).
    void stream(double dt) {
        const std::vector<FlightChunk> chunks = flight_chunks();
        team_->for_each(chunks.size(), [&](std::size_t u) {
            kick(chunks[u]);
            for (std::size_t i = chunks[u].first; i < chunks[u].last; ++i) {
                double* q[3] = {&x_[i].x, &x_[i].y, &x_[i].z};
                const double dq[3] = {v_[i].x * dt, v_[i].y * dt, v_[i].z * dt};
                for (int a = 0; a < 3; ++a) {
                    const double L = domain_.size[a];
                    double y = *q[a] + dq[a];
                    wrap_periodic(y, L);
                    *q[a] = y;
                }
            }
        });
    }

    static double& component(Vec3& q, int a) { return a == 0 ? q.x : a == 1 ? q.y : q.z; }
    static double component(const Vec3& q, int a) { return a == 0 ? q.x : a == 1 ? q.y : q.z; }

    // The earliest time in [0, limit) at which q(t) = q + v t + g t^2/2 leaves [0, L]: through 0
    // with q'(t) < 0 or through L with q'(t) > 0 (so a grain just sent back from a wall, on it with
    // its velocity pointing inwards, is not caught by the same wall at t = 0). `limit` if none;
    // `upper` says which wall.
    static double exit_time(double q, double v, double g, double L, double limit, bool& upper) {
        double best = limit;
        for (const bool up : {false, true}) {
            const double c = q - (up ? L : 0.0);
            const auto consider = [&](double t) {
                const double speed = v + g * t;
                if (t >= 0 && t < best && (up ? speed > 0 : speed < 0)) {
                    best = t;
                    upper = up;
                }
            };
            if (g == 0) {
                if (v != 0)
                    consider(-c / v);
                continue;
            }
            const double D = v * v - 2.0 * g * c;
            if (D < 0)
                continue;
            // The roots of (g/2) t^2 + v t + c without cancellation: 2Q/g and c/Q.
            const double Q = -0.5 * (v + std::copysign(std::sqrt(D), v));
            if (Q == 0) {
                consider(0.0);
                continue;
            }
            consider(2.0 * Q / g);
            consider(c / Q);
        }
        return best;
    }

    // The flight with walls or gravity (the header's step 1), after the chunk's kicks: chunks of one
    // species' grains, each with its stream and wall tallies, merged in chunk order.
    void stream_general(double dt) {
        const std::vector<FlightChunk> chunks = flight_chunks();
        // Each chunk's tallies in cache lines of their own (written at every wall hit; core/own_lines.hpp).
        std::vector<OwnLines<WallFluxes>> flux(chunks.size());
        team_->for_each(chunks.size(), [&](std::size_t u) {
            CollisionRng rng = make_collision_stream(StreamKey{seed_, Stream::wall_emission, replica_, static_cast<std::uint64_t>(steps_), u});
            kick(chunks[u]);
            for (std::size_t i = chunks[u].first; i < chunks[u].last; ++i)
                fly(i, chunks[u].species, dt, rng, flux[u].value);
        });
        for (const OwnLines<WallFluxes>& f : flux)
            for (std::size_t k = 0; k < 6; ++k)
                wall_flux_[k] += f.value[k];
    }

    // Lees-Edwards (Lees & Edwards 1972): the periodic images above y = L_y move at +a L_y along x,
    // those below 0 at -a L_y, their x offset being a L_y t. A grain that left through y = L_y k
    // times (k < 0: through 0) during the step re-enters as the image's grain: v_x - k a L_y and
    // x - k a L_y t_end. Applied at the step's end t_end whatever the crossing time: from the crossing
    // on, the grain flies with the new velocity, and x_cross - offset(t_c) + (v_x - a L_y)(t_end - t_c)
    // = x(t_end) - offset(t_end). `k` is counted by fly() as the grain's y is wrapped.
    void cross_lees_edwards(Vec3& x, Vec3& v, double k, double dt) const {
        const double Lx = domain_.size[0], Ly = domain_.size[1];
        const double offset = std::fmod(domain_.shear_rate * Ly * (t_ + dt), Lx);
        v.x -= k * domain_.shear_rate * Ly;
        x.x -= k * offset;
        wrap_periodic(x.x, Lx);
    }

    void fly(std::size_t i, std::size_t s, double dt, CollisionRng& rng, WallFluxes& flux) {
        const Vec3 g{domain_.gravity[0], domain_.gravity[1], domain_.gravity[2]};
        Vec3 x = x_[i], v = v_[i];
        double rest = dt, crossings = 0; // of y = L_y, for Lees-Edwards
        for (int hits = 0; hits < max_wall_hits_per_step; ++hits) {
            double t = rest;
            int wall = -1;
            for (int a = 0; a < 3; ++a)
                if (domain_.walled(a)) {
                    bool upper = false;
                    const double ta =
                        exit_time(component(x, a), component(v, a), component(g, a), domain_.size[a], t, upper);
                    if (ta < t) {
                        t = ta;
                        wall = 2 * a + (upper ? 1 : 0);
                    }
                }
            x += t * v + (0.5 * t * t) * g;
            v += t * g;
            for (int a = 0; a < 3; ++a) {
                const double L = domain_.size[a];
                double& q = component(x, a);
                if (domain_.walled(a)) {
                    q = std::clamp(q, 0.0, L); // round-off of a crossing found just after the step
                } else {
                    const double k = wrap_periodic(q, L);
                    if (a == 1)
                        crossings += k;
                }
            }
            if (wall < 0)
                break;
            const int a = wall / 2;
            const bool upper = wall % 2 == 1;
            component(x, a) = upper ? domain_.size[a] : 0.0;
            hit_wall(i, s, a, upper, v, rng, flux[static_cast<std::size_t>(wall)]);
            rest -= t;
        }
        if (crossings != 0 && domain_.lees_edwards())
            cross_lees_edwards(x, v, crossings, dt);
        x_[i] = x;
        v_[i] = v;
    }

    // Grain i (species s, velocity v at the wall) meets the wall of axis a.
    void hit_wall(std::size_t i, std::size_t s, int a, bool upper, Vec3& v, CollisionRng& rng, WallFlux& flux) {
        const WallSpec& wall = domain_.wall(a, upper);
        const double sign = upper ? -1.0 : 1.0; // n = sign e_a, from the wall into the gas
        Vec3 U{wall.velocity[0], wall.velocity[1], wall.velocity[2]};
        component(U, a) = 0;
        const Vec3 v0 = v;
        [[maybe_unused]] const Vec3 w0 = rough ? w_[i] : Vec3{};
        const GrainProperties& grain = blocks_[s].grain;
        switch (wall.kind) {
        case WallKind::specular:
            component(v, a) = -component(v, a);
            break;
        case WallKind::diffuse:
            emit_from_diffuse_wall<rough>(rng, wall.temperature, grain.mass, blocks_[s].moment_of_inertia(), U, a,
                                          sign, v, spin(i)); // smooth grains: the spin is left as it is
            break;
        case WallKind::rough: {
            Vec3 n{};
            component(n, a) = sign;
            if constexpr (rough)
                collide_with_wall(wall_pc_[s], make_rough_constant(wall.alpha, wall.beta), v, w_[i], U, n);
            else
                collide_with_wall(wall_pc_[s], make_smooth_constant(wall.alpha), v, n);
            break;
        }
        }
        flux.hits += 1;
        flux.momentum += grain.mass * (v0 - v);
        flux.energy += 0.5 * grain.mass * (norm2(v0) - norm2(v));
        if constexpr (rough)
            flux.energy += 0.5 * blocks_[s].moment_of_inertia() * (norm2(w0) - norm2(w_[i]));
    }

    // Each cell's collisional virial of this step into its profile bin (cells in order: the sums do
    // not depend on the threads).
    void add_cell_virials() {
        const int a = domain_.profile_axis;
        const std::size_t nx = static_cast<std::size_t>(domain_.cells[0]), ny = static_cast<std::size_t>(domain_.cells[1]);
        for (std::size_t c = 0; c < cells_; ++c) {
            const std::size_t k = a == 0 ? c % nx : a == 1 ? (c / nx) % ny : c / (nx * ny);
            for (std::size_t q = 0; q < 6; ++q)
                bin_virial_[k][q] += cell_virial_[c][q];
        }
    }

    // Per species of cell c: its grains' count, sum of v and sum of |v|^2 (collision_frequency's
    // slab statistics), in store order.
    void tally_cell(std::size_t c) {
        const std::size_t S = blocks_.size();
        for (std::size_t s = 0; s < S; ++s) {
            const auto [first, last] = cell_range(s, c);
            double n = 0, vx = 0, vy = 0, vz = 0, v2 = 0;
            for (std::size_t i = first; i < last; ++i) {
                n += 1;
                vx += v_[i].x;
                vy += v_[i].y;
                vz += v_[i].z;
                v2 += norm2(v_[i]);
            }
            double* t = cell_tally_.data() + (c * S + s) * cell_sum_fields;
            t[0] = n;
            t[1] = vx;
            t[2] = vy;
            t[3] = vz;
            t[4] = v2;
        }
    }

    // A stable counting sort of each species' grains by cell (the grains themselves move, so a
    // cell's grains are adjacent in memory while they collide), in parallel over P chunks of the
    // species' range (P fixed by the grain and cell counts, never by the threads): each chunk counts
    // its grains per cell, the offsets follow in (cell, chunk) order, and each chunk scatters its
    // grains into the second set of arrays, which become the first (no copy back).
    void sort_into_cells() {
        tallies_valid_ = false;
        const std::size_t S = blocks_.size();
        resize_on_huge_pages(key_, particles_);
        cell_start_.resize(S * (cells_ + 1));
        spins_gathered_ = -1;
        for (std::vector<Vec3>* a : {&x2_, &v2_})
            resize_on_huge_pages(*a, particles_);
        if constexpr (rough)
            resize_on_huge_pages(w2_, particles_);
        id2_.resize(id_.size());
        last2_.resize(last_.size());
        for (std::size_t s = 0; s < S; ++s) {
            const SpeciesBlock& b = blocks_[s];
            // Chunks of at least 4096 grains and on average at least 2 grains per cell and chunk
            // (the counts, P x cells, stay below the grain count).
            const std::size_t P = std::clamp<std::size_t>(std::min(b.count / 4096, b.count / (2 * cells_)), 1, 64);
            counts_.assign(P * cells_, 0);
            const auto range = [&](std::size_t p) {
                return std::pair{b.offset + b.count * p / P, b.offset + b.count * (p + 1) / P};
            };
            team_->for_each(P, [&](std::size_t p) {
                std::uint32_t* count = counts_.data() + p * cells_;
                const auto [first, last] = range(p);
                for (std::size_t i = first; i < last; ++i) {
                    key_[i] = static_cast<std::uint32_t>(cell_of(x_[i]));
                    ++count[key_[i]];
                }
            });
            std::uint32_t* start = cell_start_.data() + s * (cells_ + 1);
            std::uint32_t next = static_cast<std::uint32_t>(b.offset);
            for (std::size_t c = 0; c < cells_; ++c) {
                start[c] = next;
                for (std::size_t p = 0; p < P; ++p) {
                    const std::uint32_t n = counts_[p * cells_ + c];
                    counts_[p * cells_ + c] = next; // becomes chunk p's next position in cell c
                    next += n;
                }
            }
            start[cells_] = next;
            // Compiled twice, so that the loop of random partners has no test for the last partners.
            const auto scatter = [&]<bool Nearest>(std::size_t p) {
                std::uint32_t* pos = counts_.data() + p * cells_;
                const auto [first, last] = range(p);
                for (std::size_t i = first; i < last; ++i) {
                    const std::uint32_t q = pos[key_[i]]++;
                    x2_[q] = x_[i];
                    v2_[q] = v_[i];
                    if constexpr (rough)
                        w2_[q] = w_[i];
                    if constexpr (Nearest || !rough)
                        id2_[q] = id_[i];
                    if constexpr (Nearest)
                        last2_[q] = last_[i];
                }
            };
            team_->for_each(P, [&](std::size_t p) {
                if (nearest_)
                    scatter.template operator()<true>(p);
                else
                    scatter.template operator()<false>(p);
            });
        }
        x_.swap(x2_);
        v_.swap(v2_);
        if constexpr (rough)
            w_.swap(w2_);
        id_.swap(id2_);
        last_.swap(last2_);
    }

    // The store index of the k-th grain of cell c (species after species).
    std::size_t grain(std::size_t c, std::size_t k, std::size_t& species) const {
        for (std::size_t s = 0;; ++s) {
            const auto [first, last] = cell_range(s, c);
            if (k < last - first) {
                species = s;
                return first + k;
            }
            k -= last - first;
        }
    }

    static constexpr std::uint32_t no_partner = ~std::uint32_t{0};

    // The grain of cell c (n grains) nearest to grain i, its species in `species`: any other grain
    // but i's most recent partner when there is a third.
    std::size_t nearest_partner(std::size_t c, std::size_t i, std::size_t n, std::size_t& species) const {
        const std::uint32_t excluded = n > 2 ? last_[i] : no_partner;
        double best = std::numeric_limits<double>::infinity();
        std::size_t j = i;
        for (std::size_t s = 0; s < blocks_.size(); ++s) {
            const auto [first, last] = cell_range(s, c);
            for (std::size_t q = first; q < last; ++q) {
                const double d2 = norm2(x_[q] - x_[i]);
                if (d2 < best && q != i && id_[q] != excluded) {
                    best = d2;
                    j = q;
                    species = s;
                }
            }
        }
        return j;
    }

    // Collisions of cell c for a time dt (the header's kernel; with Maxwell, the Maxwell kernel:
    // candidates at the rate of the largest pi sigma_ab^2 u_ab, accepted with the pair's share of
    // it, no velocity bound); returns how many.
    template <bool Nearest, bool Maxwell, class Observer>
    std::int64_t collide_cell(std::size_t c, double dt, CollisionRng& rng, Observer& obs) {
        const std::size_t S = blocks_.size();
        Virial& virial = cell_virial_[c];
        virial = Virial{};
        std::size_t n = 0;
        Vec3 u{};
        for (std::size_t s = 0; s < S; ++s) {
            const auto [first, last] = cell_range(s, c);
            n += last - first;
            for (std::size_t i = first; i < last; ++i)
                u += v_[i];
        }
        if (n < 2)
            return 0;
        u = (1.0 / static_cast<double>(n)) * u;
        double b = 0;
        if constexpr (!Maxwell) {
            for (std::size_t s = 0; s < S; ++s) {
                const auto [first, last] = cell_range(s, c);
                for (std::size_t i = first; i < last; ++i)
                    b = std::max(b, norm2(v_[i] - u));
            }
            b = std::sqrt(b);
        }
        // Lambda per unit g_max: pairs x pi sigma_max^2 / V_c with V_c = N / (n C) (simulated units).
        const double rate_per_g =
            0.5 * static_cast<double>(n) * static_cast<double>(n - 1) * cs_max_ * density_ *
            static_cast<double>(cells_) / static_cast<double>(particles_);
        std::int64_t done = 0;
        double t = 0;
        for (;;) {
            // The Maxwell kernel's speed u_max = max (pi sigma_ab^2 u_ab) / (pi sigma_max^2) in place of g_max.
            const double g_max = Maxwell ? maxwell_rate_max_ / cs_max_ : 2.0 * b;
            if (!(g_max > 0))
                return done; // every grain at the cell's mean velocity: no pair approaches
            t += -std::log(uniform01_open0(rng)) / (rate_per_g * g_max);
            if (t >= dt)
                return done;
            const std::size_t k1 = static_cast<std::size_t>(uniform_index(rng, n));
            std::size_t sa = 0, sb = 0;
            std::size_t i = grain(c, k1, sa), j = 0;
            if constexpr (Nearest) {
                j = nearest_partner(c, i, n, sb);
            } else {
                std::size_t k2 = static_cast<std::size_t>(uniform_index(rng, n - 1));
                k2 += k2 >= k1;
                j = grain(c, k2, sb);
            }
            if (sa > sb) {
                std::swap(i, j);
                std::swap(sa, sb);
            }
            const std::size_t type = S == 1 ? 0 : pair_index(sa, sb, S);
            const PairConstants& pc = types_[type].pc;
            const Vec3 g_c = v_[i] - v_[j];
            const Vec3 v_before = v_[i];
            if constexpr (Maxwell) {
                if (types_.size() > 1 && !(uniform01(rng) * maxwell_rate_max_ < maxwell_rate_[type]))
                    continue;
                Vec3 normal = uniform_direction(rng);
                if (dot(normal, g_c) > 0) // onto the approaching hemisphere: uniform there
                    normal = -1.0 * normal;
                if constexpr (rough)
                    obs(collide(pc, policies_[type], v_[i], w_[i], v_[j], w_[j], normal), type);
                else
                    obs(collide(pc, policies_[type], v_[i], v_[j], normal), type);
            } else {
                const double g = std::sqrt(norm2(g_c));
                if (!(uniform01(rng) * cs_max_ * g_max < pc.cross_section * g))
                    continue;
                if constexpr (rough) {
                    const Vec3 normal = sample_impact_normal(rng, g_c, g);
                    obs(collide(pc, policies_[type], v_[i], w_[i], v_[j], w_[j], normal), type);
                } else {
                    const Vec3 g_N = sample_impact_normal_part(rng, g_c, g);
                    obs(collide_normal_part(pc, policies_[type], v_[i], v_[j], g_N), type);
                }
            }
            ++done;
            if constexpr (Nearest) {
                last_[i] = id_[j];
                last_[j] = id_[i];
            }
            // The impulse on i times the separation (observables/profiles.hpp, Pc).
            const Vec3 dp = blocks_[sa].grain.mass * (v_[i] - v_before), r = x_[i] - x_[j];
            virial[0] += dp.x * r.x;
            virial[1] += dp.y * r.y;
            virial[2] += dp.z * r.z;
            virial[3] += 0.5 * (dp.x * r.y + dp.y * r.x);
            virial[4] += 0.5 * (dp.x * r.z + dp.z * r.x);
            virial[5] += 0.5 * (dp.y * r.z + dp.z * r.y);
            if constexpr (!Maxwell)
                b = std::max({b, std::sqrt(norm2(v_[i] - u)), std::sqrt(norm2(v_[j] - u))});
        }
    }

    // The Enskog collisions of a step (see "Enskog collisions"): the cells' fields, then the blocks
    // colour by colour.
    template <class Observer> void collide_enskog(double dt, Observer& obs) {
        EnskogCells& e = *enskog_;
        const std::size_t S = blocks_.size();
        std::vector<double> count(cells_ * S), momentum(cells_ * 3);
        // Lees-Edwards: the images across y are shifted by this along x (the flight's end, where the
        // positions are; cross_lees_edwards).
        le_offset_ = domain_.lees_edwards()
                         ? std::fmod(domain_.shear_rate * domain_.size[1] * (t_ + dt), domain_.size[0])
                         : 0.0;
        for_each_cell([&](std::size_t c) {
            const double base = e.base_flow(c);
            for (std::size_t s = 0; s < S; ++s) {
                const auto [first, last] = cell_range(s, c);
                count[c * S + s] = static_cast<double>(last - first);
                for (std::size_t i = first; i < last; ++i) {
                    momentum[c * 3] += v_[i].x - base;
                    momentum[c * 3 + 1] += v_[i].y;
                    momentum[c * 3 + 2] += v_[i].z;
                }
            }
        });
        // F/V_c in simulated units: n V/N per grain over V/C per cell.
        const double weight = density_ * static_cast<double>(cells_) / static_cast<double>(particles_);
        e.set_densities(count, momentum, weight);
        for_each_cell([&](std::size_t c) {
            const std::array<double, 3> U = e.flow(c);
            double b = 0;
            for (std::size_t s = 0; s < S; ++s) {
                const auto [first, last] = cell_range(s, c);
                for (std::size_t i = first; i < last; ++i)
                    b = std::max(b, norm2(v_[i] - Vec3{U[0], U[1], U[2]}));
            }
            speed_start_[c] = std::sqrt(b);
            cell_virial_[c] = Virial{};
        });
        speed_now_ = speed_start_;
        e.set_speed_bounds(speed_start_);
        const CellBlocks& blocks = e.blocks();
        struct alignas(64) Unit {
            Observer observer;
            std::int64_t collisions = 0;
            double eps = 0;
        };
        std::vector<Unit> local;
        local.reserve(blocks.count());
        for (std::size_t u = 0; u < blocks.count(); ++u)
            local.push_back(Unit{obs.fork(), 0, 0.0});
        double eps = 0; // the largest rise of a cell's speed bound in the colours done
        for (const std::vector<std::size_t>& colour : blocks.by_colour) {
            team_->for_each(colour.size(), [&](std::size_t k) {
                const std::size_t u = colour[k];
                CollisionRng rng = make_collision_stream(
                    StreamKey{seed_, Stream::cell_collisions, replica_, static_cast<std::uint64_t>(steps_), u});
                Unit& unit = local[u];
                unit.eps = eps;
                const std::array<int, 3> b = blocks.index(u);
                for (int z = blocks.edges[2][static_cast<std::size_t>(b[2])]; z < blocks.edges[2][static_cast<std::size_t>(b[2]) + 1]; ++z)
                    for (int y = blocks.edges[1][static_cast<std::size_t>(b[1])]; y < blocks.edges[1][static_cast<std::size_t>(b[1]) + 1]; ++y)
                        for (int x = blocks.edges[0][static_cast<std::size_t>(b[0])]; x < blocks.edges[0][static_cast<std::size_t>(b[0]) + 1]; ++x) {
                            const std::size_t c = (static_cast<std::size_t>(z) * static_cast<std::size_t>(domain_.cells[1]) +
                                                   static_cast<std::size_t>(y)) * static_cast<std::size_t>(domain_.cells[0]) +
                                                  static_cast<std::size_t>(x);
                            unit.collisions += collide_cell_enskog(c, dt, rng, unit.observer, unit.eps);
                        }
            });
            for (std::size_t u : colour)
                eps = std::max(eps, local[u].eps);
        }
        for (const Unit& unit : local) {
            obs.merge(unit.observer);
            collisions_ += unit.collisions;
        }
    }

    // The point p wrapped into the box: false beyond a wall; `image` the shift that wrapping removed
    // (the partner's periodic image is at its position plus `image`) and `dv` the image's velocity
    // over the grain's: across y with Lees-Edwards boundaries the images above move at +a L_y along x
    // and sit offset by a L_y t (cross_lees_edwards), so the real point is shifted back along x.
    bool wrap_point(Vec3& p, Vec3& image, Vec3& dv) const {
        const double Ly = domain_.size[1];
        if (domain_.lees_edwards() && !(p.y >= 0 && p.y < Ly)) {
            const double up = p.y >= Ly ? 1.0 : -1.0; // the image above (+1) or below (-1)
            p.y -= up * Ly;
            p.x -= up * le_offset_;
            image.y = up * Ly;
            image.x = up * le_offset_;
            dv.x = up * domain_.shear_rate * Ly;
        }
        for (int a = 0; a < 3; ++a) {
            const double L = domain_.size[static_cast<std::size_t>(a)];
            double& q = component(p, a);
            if (q >= 0 && q < L)
                continue;
            if (domain_.walled(a))
                return false;
            // At most one period (sides of at least 2 sigma), but the Lees-Edwards offset may add one along x.
            const double shift = L * std::floor(q / L);
            q -= shift;
            if (!(q >= 0 && q < L))
                q = q < 0 ? 0.0 : std::nextafter(L, 0.0);
            component(image, a) += shift;
        }
        return true;
    }

    // A pair's virial into the profile slabs its segment from q_j to q_i (along the profile axis,
    // unwrapped) crosses, in proportion to its length in each: the slabs' cells in c's line.
    void add_virial(std::size_t c, double q_i, double q_j, const Virial& v) {
        const int a = domain_.profile_axis;
        const auto k = static_cast<std::size_t>(a);
        const int n = domain_.cells[k];
        const double h = domain_.size[k] / n;
        const double lo = std::min(q_i, q_j), hi = std::max(q_i, q_j);
        const long first = static_cast<long>(std::floor(lo / h)), last = static_cast<long>(std::floor(hi / h));
        if (first == last || !(hi > lo)) {
            Virial& to = cell_virial_[c];
            for (std::size_t q = 0; q < 6; ++q)
                to[q] += v[q];
            return;
        }
        const std::size_t stride = a == 0 ? 1 : a == 1 ? static_cast<std::size_t>(domain_.cells[0])
                                                      : static_cast<std::size_t>(domain_.cells[0]) * static_cast<std::size_t>(domain_.cells[1]);
        const long own = static_cast<long>((c / stride) % static_cast<std::size_t>(n));
        for (long b = first; b <= last; ++b) {
            const double part = (std::min(hi, (b + 1) * h) - std::max(lo, b * h)) / (hi - lo);
            const long wrapped = ((b % n) + n) % n;
            Virial& to = cell_virial_[static_cast<std::size_t>(static_cast<long>(c) + (wrapped - own) * static_cast<long>(stride))];
            for (std::size_t q = 0; q < 6; ++q)
                to[q] += part * v[q];
        }
    }

    // The Enskog collisions of cell c for a time dt (see "Enskog collisions"); `eps` the largest rise
    // of a speed bound known to this block. Returns how many.
    template <class Observer>
    std::int64_t collide_cell_enskog(std::size_t c, double dt, CollisionRng& rng, Observer& obs, double& eps) {
        const EnskogCells& e = *enskog_;
        const std::size_t S = blocks_.size();
        std::size_t n = 0;
        for (std::size_t s = 0; s < S; ++s) {
            const auto [first, last] = cell_range(s, c);
            n += last - first;
        }
        if (n == 0)
            return 0;
        const double W = e.weight_max(c), N_max = e.count_max(c);
        const auto slots = static_cast<std::uint64_t>(N_max);
        const double others = e.speed_max(c) + e.flow_spread(c);
        const std::array<double, 3> Uc = e.flow(c);
        const Vec3 U{Uc[0], Uc[1], Uc[2]};
        // Lambda per unit B: (1/2) N_c S 4 pi W N_max F/V_c, F/V_c = n C/N in simulated units.
        const double rate_per_B = 0.5 * static_cast<double>(n) * static_cast<double>(S) * 4 * std::numbers::pi * W *
                                  N_max * density_ * static_cast<double>(cells_) / static_cast<double>(particles_);
        double B = others + eps;
        boost::random::exponential_distribution<double> exponential{1.0};
        std::int64_t done = 0;
        double t = 0;
        const int axis = domain_.profile_axis;
        for (;;) {
            if (!(B > 0) || !(rate_per_B > 0))
                return done;
            t += exponential(rng) / (rate_per_B * B);
            if (t >= dt)
                return done;
            std::size_t sa = 0;
            std::size_t i = grain(c, static_cast<std::size_t>(uniform_index(rng, n)), sa);
            const std::size_t sb = S == 1 ? 0 : static_cast<std::size_t>(uniform_index(rng, S));
            const std::size_t type = S == 1 ? 0 : pair_index(std::min(sa, sb), std::max(sa, sb), S);
            const double sigma = types_[type].pc.sigma;
            // k with density (B + a.k)/(4 pi B), a = v_i - U: uniform with probability 1 - |a|/B, else
            // with density (1 + a^.k)/(4 pi) (mu = a^.k = 2 sqrt(u) - 1, the azimuth uniform).
            const Vec3 a = v_[i] - U;
            const double a_abs = std::sqrt(norm2(a));
            Vec3 k = uniform_direction(rng);
            if (uniform01(rng) * B < a_abs) {
                const Vec3 axis_a = (1.0 / a_abs) * a;
                const double mu = 2 * std::sqrt(uniform01(rng)) - 1;
                const Vec3 across = k - dot(k, axis_a) * axis_a;
                const double across2 = norm2(across);
                if (!(across2 > 0))
                    continue; // k along a (probability 0): a candidate lost costs nothing but time
                k = mu * axis_a + (std::sqrt(std::max(0.0, 1 - mu * mu) / across2)) * across;
            }
            const double bound = B + dot(a, k); // >= (g.k)+ for every partner
            Vec3 p = x_[i] + sigma * k, image{}, dv{};
            const double u = uniform01(rng) * bound;
            if (!wrap_point(p, image, dv))
                continue; // beyond a wall: no partner there
            const std::size_t c2 = cell_of(p);
            const auto [first, last] = cell_range(sb, c2);
            // One of N_max slots: the partner if it is one of the cell's N'_b grains (probability N'_b/N_max).
            const std::size_t slot = static_cast<std::size_t>(uniform_index(rng, slots));
            if (slot >= last - first)
                continue;
            const std::size_t j = first + slot;
            if (j == i)
                continue;
            // Accepted with probability (sigma^2 chi/W) (g.k)+/bound: first against (g.k)+/bound
            // (sigma^2 chi <= W), the midpoint's chi only for what passes (about one in ten).
            const double approach = dot(v_[i] - v_[j] - dv, k);
            if (!(u < approach))
                continue;
            double chi = types_[type].chi;
            if (!chi_uniform_) {
                Vec3 mid = x_[i] + (0.5 * sigma) * k, mid_image{}, mid_dv{};
                wrap_point(mid, mid_image, mid_dv);
                chi = e.chi(cell_of(mid), type);
            }
            if (!(u * W < sigma * sigma * chi * approach))
                continue;
            // The rule's i is of the lower species; n from j to i.
            std::size_t ri = i, rj = j;
            Vec3 normal = -1.0 * k;
            if (sa > sb) {
                std::swap(ri, rj);
                normal = k;
            }
            const PairConstants& pc = types_[type].pc;
            const Vec3 v_before = v_[i];
            // The partner at its image's velocity for the rule, and back (dv = 0 but across a
            // Lees-Edwards boundary).
            v_[j] += dv;
            CollisionRecord rec;
            if constexpr (rough)
                rec = collide(pc, policies_[type], v_[ri], w_[ri], v_[rj], w_[rj], normal);
            else
                rec = collide(pc, policies_[type], v_[ri], v_[rj], normal);
            v_[j] -= dv;
            // The rule counted j's energy at its image's velocity: the grains' own kinetic energy
            // changes by dv.J more (J the impulse on i; Engine::collide_sheared says why).
            rec.dE_tr += dot(dv, blocks_[sa].grain.mass * (v_[i] - v_before));
            obs(rec, type);
            ++done;
            // The impulse on i times its separation from j's image (observables/profiles.hpp, Pc).
            const Vec3 dp = blocks_[sa].grain.mass * (v_[i] - v_before), r = x_[i] - (x_[j] + image);
            const Virial virial{dp.x * r.x,
                                dp.y * r.y,
                                dp.z * r.z,
                                0.5 * (dp.x * r.y + dp.y * r.x),
                                0.5 * (dp.x * r.z + dp.z * r.x),
                                0.5 * (dp.y * r.z + dp.z * r.y)};
            const double q_i = component(x_[i], axis);
            add_virial(c, q_i, q_i - component(r, axis), virial);
            // The speed bounds: a rise of c's is G's at once; a grain beyond its cell's floor raises
            // eps, which bounds by how much any cell's speed_max may now be exceeded.
            const double b_i = std::sqrt(norm2(v_[i] - U));
            if (b_i > speed_now_[c]) {
                speed_now_[c] = b_i;
                eps = std::max(eps, b_i - e.speed_floor(c));
            }
            const std::array<double, 3> U2 = e.flow(c2);
            const double b_j = std::sqrt(norm2(v_[j] - Vec3{U2[0], U2[1], U2[2]}));
            if (b_j > speed_now_[c2]) {
                speed_now_[c2] = b_j;
                eps = std::max(eps, b_j - e.speed_floor(c2));
            }
            B = others + eps;
        }
    }

    DomainSpec domain_;
    std::vector<SpeciesBlock> blocks_;
    std::vector<PairType> types_;
    std::vector<Policy> policies_;
    double density_ = 1;
    std::uint64_t seed_ = 0, replica_ = 0;
    std::unique_ptr<WorkerTeam> team_;
    std::size_t particles_ = 0, cells_ = 1;
    double cs_max_ = 0;
    bool maxwell_ = false;
    std::vector<double> maxwell_rate_; // per pair type: pi sigma_ab^2 u_ab of the Maxwell kernel
    double maxwell_rate_max_ = 0;
    std::array<double, 3> k_{}; // the initial wave's wave vector
    std::vector<PairConstants> wall_pc_; // per species: the grain with an infinitely massive wall
    WallFluxes wall_flux_{};
    std::vector<Virial> cell_virial_, bin_virial_; // this step's per cell; since the last row per bin
    // Per (cell, species): cell_sum_fields sums of tally_cell; valid since the last step's collisions.
    std::vector<double> cell_tally_;
    bool tallies_valid_ = false;
    // Rough grains: w_[i] is the spin of the grain at store index i (sorted with it, w2_ its second
    // copy). Smooth grains: w_[id_[i]] (not moved by the sort; w2_ unused).
    std::vector<Vec3> x_, v_, w_, x2_, v2_, w2_;
    std::vector<std::uint32_t> key_, cell_start_, counts_;
    // Each grain's identity (smooth grains, or nearest partners; else empty) and, with nearest
    // partners only, its most recent partner's.
    std::vector<std::uint32_t> id_, last_, id2_, last2_;
    bool nearest_ = false;
    // Smooth grains: the step at which the spins were last gathered into store order (-1: not
    // since the last sort). Between sorts x2_, the positions' second copy, is free to take them.
    std::int64_t spins_gathered_ = -1;
    std::array<double, 3> cells_per_length_{};
    double t_ = 0;
    std::int64_t steps_ = 0, collisions_ = 0;
    // The thermostat (unset: no drive), the time its kicks reached, per species the current step's
    // kicks, and whether the current step kicks any grain.
    std::optional<ThermostatSpec> thermostat_;
    double t_kick_ = 0;
    std::vector<StepKick> kicks_;
    bool kicking_ = false;
    // Enskog collisions: the cells' fields (unset: Boltzmann), each cell's speed bound about the flow
    // U at the step's start and now.
    std::optional<EnskogCells> enskog_;
    std::vector<double> speed_start_, speed_now_;
    bool chi_uniform_ = false; // a constant chi (run.chi): no midpoint's cell to find
    double le_offset_ = 0;     // the Lees-Edwards images' offset along x during a step's Enskog collisions
};

} // namespace roughgas
