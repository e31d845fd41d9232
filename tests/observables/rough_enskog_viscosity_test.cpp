// Enskog's shear viscosity of elastic perfectly rough spheres (observables/rough_enskog_viscosity.hpp):
// its dilute limit (Pidduck's), its q -> 0 limit (Enskog's smooth-sphere value), its structure and the
// values at q = 2/5 quoted in docs/validation.md.
#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/observables/rough_enskog_viscosity.hpp"
#include "roughgas/observables/shear_mode.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace roughgas {
namespace {

double smooth_enskog(double phi, double chi) {
    return (1 + 1.6 * phi * chi) * (1 + 1.6 * phi * chi) / chi + 768 / (25 * std::numbers::pi) * phi * phi * chi;
}

TEST(RoughEnskogViscosity, DiluteLimitIsPidducks) {
    for (const double q : {0.1, 0.4, 2.0 / 3.0}) {
        const RoughEnskogViscosity r = rough_enskog_viscosity(q, 0.0, 1.0);
        EXPECT_DOUBLE_EQ(r.total, 6 * (1 + q) * (1 + q) / (6 + 13 * q));
        EXPECT_EQ(r.collisional, 0.0);
    }
    // The same as the dilute rough shear mode's eta* at alpha = beta = 1 (observables/shear_mode.hpp).
    EXPECT_NEAR(rough_enskog_viscosity(0.4, 0.0, 1.0).total, rough_shear_mode(1.0, 1.0, 0.4).eta_star, 1e-14);
    // Continuous in phi: the first density correction is (2 A - 1) eta_P phi at chi = 1 + (5/2) phi.
    const double phi = 1e-6, q = 0.4, kappa = q / (1 + q), A = 1.6 * (1 + 1.5 * kappa);
    const double eta_p = 1.05;
    EXPECT_NEAR((rough_enskog_viscosity(q, phi, carnahan_starling_chi(phi)).total - eta_p) / phi,
                eta_p * (2 * A - 2.5), 1e-4);
}

TEST(RoughEnskogViscosity, VanishingInertiaGivesTheSmoothEnskogValue) {
    for (const double phi : {0.1, 0.25, 0.4}) {
        const double chi = carnahan_starling_chi(phi);
        EXPECT_NEAR(rough_enskog_viscosity(1e-10, phi, chi).total, smooth_enskog(phi, chi), 1e-8);
    }
}

TEST(RoughEnskogViscosity, StructureAndUniformSpheres) {
    const double q = 0.4, kappa = 2.0 / 7.0, eta_p = 1.05, A = 16.0 / 7.0;
    for (const double phi : {0.1, 0.25}) {
        const double chi = carnahan_starling_chi(phi);
        const RoughEnskogViscosity r = rough_enskog_viscosity(q, phi, chi);
        EXPECT_NEAR(r.kinetic, eta_p * (1 + A * phi * chi) / chi, 1e-13);
        // The collisional transfer carries A phi chi times the kinetic stress plus the bulk-like term.
        EXPECT_NEAR(r.collisional - A * phi * chi * r.kinetic,
                    768 / (25 * std::numbers::pi) * (1 + 0.75 * kappa) * phi * phi * chi, 1e-13);
        EXPECT_NEAR(r.total, r.kinetic + r.collisional, 1e-14);
        EXPECT_GT(r.total, smooth_enskog(phi, chi)); // roughness adds to every term
    }
    EXPECT_NEAR(rough_enskog_viscosity(q, 0.1, carnahan_starling_chi(0.1)).total, 1.51196, 1e-5);
    EXPECT_NEAR(rough_enskog_viscosity(q, 0.25, carnahan_starling_chi(0.25)).total, 3.95657, 1e-5);
}

TEST(RoughEnskogViscosity, RejectsBadArguments) {
    EXPECT_THROW(rough_enskog_viscosity(0.0, 0.1, 1.2), std::invalid_argument);
    EXPECT_THROW(rough_enskog_viscosity(0.7, 0.1, 1.2), std::invalid_argument);
    EXPECT_THROW(rough_enskog_viscosity(0.4, 1.0, 1.2), std::invalid_argument);
    EXPECT_THROW(rough_enskog_viscosity(0.4, 0.1, 0.0), std::invalid_argument);
    EXPECT_THROW(rough_enskog_viscosity(0.4, std::nan(""), 1.2), std::invalid_argument);
}

} // namespace
} // namespace roughgas
