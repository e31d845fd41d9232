#pragma once
// What a row of moments.csv holds (dsmc_columns, dsmc/run.hpp), from the
// moments of the state and the collisions since the previous row: shared by the homogeneous
// (drive_impl.hpp) and the spatially resolved (drive_spatial.cpp) runs, so that both write the same
// columns with the same definitions.
#include "roughgas/collision/record.hpp"
#include "roughgas/core/bytes.hpp"
#include "roughgas/dsmc/species.hpp"
#include "roughgas/observables/moments.hpp"
#include "roughgas/observables/pressure.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <cstdint>
#include <optional>
#include <vector>

namespace roughgas::detail {

// Sums over the collisions since the last output row.
struct Tally {
    double dE = 0;                      // energy change of the gas (<= 0)
    std::vector<std::int64_t> per_type; // collisions per pair type
    // Per pair type, the sum of (1 + alpha) g_n: the normal impulse of a collision is m_ab (1 + alpha) g_n
    // (docs/model.md §3), and sigma_ab times it is what the collision adds to the collisional transfer
    // of momentum of the Enskog equation (append_pressure_columns).
    std::vector<double> impulse;
    // The sheared Enskog gas (Engine::set_enskog_shear): sum of sigma n_k J_l over the collisions, J the
    // impulse on the grain at r_j + sigma n: momentum l carried along k across the grains' distance
    // (row-major, k the direction).
    std::array<double, 9> transfer{};
    std::int64_t clamped = 0;           // all collisions so far with beta clamped
    void operator()(const CollisionRecord& r, std::size_t k) {
        dE += r.dE_tr + r.dE_rot;
        ++per_type[k];
        impulse[k] += (1 + r.alpha) * r.g_n;
        clamped += r.beta_clamped;
    }
    void transfer_of(const Vec3& sigma_n, const Vec3& J) {
        const double a[3] = {sigma_n.x, sigma_n.y, sigma_n.z}, b[3] = {J.x, J.y, J.z};
        for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l)
                transfer[static_cast<std::size_t>(3 * k + l)] += a[k] * b[l];
    }
    // Sized for `types` pair types, every sum 0.
    void assign(std::size_t types) {
        per_type.assign(types, 0);
        impulse.assign(types, 0.0);
    }
    // One per group (or work unit) of an engine (ForkableObserver, dsmc/engine.hpp), merged in order.
    // Its arrays end a cache line before their allocations do, so that no other fork's sums, which
    // another thread writes at every collision, share a line with them.
    Tally fork() const {
        Tally t;
        t.per_type.reserve(per_type.size() + 64 / sizeof(std::int64_t));
        t.impulse.reserve(impulse.size() + 64 / sizeof(double));
        t.assign(per_type.size());
        return t;
    }
    void merge(const Tally& o) {
        dE += o.dE;
        for (std::size_t k = 0; k < per_type.size(); ++k) {
            per_type[k] += o.per_type[k];
            impulse[k] += o.impulse[k];
        }
        for (std::size_t k = 0; k < transfer.size(); ++k)
            transfer[k] += o.transfer[k];
        clamped += o.clamped;
    }
    // In a checkpoint (core/bytes.hpp); load() resizes the arrays to what was saved.
    void save(ByteWriter& w) const {
        w.f64(dE);
        w.u64(per_type.size());
        for (std::int64_t x : per_type)
            w.put(x);
        for (double x : impulse)
            w.f64(x);
        for (double x : transfer)
            w.f64(x);
        w.put(clamped);
    }
    void load(ByteReader& r) {
        dE = r.f64();
        per_type.resize(r.count(sizeof(std::int64_t)));
        for (std::int64_t& x : per_type)
            x = r.get<std::int64_t>();
        impulse.resize(per_type.size());
        for (double& x : impulse)
            x = r.f64();
        for (double& x : transfer)
            x = r.f64();
        clamped = r.get<std::int64_t>();
    }
    // After a row: the interval sums start again (clamped counts the whole run).
    void next_interval() {
        dE = 0;
        std::fill(per_type.begin(), per_type.end(), 0);
        std::fill(impulse.begin(), impulse.end(), 0.0);
        transfer.fill(0.0);
    }
};

inline void append_group(std::vector<double>& row, const GroupMoments& g) {
    for (double x : {g.T_tr, g.T_rot, g.theta, g.a20, g.a02, g.a11, g.A_cw})
        row.push_back(x);
}

// t, coll_per_particle, the whole gas's moments, coll_rate, E_diss_rate. `inv_dt`: 1 over the time
// since the previous row (NaN in the first row); `volume`: N/n.
inline void append_row_head(std::vector<double>& row, double t, std::int64_t collisions, std::int64_t collisions_prev,
                            double N, const Moments& m, double inv_dt, const Tally& tally, double volume) {
    row.push_back(t);
    row.push_back(2.0 * static_cast<double>(collisions) / N);
    append_group(row, m.all);
    row.push_back(2.0 * static_cast<double>(collisions - collisions_prev) / N * inv_dt);
    row.push_back(-tally.dE / volume * inv_dt);
}

// The Enskog equation's pressure (enskog runs: dsmc_columns, dsmc/run.hpp): p_kin = n T_tr (the trace
// of the kinetic pressure tensor over 3, at the row), p_coll, the collisional transfer's: each
// collision moves the momentum J = m_ab (1 + alpha) g_n n across the distance sigma_ab n between the
// grains' centres, so that (1/3) sum sigma_ab J_n over the collisions of an interval, over the volume
// and the interval's length, is the trace over 3 of its collisional pressure tensor (the virial of
// hard spheres; Enskog 1922), averaged over the interval since the previous row (NaN in the first
// row, as coll_rate); and p = p_kin + p_coll.
inline void append_pressure_columns(std::vector<double>& row, const Moments& m, std::span<const SpeciesSlice> slices,
                                    const std::vector<PairType>& types, const Tally& tally, double volume,
                                    double inv_dt) {
    double N = 0;
    for (const SpeciesSlice& s : slices)
        N += static_cast<double>(s.count);
    double virial = 0;
    for (std::size_t k = 0; k < types.size(); ++k)
        virial += types[k].pc.sigma * types[k].pc.m_eff * tally.impulse[k];
    const double p_kin = N / volume * m.all.T_tr, p_coll = virial / (3 * volume) * inv_dt;
    row.push_back(p_kin);
    row.push_back(p_coll);
    row.push_back(p_kin + p_coll);
}

// Mixtures: each species' moments and collision rate, then the temperature ratios of every pair;
// beta_clamped when the run has a brilliantov pair.
inline void append_row_tail(std::vector<double>& row, const Moments& m, const Tally& tally,
                            const std::vector<PairType>& types, const std::vector<SpeciesBlock>& blocks, double inv_dt,
                            bool clamp_column) {
    const std::size_t S = blocks.size();
    if (S > 1) {
        std::vector<double> per_species(S, 0.0);
        for (std::size_t k = 0; k < types.size(); ++k) {
            per_species[types[k].a] += static_cast<double>(tally.per_type[k]);
            per_species[types[k].b] += static_cast<double>(tally.per_type[k]);
        }
        for (std::size_t s = 0; s < S; ++s) {
            append_group(row, m.species[s]);
            row.push_back(per_species[s] / static_cast<double>(blocks[s].count) * inv_dt);
        }
        for (std::size_t a = 0; a < S; ++a) {
            for (std::size_t b = a + 1; b < S; ++b) {
                row.push_back(m.species[a].T_tr / m.species[b].T_tr);
                row.push_back(m.species[a].T_rot / m.species[b].T_rot);
            }
        }
    }
    if (clamp_column)
        row.push_back(static_cast<double>(tally.clamped));
}

// The collisional transfer part of the pressure tensor of a sheared Enskog gas over the interval since
// the previous row, from the tally's sums: P_coll,kl = flux along k of l-momentum, (xx, yy, zz, xy, xz,
// yz) = (sigma n_x J_x, sigma n_y J_y, sigma n_z J_z, sigma n_y J_x, sigma n_z J_x, sigma n_z J_y) per
// unit volume and time: xy is the flux along y of x-momentum, the shear stress of u = a y x^ (for
// rough grains the tangential impulses make the whole tensor asymmetric; these are the fluxes along
// the gradient's directions). NaN in the first row.
inline PressureTensor collisional_pressure_tensor(const Tally& tally, double volume, double inv_dt) {
    const double f = inv_dt / volume;
    const std::array<double, 9>& t = tally.transfer;
    return {t[0] * f, t[4] * f, t[8] * f, t[3] * f, t[6] * f, t[7] * f};
}

// The shear columns (shear runs: dsmc_columns, dsmc/run.hpp) from the kinetic pressure tensor P, the
// mean spin Omega and the gas temperature T: P_ij, Omega, then the reduced a*, eta*, P*_ij, N1*, N2*
// of the whole pressure tensor, P plus `P_coll` (a sheared Enskog gas, then also its P_coll_ij last).
inline void append_shear_columns(std::vector<double>& row, const PressureTensor& P, const Vec3& Omega, double rate,
                                 const std::vector<UsfSpecies>& species, double density, double T,
                                 const std::optional<PressureTensor>& P_coll = std::nullopt) {
    PressureTensor total = P;
    if (P_coll)
        total = {P.xx + P_coll->xx, P.yy + P_coll->yy, P.zz + P_coll->zz,
                 P.xy + P_coll->xy, P.xz + P_coll->xz, P.yz + P_coll->yz};
    const UsfReduced r = usf_reduced(total, rate, usf_nu(species, density, T), density, T);
    for (double x : {P.xx, P.yy, P.zz, P.xy, P.xz, P.yz, Omega.x, Omega.y, Omega.z, r.a_star, r.eta_star,
                     r.P_star.xx, r.P_star.yy, r.P_star.zz, r.P_star.xy, r.P_star.xz, r.P_star.yz, r.N1_star,
                     r.N2_star})
        row.push_back(x);
    if (P_coll)
        for (double x : {P_coll->xx, P_coll->yy, P_coll->zz, P_coll->xy, P_coll->xz, P_coll->yz})
            row.push_back(x);
}

} // namespace roughgas::detail
