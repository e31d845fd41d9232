// The first Sonine approximation of rough spheres (observables/sonine_rates.hpp,
// observables/sonine_cooling_state.hpp) against scripts/rough_sonine_reference.py, an independent
// evaluation (sympy closed forms derived from the collision rule, cross-checked by deterministic
// quadrature of the collision integrals; its cooling state by bisection), and against the limits
// in closed form: van Noije & Ernst's smooth spheres, equipartition of elastic perfectly rough ones.
// The arrays are the script's output, pasted: `scripts/python3 scripts/rough_sonine_reference.py`.
#include "roughgas/observables/sonine_cooling_state.hpp"
#include "roughgas/observables/sonine_rates.hpp"
#include "roughgas/observables/theory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace roughgas {
namespace {

// {alpha, beta, q, theta, then R_c2, R_w2, R_c4, R_w4, R_c2w2 each as (R^0, R^20, R^02, R^11)}, by
// the script's quadrature (which agrees with its closed forms within 6e-15 relative to max(1, |R|)).
constexpr std::array<std::array<double, 24>, 3> quadrature_rates = {{
    {0.9,
     0.0,
     0.4,
     0.55,
     2.837755102040814e-01,
     6.723852040816287e-02,
     9.070484079408191e-17,
     -1.403061224489832e-02,
     2.736549165120594e-01,
     -6.348562152133554e-02,
     -7.830791539399623e-16,
     1.147959183673461e-01,
     1.435575572678049e+00,
     3.928023330122856e+00,
     -3.149729279466466e-03,
     -1.854245626822186e-01,
     1.218500555897852e+00,
     -2.917172941026628e-01,
     2.212619741774250e+00,
     4.969520275642677e-01,
     7.564586725228116e-01,
     -8.687078773995718e-02,
     -4.438254893794417e-02,
     2.336166180758008e+00},
    {0.7,
     -0.5,
     0.5,
     3.0,
     3.244444444444441e-01,
     8.166666666666626e-02,
     4.394866181031396e-17,
     -2.083333333333380e-02,
     2.685185185185184e-01,
     -1.909722222222221e-02,
     -4.552549569794461e-16,
     6.944444444444373e-02,
     1.609332716049380e+00,
     4.276318865740732e+00,
     -6.944444444444239e-03,
     -2.806250000000033e-01,
     1.198388203017832e+00,
     -8.407278806584353e-02,
     1.339506172839500e+00,
     5.902777777777720e-01,
     8.322890946502047e-01,
     2.056645447530854e-01,
     -8.101851851851960e-02,
     2.074374999999990e+00},
    {0.5,
     1.0,
     0.3,
     1.5,
     1.974852071005911e-01,
     1.701645710059164e-01,
     3.873711954876447e-16,
     -1.331360946745561e-01,
     1.183431952662723e-01,
     -6.656804733727774e-02,
     -3.227682572983553e-17,
     8.875739644970357e-02,
     8.750317303315672e-01,
     5.496192838901813e+00,
     -2.836035152830763e-01,
     -1.613585833829344e+00,
     5.637057525996991e-01,
     -3.590998214348219e-01,
     2.240817898532963e+00,
     1.260460067924769e-01,
     4.713792409229359e-01,
     8.948363809039734e-03,
     -4.766114631840614e-01,
     2.055291196911863e+00},
}};

// The closed forms against the quadrature: 1e-13 relative to max(1, |R|), the quadrature's own
// round-off (6e-15) with a margin for the closed forms' (sums of terms up to ~10).
TEST(SonineTheory, RatesAgreeWithQuadrature) {
    for (const auto& p : quadrature_rates) {
        const SonineRates r = sonine_rates(p[0], p[1], p[2], p[3]);
        const SonineRate* rates[] = {&r.c2, &r.w2, &r.c4, &r.w4, &r.c2w2};
        for (int k = 0; k < 5; ++k) {
            const double want[] = {p[4 + 4 * k], p[5 + 4 * k], p[6 + 4 * k], p[7 + 4 * k]};
            const double got[] = {rates[k]->one, rates[k]->a20, rates[k]->a02, rates[k]->a11};
            for (int w = 0; w < 4; ++w)
                EXPECT_NEAR(got[w], want[w], 1e-13 * std::max(1.0, std::abs(want[w])))
                    << "alpha = " << p[0] << ", beta = " << p[1] << ", rate " << k << ", coefficient " << w;
        }
    }
}

// The Maxwellian parts are the cooling equations of Huthmann & Zippelius (1997) that theory.hpp
// integrates: R_c2^0 = 2(A - B theta), R_w2^0 = 2(C - B/theta).
TEST(SonineTheory, MaxwellianRatesAreTheTheoryColumnsEquations) {
    for (double alpha : {0.3, 0.9, 1.0})
        for (double beta : {-0.6, 0.0, 0.7, 1.0})
            for (double q : {0.25, 0.4, 2.0 / 3.0})
                for (double theta : {0.2, 1.0, 3.0}) {
                    const EqualSphereCoefficients c =
                        equal_sphere_coefficients(alpha, beta, q, 1.0, 1.0, 1.0);
                    const SonineRates r = sonine_rates(alpha, beta, q, theta);
                    EXPECT_NEAR(r.c2.one, 2 * (c.A - c.B * theta), 1e-14);
                    EXPECT_NEAR(r.w2.one, 2 * (c.C - c.B / theta), 1e-14);
                }
}

// {alpha, beta, q, theta, a20, a02, a11, zeta*}: the script's cooling states (its bisection in
// ln theta to 1e-15, its cumulants from numpy's solve), printed to 15 digits. Tolerance 1e-11
// relative: both sides solve the same 3 x 3 systems to round-off; the printed digits limit the rest.
constexpr std::array<std::array<double, 8>, 10> reference_states = {{
    {0.9, -0.5, 0.4, 0.328296306153179, -0.0176906620582553, 0.273904661276265, 0.0300803281426695,
     0.145473015789273},
    {0.9, 0.0, 0.4, 0.552846154972635, -0.00401517955093198, 0.185534857437112, 0.0647855263246403,
     0.188153685871062},
    {0.9, 0.5, 0.4, 0.855515040345295, -0.00765428165249029, 0.0806896460209848, 0.0282274726739611,
     0.155402815070803},
    {0.9, 1.0, 0.4, 1.12358999614964, -0.00393641545361286, 0.000192459589533888, -0.00550925261770603,
     0.029794368122011},
    {0.5, -0.5, 0.4, 3.28719853654764, 0.264277689199596, 19.8880624595448, 1.80221227188778,
     0.27965532343392},
    {0.5, 0.0, 0.4, 1.82155387692114, 0.107014095183315, 1.27671401357495, 0.302216875967236,
     0.291055467503753},
    {0.5, 0.5, 0.4, 1.54178827939186, 0.0641345298620441, 0.300925428942445, 0.107953599847811,
     0.23974563621157},
    {0.5, 1.0, 0.4, 1.57492805897939, 0.0412466950741993, 0.0292524028838137, 0.00801454800821831,
     0.0980938400981988},
    {0.8, 0.3, 0.25, 0.691040389664983, 0.00230565856392745, 0.18857269274877, 0.0645527643924469,
     0.207665017202089},
    {1.0, 0.0, 0.4, 0.390263690440193, -0.00653811218044849, 0.0748148496524826, 0.05236912859593,
     0.136102563897078},
}};

TEST(SonineTheory, CoolingStateAgreesWithAnIndependentEvaluation) {
    for (const auto& p : reference_states) {
        const std::optional<SonineCoolingState> s = sonine_cooling_state(p[0], p[1], p[2]);
        ASSERT_TRUE(s) << p[0] << " " << p[1];
        const double got[] = {s->theta, s->a20, s->a02, s->a11, s->zeta_star};
        for (int k = 0; k < 5; ++k)
            EXPECT_NEAR(got[k], p[3 + k], 1e-11 * std::max(1.0, std::abs(p[3 + k])))
                << "alpha = " << p[0] << ", beta = " << p[1] << ", q = " << p[2] << ", value " << k;
    }
}

// Smooth spheres: van Noije & Ernst's (1998) a2 in closed form, the cooling rate with it, theta
// without a scaled value (+infinity; NaN when elastic), the spins' cumulants undefined.
TEST(SonineTheory, SmoothLimitIsVanNoijeErnst) {
    for (double alpha : {0.0, 0.2, 0.5, 0.7, 0.9, 1.0})
        for (double q : {0.25, 0.4, 2.0 / 3.0}) {
            const std::optional<SonineCoolingState> s = sonine_cooling_state(alpha, -1.0, q);
            ASSERT_TRUE(s);
            const double a2 = 16 * (1 - alpha) * (1 - 2 * alpha * alpha) /
                              (81 - 17 * alpha + 30 * alpha * alpha * (1 - alpha));
            EXPECT_NEAR(s->a20, a2, 1e-14) << alpha;
            EXPECT_NEAR(s->zeta_star, (1 - alpha * alpha) / 3 * (1 + 3 * a2 / 16) / (1 - a2 / 16), 1e-14)
                << alpha;
            if (alpha < 1)
                EXPECT_EQ(s->theta, HUGE_VAL);
            else
                EXPECT_TRUE(std::isnan(s->theta));
            EXPECT_TRUE(std::isnan(s->a02) && std::isnan(s->a11));
        }
}

// Elastic perfectly rough spheres: the equilibrium, equipartition theta = 1 and Maxwellian
// (cumulants 0), no cooling. The root is found to round-off: 1e-12.
TEST(SonineTheory, ElasticPerfectlyRoughLimitIsEquipartition) {
    for (double q : {0.1, 0.25, 0.4, 2.0 / 3.0, 1.5}) {
        const std::optional<SonineCoolingState> s = sonine_cooling_state(1.0, 1.0, q);
        ASSERT_TRUE(s) << q;
        EXPECT_NEAR(s->theta, 1.0, 1e-12) << q;
        EXPECT_NEAR(s->a20, 0.0, 1e-12) << q;
        EXPECT_NEAR(s->a02, 0.0, 1e-12) << q;
        EXPECT_NEAR(s->a11, 0.0, 1e-12) << q;
        EXPECT_NEAR(s->zeta_star, 0.0, 1e-13) << q;
    }
}

// beta -> -1 is singular: theta ~ 1/(1 + beta)^2 with y = bt^2 theta/q finite, a11 -> 0 and a20
// tending to a value other than van Noije & Ernst's. {alpha, q, y, a20, a02} of the limit, from the
// script's leading-order equations (sympy series, Newton). Its approach at alpha = 0.9 is linear in
// 1 + beta with coefficients below 15 (it prints a02 -0.3985 at beta = -0.9999 against the limit
// -0.3998), so at 1 + beta = 1e-6 the state is within 1e-4 of the limit.
constexpr std::array<std::array<double, 5>, 3> quasi_smooth = {{
    {0.9, 0.4, 0.047573421046503, 0.00618043668378169, -0.399845489082905},
    {0.5, 0.4, 0.190956051259003, 0.0733909032274056, -0.398165227419315},
    {0.7, 0.2, 0.128683431470199, 0.0370413091612137, -0.39907396727097},
}};

TEST(SonineTheory, QuasiSmoothLimit) {
    for (const auto& p : quasi_smooth) {
        const double alpha = p[0], q = p[1], beta = -1 + 1e-6;
        const std::optional<SonineCoolingState> s = sonine_cooling_state(alpha, beta, q);
        ASSERT_TRUE(s) << alpha;
        const double bt = q * (1 + beta) / (2 * (1 + q));
        EXPECT_NEAR(bt * bt * s->theta / q, p[2], 1e-4 * p[2]) << alpha;
        EXPECT_NEAR(s->a20, p[3], 1e-4) << alpha;
        EXPECT_NEAR(s->a02, p[4], 1e-4) << alpha;
        EXPECT_NEAR(s->a11, 0.0, 1e-4) << alpha;
        const double vne =
            16 * (1 - alpha) * (1 - 2 * alpha * alpha) / (81 - 17 * alpha + 30 * alpha * alpha * (1 - alpha));
        EXPECT_GT(std::abs(s->a20 - vne), 0.01) << alpha; // not the smooth gas's
    }
}

// Where the approximation has no cooling state (alpha = 0.9, q = 0.4, the script's scan): at
// beta = -0.9 the branch of the Maxwellian theta meets a pole of the linear system before a root; at
// beta = -0.8 its root has a02 = -5.8, below the -2/5 no distribution goes below.
TEST(SonineTheory, NoStateWhereTheApproximationFails) {
    EXPECT_FALSE(sonine_cooling_state(0.9, -0.9, 0.4));
    EXPECT_FALSE(sonine_cooling_state(0.9, -0.8, 0.4));
    EXPECT_TRUE(sonine_cooling_state(0.9, -0.7, 0.4));
    EXPECT_THROW(sonine_cooling_state(1.1, 0.0, 0.4), std::invalid_argument);
    EXPECT_THROW(sonine_cooling_state(0.9, -1.1, 0.4), std::invalid_argument);
    EXPECT_THROW(sonine_cooling_state(0.9, 0.0, 0.0), std::invalid_argument);
}

} // namespace
} // namespace roughgas
