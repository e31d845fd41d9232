// The Enskog equation's theory of the uniform gas (observables/enskog_pressure.hpp, HcsTheory's pair
// correlations): the pressure's closed forms and limits, and the rates scaled by chi.
#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/observables/driven_steady_state.hpp"
#include "roughgas/observables/enskog_pressure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace roughgas {
namespace {

HcsTheory one_species(double phi, double alpha, double beta) {
    const double n = 6 * phi / std::numbers::pi; // unit diameter
    HcsTheory th({HcsSpecies{1.0, 0.5, 0.4, 1.0}}, {ConstantRestitution{alpha, beta}}, n);
    th.set_pair_correlations({carnahan_starling_chi(phi)});
    return th;
}

TEST(EnskogPressure, OneSpeciesClosedFormAndCarnahanStarling) {
    const HcsTemperatures T{{1.7}, {0.6}};
    for (double phi : {0.05, 0.2, 0.45})
        for (double alpha : {0.5, 1.0}) {
            const HcsTheory th = one_species(phi, alpha, 0.3);
            const double n = th.density(), chi = carnahan_starling_chi(phi);
            EXPECT_NEAR(enskog_kinetic_pressure(th, T), n * 1.7, 1e-14);
            EXPECT_NEAR(enskog_collisional_pressure(th, T) / (n * 1.7), 2 * (1 + alpha) * phi * chi, 1e-13);
            if (alpha == 1.0) // elastic: Carnahan & Starling's equation of state
                EXPECT_NEAR((enskog_kinetic_pressure(th, T) + enskog_collisional_pressure(th, T)) / (n * 1.7),
                            carnahan_starling_compressibility(phi), 1e-13);
        }
    // beta and T_rot do not enter.
    EXPECT_EQ(enskog_collisional_pressure(one_species(0.2, 0.8, -1.0), T),
              enskog_collisional_pressure(one_species(0.2, 0.8, 1.0), HcsTemperatures{{1.7}, {9.0}}));
}

TEST(EnskogPressure, MixtureOfIdenticalSpeciesIsOneSpecies) {
    const double phi = 0.3, n = 6 * phi / std::numbers::pi;
    HcsTheory mix({HcsSpecies{1.0, 0.5, 0.4, 0.3}, HcsSpecies{1.0, 0.5, 0.4, 0.7}},
                  {ConstantRestitution{0.8, 0.1}, ConstantRestitution{0.8, 0.1}, ConstantRestitution{0.8, 0.1}}, n);
    const double chi = carnahan_starling_chi(phi);
    mix.set_pair_correlations({chi, chi, chi});
    const HcsTemperatures T{{1.3, 1.3}, {0.5, 0.5}};
    EXPECT_NEAR(enskog_collisional_pressure(mix, T), enskog_collisional_pressure(one_species(phi, 0.8, 0.1), {{1.3}, {0.5}}),
                1e-13);
    // Species at different temperatures: each pair weighs T_a/m_a + T_b/m_b, so the light species' share
    // counts with its mass.
    HcsTheory light({HcsSpecies{1.0, 0.5, 0.4, 0.5}, HcsSpecies{0.5, 0.5, 0.4, 0.5}},
                    {ConstantRestitution{1, -1}, ConstantRestitution{1, -1}, ConstantRestitution{1, -1}}, n);
    // (pi/3) n^2 sum over ordered pairs of x_a x_b m_ab (1 + alpha) (T_a/m_a + T_b/m_b), sigma = 1, chi = 1:
    // m_aa = 1/2, m_ab = 1/3, m_bb = 1/4, T_a/m_a = 2, T_b/m_b = 2.
    const double expected = std::numbers::pi / 3 * n * n *
                            (0.25 * 0.5 * 2 * 4 + 2 * 0.25 * (1.0 / 3.0) * 2 * 4 + 0.25 * 0.25 * 2 * 4);
    EXPECT_NEAR(enskog_collisional_pressure(light, HcsTemperatures{{2.0, 1.0}, {1, 1}}), expected, 1e-12 * expected);
}

TEST(EnskogPressure, RatesScaleWithChi) {
    const HcsTemperatures T{{1.0}, {0.7}};
    HcsTheory dilute({HcsSpecies{}}, {ConstantRestitution{0.7, 0.4}}, 0.3);
    HcsTheory dense = dilute;
    dense.set_pair_correlations({2.2});
    const PairExchange a = dilute.exchange(0, 0, T.T_tr, T.T_rot), b = dense.exchange(0, 0, T.T_tr, T.T_rot);
    EXPECT_NEAR(b.frequency, 2.2 * a.frequency, 1e-14 * b.frequency);
    EXPECT_EQ(a.dE_tr, b.dE_tr);
    EXPECT_EQ(a.dE_rot, b.dE_rot);
    EXPECT_NEAR(reduced_cooling_rate(dense, T), reduced_cooling_rate(dilute, T), 1e-14);
    // White noise: the power in is fixed, the cooling ~ chi T^(3/2), so the steady temperatures are
    // chi^(-2/3) times the dilute gas's, with the same theta.
    ThermostatSpec th;
    th.species.resize(1);
    th.species[0].drive.value = {0.8};
    const auto d = driven_steady_state(dilute, th), e = driven_steady_state(dense, th);
    ASSERT_TRUE(d && e);
    EXPECT_NEAR(e->T_tr / d->T_tr, std::pow(2.2, -2.0 / 3.0), 1e-8);
    EXPECT_NEAR(e->theta, d->theta, 1e-8);
    EXPECT_THROW(dense.set_pair_correlations({0.0}), std::invalid_argument);
    EXPECT_THROW(dense.set_pair_correlations({1.0, 1.0}), std::invalid_argument);
}

} // namespace
} // namespace roughgas
