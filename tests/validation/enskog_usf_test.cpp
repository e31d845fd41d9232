// The sheared Enskog gas (dsmc/engine.hpp, "Sheared Enskog gas") against Enskog's Navier-Stokes shear
// viscosity of elastic hard spheres (Chapman & Cowling 1970, first Sonine approximation):
//   eta/eta_0 = (1 + (2/5) b rho chi)^2/chi + (3/5) kappa/eta_0,   kappa/eta_0 = (16/(5 pi)) (b rho)^2 chi,
// b rho = 4 phi: the kinetic part with the collisional transfer's cross term, and the bulk viscosity
// kappa's share. eta_0 here is the first Sonine approximation's dilute viscosity, the unit of the
// DSMC's eta* (docs/model.md, "Uniform shear flow"); with Chapman & Cowling's exact eta_0 (1.016 times
// larger) the last term's coefficient reads 0.7614 (b rho)^2 chi. An elastic gas has no
// steady shear state: it heats, slowly at a* ~ 0.05, and eta* is measured over 10 to 40 collisions
// per particle, where a* changes by a few per cent (shear thinning, O(a*^2), is far below the errors).
// The first Sonine approximation leaves out about 1.6 % of the dilute gas's eta (its higher
// approximations: eta_0 = 1.016 times the first; Chapman & Cowling) and a similar share at finite
// density: the band is 3 % plus four standard errors (from the spread of 30 rows, whose intervals of
// a collision per particle are nearly independent). Perfectly rough grains: see
// PerfectlyRoughElasticViscosity. CPU: about 8 s for the file.
#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/observables/enskog_usf_theory.hpp"
#include "roughgas/observables/rough_enskog_viscosity.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/dsmc/tables.hpp"

#include "../dsmc/run_test_support.hpp"
#include "../dsmc/test_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <vector>

namespace roughgas {
namespace {

using test::column;
using test::mean_err;
using Rows = std::vector<std::vector<double>>;

// Smooth grains of unit diameter (m = 1, T = 1) at the solid fraction phi in the Enskog equation,
// sheared at a* = a/nu(T = 1), nu = (16/5) n sigma^2 sqrt(pi T/m), steps of 0.1 mean free times; 40
// rows a collision per particle apart.
// beta = -1: smooth; the grains are uniform spheres (q = 2/5).
Rows sheared_gas(double phi, double alpha, double a_star, std::int64_t N, std::uint64_t seed, RunSpec& s,
                 double beta = -1.0) {
    s.species = {SpeciesSpec{}};
    s.pairs = {ConstantRestitution{alpha, beta}};
    s.particles = N;
    s.density = 6 * phi / std::numbers::pi;
    s.end = 40;
    for (int k = 1; k <= 40; ++k)
        s.output_times.push_back(k);
    s.seed = seed;
    s.enskog = EnskogSpec{};
    s.shear = ShearSpec{a_star * 16.0 / 5.0 * s.density * std::sqrt(std::numbers::pi), 0.1};
    const auto tables = RestitutionTables::build(s);
    Rows rows;
    run_replica(s, *tables, 0, [&](std::span<const double> r) { rows.emplace_back(r.begin(), r.end()); });
    return rows;
}

TEST(EnskogShear, ElasticViscosityIsEnskogs) {
    for (const double phi : {0.1, 0.25}) {
        RunSpec s;
        const Rows rows = sheared_gas(phi, 1.0, 0.05, 200000, 5, s);
        std::vector<double> eta;
        for (std::size_t k = 11; k < rows.size(); ++k)
            eta.push_back(rows[k][column(s, "eta_star")]);
        const auto [mean, err] = mean_err(eta);
        const double chi = carnahan_starling_chi(phi), b_rho = 4 * phi;
        const double kappa = 16 / (5 * std::numbers::pi) * b_rho * b_rho * chi;
        const double enskog = (1 + 0.4 * b_rho * chi) * (1 + 0.4 * b_rho * chi) / chi + 0.6 * kappa;
        EXPECT_NEAR(mean / enskog, 1.0, 0.03 + 4 * err / enskog)
            << "phi = " << phi << ": eta* = " << mean << " +- " << err << ", Enskog " << enskog;
        // The Boltzmann gas's eta* = 1 (the dilute viscosity, first Sonine) is outside twice the band.
        EXPECT_GT(std::abs(enskog - 1.0) / enskog, 2 * (0.03 + 4 * err / enskog));
        RecordProperty("eta_phi_" + std::to_string(phi),
                       std::to_string(mean) + " +- " + std::to_string(err) + " against " + std::to_string(enskog));
    }
}

TEST(EnskogShear, PerfectlyRoughElasticViscosity) {
    // Elastic perfectly rough uniform spheres (alpha = beta = 1, q = 2/5) at phi = 0.25, a* = 0.05, as
    // ElasticViscosityIsEnskogs, one run of 2 10^5 grains (about 2.2 s). Against Enskog's viscosity in
    // the first Sonine approximation (observables/rough_enskog_viscosity.hpp): 3.957. That
    // approximation leaves out the spins' anisotropy <J omega_x omega_y>, which the tangential impulse
    // couples to the shear stress: with it the dilute gas's eta is 1.065 times Pidduck's (a Galerkin
    // quadrature of the collision rule), and the Boltzmann gas of the same grains measures 1.058
    // (docs/validation.md). So: eta* 0 to 8 % above the first Sonine value; the collisional transfer,
    // given the measured kinetic stress, A phi chi times it plus the bulk-like term (the transfer of
    // both the stress deviation and the Maxwellian across the shifted contact, 2.939 against the
    // measured 2.935), within 2 %; and the mean spin at half the vorticity, -a/2, within 5 %. Bands
    // plus four standard errors.
    const double phi = 0.25, chi = carnahan_starling_chi(phi), q = 0.4;
    RunSpec s;
    const Rows rows = sheared_gas(phi, 1.0, 0.05, 200000, 5, s, 1.0);
    const double a = s.shear->rate;
    const RoughEnskogViscosity th = rough_enskog_viscosity(q, phi, chi);
    const double kappa = q / (1 + q), A = 1.6 * (1 + 1.5 * kappa);
    const double bulk = 768 / (25 * std::numbers::pi) * (1 + 0.75 * kappa) * phi * phi * chi;
    std::vector<double> eta, transfer, spin;
    for (std::size_t k = 11; k < rows.size(); ++k) {
        const double e = rows[k][column(s, "eta_star")];
        const double pk = rows[k][column(s, "P_xy")], pc = rows[k][column(s, "P_coll_xy")];
        const double kinetic = e * pk / (pk + pc);
        eta.push_back(e);
        transfer.push_back((e - kinetic) / (A * phi * chi * kinetic + bulk));
        spin.push_back(rows[k][column(s, "omega_z")] / (-a / 2));
    }
    const auto [eta_mean, eta_err] = mean_err(eta);
    EXPECT_GT(eta_mean / th.total, 1.0 - 4 * eta_err / th.total) << eta_mean << " +- " << eta_err;
    EXPECT_LT(eta_mean / th.total, 1.08 + 4 * eta_err / th.total) << eta_mean << " +- " << eta_err;
    const auto [tr_mean, tr_err] = mean_err(transfer);
    EXPECT_NEAR(tr_mean, 1.0, 0.02 + 4 * tr_err) << "collisional transfer over theory " << tr_mean << " +- " << tr_err;
    const auto [spin_mean, spin_err] = mean_err(spin);
    EXPECT_NEAR(spin_mean, 1.0, 0.05 + 4 * spin_err) << "Omega_z/(-a/2) = " << spin_mean << " +- " << spin_err;
    RecordProperty("eta_rough_phi_0.25", std::to_string(eta_mean) + " +- " + std::to_string(eta_err) +
                                             " against " + std::to_string(th.total));
    RecordProperty("transfer_rough_phi_0.25", std::to_string(tr_mean) + " +- " + std::to_string(tr_err));
    RecordProperty("spin_rough_phi_0.25", std::to_string(spin_mean) + " +- " + std::to_string(spin_err));
}

TEST(EnskogShear, SteadyRheologyAgainstGradsApproximation) {
    // Smooth grains, alpha = 0.7, at phi = 0.1 and 0.25: the steady state against Grad's approximation of
    // the Enskog equation (observables/enskog_usf_theory.hpp), started at its a* (T = 1, a = a* nu(1)) so
    // that the gas starts near the steady state; 10^5 grains, 10 collisions per particle to settle, 30
    // rows a collision per particle apart. Grad's approximation drops the velocity distribution's fourth
    // cumulant (a20 ~ 0.05 here) and the product of the two grains' stress deviations, and gives P*_yy =
    // P*_zz in the dilute gas: the Boltzmann solver's steady state at alpha = 0.7 (roughgas's dilute
    // uniform shear flow, 10^5 grains) is off Grad's dilute closed form by +3.8 % in a*, -4.4 % in eta*,
    // -1.7 % in P*_yy and +3.9 % in P*_zz; the dense gas's collisional transfer, which Grad's method
    // takes exactly in the shift, shrinks that share. Bands: 5 % on a* and eta*, 4 % on the normal
    // stresses, plus four standard errors. Measured (2026-12-07): see docs/validation.md.
    for (const double phi : {0.1, 0.25}) {
        const double chi = carnahan_starling_chi(phi);
        const EnskogUsfState th = enskog_usf_grad(0.7, phi, chi);
        RunSpec s;
        const Rows rows = sheared_gas(phi, 0.7, th.a_star, 100000, 9, s);
        const auto steady = [&](const char* q) {
            std::vector<double> x;
            for (std::size_t k = 11; k < rows.size(); ++k)
                x.push_back(rows[k][column(s, q)]);
            return mean_err(x);
        };
        const auto compare = [&](const char* q, double theory, double band) {
            const auto [mean, err] = steady(q);
            EXPECT_NEAR(mean / theory, 1.0, band + 4 * err / std::abs(theory))
                << "phi = " << phi << ", " << q << " = " << mean << " +- " << err << ", Grad " << theory;
            RecordProperty(std::string(q) + "_phi_" + std::to_string(phi),
                           std::to_string(mean) + " +- " + std::to_string(err) + " against " + std::to_string(theory));
        };
        compare("a_star", th.a_star, 0.05);
        compare("eta_star", th.eta_star, 0.05);
        compare("P_xx_star", th.total.xx, 0.04);
        compare("P_yy_star", th.total.yy, 0.04);
        compare("P_zz_star", th.total.zz, 0.04);
    }
}

} // namespace
} // namespace roughgas
