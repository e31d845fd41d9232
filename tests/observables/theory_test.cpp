// The Maxwellian-approximation HCS theory (observables/theory.hpp): closed forms, limits,
// conservation, the literature coefficients, and the collision averages against Monte Carlo
// averages of the collision rule of docs/model.md §3.
#include "roughgas/observables/theory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace roughgas {
namespace {

HcsTheory one_species(double alpha, double beta, double q = 0.4, double m = 1.0, double R = 0.5,
                      double n = 1.0) {
    return HcsTheory({{m, R, q, 1.0}}, {{alpha, beta}}, n);
}

// A binary mixture with unequal masses, radii and q, and a different (alpha, beta) per pair.
HcsTheory mixture(double alpha = 0.8, double beta = 0.3) {
    return HcsTheory({{1.0, 0.5, 0.4, 0.3}, {3.5, 0.8, 0.25, 0.7}},
                     {{alpha, beta}, {0.5 * (1 + alpha), beta * 0.5}, {alpha, -beta}}, 2.0);
}

TEST(HcsTheory, EqualSpheresReduceToTheLiteratureCoefficients) {
    // Huthmann & Zippelius 1997, Luding et al. 1998 (3-D): dT/dt = G[-A T^{3/2} + B T^{1/2} T_r],
    // dT_r/dt = G[B T^{3/2} - C T^{1/2} T_r] (theory.hpp: no factor 2 in 3-D).
    for (double alpha : {0.3, 0.9, 1.0})
        for (double beta : {-1.0, -0.4, 0.0, 0.7, 1.0})
            for (double q : {0.4, 0.5, 2.0 / 3.0}) {
                const double m = 2.5, R = 0.3, n = 0.7, T = 1.7, Tr = 0.6;
                const HcsTheory th = one_species(alpha, beta, q, m, R, n);
                const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, beta, q, m, 2 * R, n);
                std::vector<double> dT(1), dTr(1), vT{T}, vTr{Tr};
                th.rates(vT, vTr, dT, dTr);
                const double s = std::sqrt(T);
                EXPECT_NEAR(dT[0], c.G * (-c.A * T * s + c.B * s * Tr), 1e-13 * c.G)
                    << alpha << " " << beta << " " << q;
                EXPECT_NEAR(dTr[0], c.G * (c.B * T * s - c.C * s * Tr), 1e-13 * c.G)
                    << alpha << " " << beta << " " << q;
            }
    // The printed values for uniform spheres, alpha = beta = 1: eta = 2/7 and A = B = C = 10/49.
    const EqualSphereCoefficients c = equal_sphere_coefficients(1.0, 1.0, 0.4, 1.0, 1.0, 1.0);
    EXPECT_NEAR(c.eta, 2.0 / 7.0, 1e-15);
    EXPECT_NEAR(c.A, 10.0 / 49.0, 1e-15);
    EXPECT_NEAR(c.B, 10.0 / 49.0, 1e-15);
    EXPECT_NEAR(c.C, 10.0 / 49.0, 1e-15);
    EXPECT_NEAR(c.G, 16.0 / 3.0 * std::sqrt(std::numbers::pi), 1e-14);
}

TEST(HcsTheory, CollisionFrequencyOfEqualSpheres) {
    // 4 n sigma^2 sqrt(pi T/m) (docs/model.md §4).
    const HcsTheory th = one_species(0.9, 0.0, 0.4, 2.0, 0.5, 3.0);
    std::vector<double> T{1.3}, Tr{0.2};
    EXPECT_NEAR(th.exchange(0, 0, T, Tr).frequency, 4 * 3.0 * 1.0 * std::sqrt(std::numbers::pi * 1.3 / 2.0),
                1e-13);
}

TEST(HcsTheory, HaffClosedFormEqualsTheIntegratedOde) {
    const double alpha = 0.9, m = 1.0, R = 0.5, n = 1.0, T0 = 1.0;
    HcsTrajectory ode(one_species(alpha, -1.0), {{T0}, {1.0}}, 1e-10, /*closed_form=*/false);
    const double t0 = haff_time(T0, alpha, m, 2 * R, n);
    // t0 = 2/(G A sqrt(T0)) with A = (1 - alpha^2)/4
    EXPECT_NEAR(t0, 2.0 / ((16.0 / 3.0) * std::sqrt(std::numbers::pi) * 0.25 * (1 - alpha * alpha)),
                1e-12 * t0);
    // Through 40 decades of T (t up to 1e20 t0): the scale-free integration keeps its accuracy.
    for (double x : {1e-3, 0.1, 1.0, 10.0, 1e3, 1e6, 1e10, 1e20}) {
        const HcsTemperatures T = ode.at(x * t0);
        const double haff = haff_temperature(x * t0, T0, alpha, m, 2 * R, n);
        EXPECT_NEAR(T.T_tr[0] / haff, 1.0, 1e-8) << "t/t0 = " << x;
        EXPECT_NEAR(T.T_rot[0], 1.0, 1e-9) << "t/t0 = " << x; // beta = -1: T_rot is untouched
    }
    EXPECT_LT(ode.steps(), 20000u);
    // The closed-form trajectory gives the same.
    HcsTrajectory closed(one_species(alpha, -1.0), {{T0}, {1.0}});
    EXPECT_DOUBLE_EQ(closed.at(10 * t0).T_tr[0], T0 / 121.0);
}

TEST(HcsTheory, SmoothSpheresKeepTrot) {
    // beta = -1 for every pair: a_T = 0, no torque, T_rot,s constant (mixture: per species).
    HcsTheory th({{1.0, 0.5, 0.4, 0.5}, {2.0, 0.7, 0.3, 0.5}}, {{0.7, -1.0}, {0.8, -1.0}, {0.9, -1.0}}, 1.0);
    HcsTrajectory tr(th, {{1.0, 2.0}, {0.3, 5.0}});
    double T_prev = 1.5;
    for (double t : {0.1, 1.0, 100.0}) {
        const HcsTemperatures T = tr.at(t);
        EXPECT_LT(th.mixture_T_tr(T), T_prev); // the mixture cools (species 0 may first heat up)
        T_prev = th.mixture_T_tr(T);
        EXPECT_NEAR(T.T_rot[0], 0.3, 3e-10);
        EXPECT_NEAR(T.T_rot[1], 5.0, 5e-9);
    }
}

TEST(HcsTheory, ElasticPerfectlyRoughConservesEnergy) {
    // alpha = beta = 1 conserves energy: per grain (3/2) sum_s x_s (T_tr,s + T_rot,s).
    {
        HcsTrajectory tr(one_species(1.0, 1.0), {{1.0}, {0.1}}, 1e-11, false);
        for (double t : {0.5, 5.0, 50.0}) {
            const HcsTemperatures T = tr.at(t);
            EXPECT_NEAR(T.T_tr[0] + T.T_rot[0], 1.1, 1e-10) << t;
        }
        EXPECT_NEAR(tr.at(100.0).T_rot[0], 0.55, 1e-8); // and relaxes to theta = 1
    }
    HcsTheory th({{1.0, 0.5, 0.4, 0.3}, {3.5, 0.8, 0.25, 0.7}}, {{1, 1}, {1, 1}, {1, 1}}, 2.0);
    const HcsTemperatures T0{{1.0, 0.2}, {0.05, 3.0}};
    const double E0 = th.mixture_T_tr(T0) + th.mixture_T_rot(T0);
    HcsTrajectory tr(th, T0, 1e-11);
    for (double t : {0.1, 1.0, 10.0, 100.0}) {
        const HcsTemperatures T = tr.at(t);
        EXPECT_NEAR(th.mixture_T_tr(T) + th.mixture_T_rot(T), E0, 1e-9 * E0) << t;
    }
}

TEST(HcsTheory, PairEnergyChangeIsTheAveragedEnergyLoss) {
    // <dE_i> + <dE_j> = (m_eff/2)(alpha^2 - 1) 2s + (kappa m_eff/2)(beta^2 - 1) 2(s + s_W)
    // (docs/model.md §3 averaged, theory.hpp), for unequal species.
    const HcsTheory th = mixture();
    const std::vector<double> T{1.3, 0.4}, Tr{0.7, 2.2};
    const std::vector<HcsSpecies>& sp = th.species();
    const ConstantRestitution r = th.pairs()[pair_index(0, 1, 2)];
    const PairExchange ab = th.exchange(0, 1, T, Tr), ba = th.exchange(1, 0, T, Tr);
    const double m_eff = sp[0].mass * sp[1].mass / (sp[0].mass + sp[1].mass);
    const double kappa =
        1 / (1 + m_eff * (1 / (sp[0].inertia * sp[0].mass) + 1 / (sp[1].inertia * sp[1].mass)));
    const double s = T[0] / sp[0].mass + T[1] / sp[1].mass;
    const double s_w = Tr[0] / (sp[0].inertia * sp[0].mass) + Tr[1] / (sp[1].inertia * sp[1].mass);
    const double loss =
        m_eff * (r.alpha * r.alpha - 1) * s + kappa * m_eff * (r.beta * r.beta - 1) * (s + s_w);
    EXPECT_NEAR(ab.dE_tr + ab.dE_rot + ba.dE_tr + ba.dE_rot, loss, 1e-13 * std::abs(loss));
    // Collisions a-b seen from either side: n_a nu_ab = n_b nu_ba.
    EXPECT_NEAR(sp[0].fraction * ab.frequency, sp[1].fraction * ba.frequency, 1e-13 * ab.frequency);
}

// Monte Carlo of the Boltzmann collision integral with the collision rule of docs/model.md §3
// (written out here, independent of src/): Maxwellian v and omega per species, n uniform on the
// sphere, each sample weighted by the kernel |v_ij . n| on the approaching hemisphere.
// Monte Carlo of the collision rule over Gaussian v and omega: each pair weighted by |v_ij.n| (hard
// spheres) or not at all (the Maxwell kernel), n uniform on the approaching hemisphere.
void check_collision_averages(const HcsTheory& th) {
    const std::vector<HcsSpecies>& sp = th.species();
    const std::vector<double> T{1.3, 0.4}, Tr{0.7, 2.2};
    std::mt19937_64 rng(12345);
    std::normal_distribution<double> normal;
    struct V {
        double x, y, z;
    };
    const auto add = [](V a, V b, double f) { return V{a.x + f * b.x, a.y + f * b.y, a.z + f * b.z}; };
    const auto dot = [](V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
    const auto cross = [](V a, V b) {
        return V{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    };
    const auto gauss = [&](double sd) { return V{sd * normal(rng), sd * normal(rng), sd * normal(rng)}; };
    for (std::size_t a = 0; a < 2; ++a)
        for (std::size_t b = 0; b < 2; ++b) {
            const HcsSpecies& A = sp[a];
            const HcsSpecies& B = sp[b];
            const ConstantRestitution r = th.pairs()[pair_index(a, b, 2)];
            const double m_eff = A.mass * B.mass / (A.mass + B.mass);
            const double kappa = 1 / (1 + m_eff * (1 / (A.inertia * A.mass) + 1 / (B.inertia * B.mass)));
            const double Ja = A.inertia * A.mass * A.radius * A.radius,
                         Jb = B.inertia * B.mass * B.radius * B.radius;
            const int samples = 400000;
            double sw = 0, sw2 = 0, s_tr = 0, s_tr2 = 0, s_rot = 0, s_rot2 = 0, c_tr = 0, c_rot = 0;
            for (int k = 0; k < samples; ++k) {
                const V vi = gauss(std::sqrt(T[a] / A.mass)), vj = gauss(std::sqrt(T[b] / B.mass));
                const V wi = gauss(std::sqrt(Tr[a] / Ja)), wj = gauss(std::sqrt(Tr[b] / Jb));
                V n = gauss(1.0);
                n = add(V{0, 0, 0}, n, 1 / std::sqrt(dot(n, n)));
                const V vij = add(vi, vj, -1);
                double u = dot(vij, n);
                if (u > 0) {
                    n = add(V{0, 0, 0}, n, -1);
                    u = -u;
                } // the approaching hemisphere
                const double weight = th.maxwell() ? 1.0 : -u;
                const V g = add(add(vij, cross(wi, n), -A.radius), cross(wj, n), -B.radius);
                const V gn = add(V{0, 0, 0}, n, dot(g, n));
                const V gt = add(g, gn, -1);
                const V P =
                    add(add(V{0, 0, 0}, gn, -m_eff * (1 + r.alpha)), gt, -kappa * m_eff * (1 + r.beta));
                const V vi2 = add(vi, P, 1 / A.mass);
                const V wi2 = add(wi, cross(n, P), -1 / (A.inertia * A.mass * A.radius));
                const double dtr = 0.5 * A.mass * (dot(vi2, vi2) - dot(vi, vi));
                const double drot = 0.5 * Ja * (dot(wi2, wi2) - dot(wi, wi));
                sw += weight;
                sw2 += weight * weight;
                s_tr += weight * dtr;
                s_tr2 += weight * weight * dtr * dtr;
                c_tr += weight * weight * dtr;
                s_rot += weight * drot;
                s_rot2 += weight * weight * drot * drot;
                c_rot += weight * weight * drot;
            }
            const double N = samples;
            const PairExchange x = th.exchange(a, b, T, Tr);
            // frequency n_b sigma^2 2 pi <weight> (n uniform on the approaching hemisphere, area 2 pi)
            const double sigma = A.radius + B.radius;
            const double mean_w = sw / N, se_w = std::sqrt((sw2 / N - mean_w * mean_w) / N);
            const double f_mc =
                th.density() * B.fraction * sigma * sigma * 2 * std::numbers::pi; // hemisphere
            if (!th.maxwell()) {
                EXPECT_NEAR(x.frequency, f_mc * mean_w, 4 * f_mc * se_w) << a << b;
            }
            // Ratio estimators <w dE>/<w> with their delta-method standard errors.
            const double scale = std::abs(x.dE_tr) + std::abs(x.dE_rot);
            const auto check = [&](double sum, double sum2, double cross_sum, double theory,
                                   const char* what) {
                const double R = sum / sw;
                const double var = (sum2 - 2 * R * cross_sum + R * R * sw2) / (mean_w * mean_w * N * N);
                const double se = std::sqrt(var);
                EXPECT_NEAR(theory, R, 4 * se)
                    << what << " a=" << a << " b=" << b << " (N = " << samples << ")";
                EXPECT_LT(se, 0.02 * scale) << what; // the test resolves 2% of the energy exchanged
            };
            check(s_tr, s_tr2, c_tr, x.dE_tr, "dE_tr");
            check(s_rot, s_rot2, c_rot, x.dE_rot, "dE_rot");
        }
}

TEST(HcsTheory, CollisionAveragesMatchMonteCarloOfTheCollisionRule) {
    check_collision_averages(mixture(0.7, 0.4));
}

// The Maxwell kernel (theory.hpp): the same mixture with the initial T_tr of the frequencies.
HcsTheory maxwell_mixture(double alpha = 0.7, double beta = 0.4) {
    const HcsTheory h = mixture(alpha, beta);
    return HcsTheory(h.species(), h.pairs(), h.density(), {1.1, 0.6});
}

TEST(MaxwellTheory, CollisionAveragesMatchMonteCarloOfTheCollisionRule) {
    check_collision_averages(maxwell_mixture());
}

TEST(MaxwellTheory, FrequencyIsTheHardSphereOneOfTheInitialState) {
    // nu_ab = n_b sigma^2 sqrt(8 pi s_0) whatever the current temperatures.
    const HcsTheory m = maxwell_mixture();
    const HcsTheory h = mixture();
    const std::vector<double> T0{1.1, 0.6}, Tr{0.3, 0.2}, T{0.01, 0.5};
    for (std::size_t a = 0; a < 2; ++a)
        for (std::size_t b = 0; b < 2; ++b) {
            EXPECT_DOUBLE_EQ(m.exchange(a, b, T, Tr).frequency, h.exchange(a, b, T0, Tr).frequency);
            EXPECT_DOUBLE_EQ(m.exchange(a, b, T0, Tr).frequency, h.exchange(a, b, T0, Tr).frequency);
        }
}

TEST(MaxwellTheory, ElasticPerfectlyRoughConservesEnergy) {
    // alpha = beta = 1: one species and the unequal mixture (all pairs elastic, perfectly rough).
    HcsTrajectory one(HcsTheory({{1.0, 0.5, 0.4, 1.0}}, {{1.0, 1.0}}, 1.0, {1.0}), {{1.0}, {0.1}}, 1e-11);
    const HcsTheory h = mixture();
    HcsTrajectory two(HcsTheory(h.species(), {{1, 1}, {1, 1}, {1, 1}}, h.density(), {1.0, 2.0}),
                      {{1.0, 2.0}, {0.1, 0.5}}, 1e-11);
    for (double t : {0.5, 2.0, 10.0}) {
        const HcsTemperatures a = one.at(t), b = two.at(t);
        EXPECT_NEAR(a.T_tr[0] + a.T_rot[0], 1.1, 1e-9) << t;
        const double x0 = h.species()[0].fraction, x1 = h.species()[1].fraction;
        EXPECT_NEAR(x0 * (b.T_tr[0] + b.T_rot[0]) + x1 * (b.T_tr[1] + b.T_rot[1]),
                    x0 * 1.1 + x1 * 2.5, 1e-9)
            << t;
    }
    EXPECT_GT(one.at(20.0).T_rot[0], 0.5) << "the energy must have been exchanged";
}

TEST(MaxwellTheory, SmoothSpheresCoolExponentially) {
    // beta = -1: (3/2) dT/dt = nu <dE_tr> = -nu (1 - alpha^2) T/4, so T = T0 exp(-nu (1 - alpha^2) t/6)
    // with nu = 4 n sigma^2 sqrt(pi T0/m) (constant), and T_rot stays.
    const double alpha = 0.7, T0 = 2.0, m = 1.5, R = 0.4, n = 0.8;
    HcsTrajectory tr(HcsTheory({{m, R, 0.4, 1.0}}, {{alpha, -1.0}}, n, {T0}), {{T0}, {0.3}}, 1e-11);
    const double nu = 4 * n * 4 * R * R * std::sqrt(std::numbers::pi * T0 / m);
    for (double t : {0.3, 3.0, 30.0}) {
        const HcsTemperatures T = tr.at(t);
        EXPECT_NEAR(T.T_tr[0] / (T0 * std::exp(-nu * (1 - alpha * alpha) * t / 6)), 1.0, 1e-8) << t;
        EXPECT_NEAR(T.T_rot[0], 0.3, 1e-9); // integrated in ln E, tolerance 1e-11 per step
    }
}

TEST(HcsTheory, TwoEqualSpeciesAreOneSpecies) {
    const double alpha = 0.8, beta = 0.2;
    HcsTrajectory one(one_species(alpha, beta, 0.4, 1.5, 0.4, 2.0), {{1.0}, {0.3}});
    HcsTheory two_th({{1.5, 0.4, 0.4, 0.25}, {1.5, 0.4, 0.4, 0.75}},
                     {{alpha, beta}, {alpha, beta}, {alpha, beta}}, 2.0);
    HcsTrajectory two(two_th, {{1.0, 1.0}, {0.3, 0.3}});
    for (double t : {0.3, 3.0, 30.0}) {
        const HcsTemperatures a = one.at(t), b = two.at(t);
        EXPECT_NEAR(b.T_tr[0] / a.T_tr[0], 1.0, 1e-8);
        EXPECT_NEAR(b.T_tr[1] / a.T_tr[0], 1.0, 1e-8);
        EXPECT_NEAR(two_th.mixture_T_rot(b) / a.T_rot[0], 1.0, 1e-8);
    }
}

// The reduced cooling rate -(dT_tr/dt)/(T_tr nu_c): (1 - alpha^2)/3 per collision for smooth
// spheres at any temperature; (4/3)(A - B theta) for rough ones (dT/dt = G sqrt(T)(-A T + B T_rot),
// nu_c = 4 n sigma^2 sqrt(pi T/m) = (3/4) G sqrt(T)); a mixture of two equal species as one species.
TEST(HcsTheory, ReducedCoolingRatePerCollision) {
    for (double alpha : {0.3, 0.9, 1.0})
        for (double T : {1e-30, 1.0, 7.5}) {
            const HcsTheory th = one_species(alpha, -1.0, 0.4, 2.0, 0.3, 0.8);
            EXPECT_NEAR(reduced_cooling_rate(th, {{T}, {0.4}}), (1 - alpha * alpha) / 3, 1e-14) << alpha << " " << T;
        }
    for (double beta : {-0.5, 0.0, 1.0}) {
        const double alpha = 0.8, q = 0.4, T = 2.0, Tr = 0.7;
        const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, beta, q, 1.5, 0.8, 2.0);
        const HcsTheory th = one_species(alpha, beta, q, 1.5, 0.4, 2.0);
        EXPECT_NEAR(reduced_cooling_rate(th, {{T}, {Tr}}), 4.0 / 3.0 * (c.A - c.B * Tr / T), 1e-13) << beta;
        const HcsTheory two({{1.5, 0.4, q, 0.25}, {1.5, 0.4, q, 0.75}}, {{alpha, beta}, {alpha, beta}, {alpha, beta}},
                            2.0);
        EXPECT_NEAR(reduced_cooling_rate(two, {{T, T}, {Tr, Tr}}), reduced_cooling_rate(th, {{T}, {Tr}}), 1e-13)
            << beta;
    }
}

TEST(HcsTheory, LongTimeThetaIsTheClosedFormFixedPoint) {
    for (double alpha : {0.5, 0.9, 1.0})
        for (double beta : {-0.8, -0.3, 0.0, 0.5, 1.0})
            for (double q : {0.4, 0.5}) {
                HcsTrajectory tr(one_species(alpha, beta, q), {{1.0}, {0.05}}, 1e-11);
                // theta - theta* decays like a power of t while T cools (for alpha = 0.9, beta = -0.8
                // like t^-0.3, the slowest here), so go far: 1e40 mean free times (some 4000 steps).
                // alpha = beta = 1 does not cool: the time scale stays put, and theta = 1 by t = 100.
                const HcsTemperatures T = tr.at(alpha == 1 && beta == 1 ? 100.0 : 1e40);
                const double theta = T.T_rot[0] / T.T_tr[0];
                const double star = theta_fixed_point(alpha, beta, q);
                EXPECT_NEAR(theta / star, 1.0, 1e-7) << "alpha " << alpha << " beta " << beta << " q " << q;
            }
    // Limits: perfectly rough elastic -> 1; smooth -> diverges (T_rot frozen).
    EXPECT_NEAR(theta_fixed_point(1.0, 1.0, 0.4), 1.0, 1e-15);
    EXPECT_TRUE(std::isinf(theta_fixed_point(0.9, -1.0, 0.4)));
    // alpha = 0.9, beta = 1, q = 2/5 (the validation case of tests/io/run_cli_test.cpp):
    // theta* = 1.12312379718..., the root of B theta^2 + (C - A) theta - B = 0.
    const EqualSphereCoefficients c = equal_sphere_coefficients(0.9, 1.0, 0.4, 1, 1, 1);
    const double star = theta_fixed_point(0.9, 1.0, 0.4);
    EXPECT_NEAR(star, 1.1231237971808, 1e-12);
    EXPECT_NEAR(c.B * star * star + (c.C - c.A) * star - c.B, 0.0, 1e-15);
}

// cooling_reach: smooth grains lose (1 - alpha^2)/3 of T_tr per collision from the start, so the
// reach is ln(T0/(m floor)) over that; rough grains started at their fixed-point theta the same with
// the cooling state's zeta*, and from theta = 0 within a percent (the relaxation, some tens of
// collisions of the thousands); two equal species are the one; an elastic gas never gets there.
TEST(HcsTheory, CoolingReach) {
    const double floor = 1e-300;
    const HcsTheory smooth = one_species(0.8, -1.0, 0.4, 1.5);
    EXPECT_NEAR(cooling_reach(smooth, {{2.0}, {0.3}}, floor) / (std::log(2.0 / 1.5 / floor) / ((1 - 0.64) / 3)), 1.0,
                1e-9);
    const HcsTheory rough = one_species(0.9, 0.4);
    const HcsTemperatures at_star{{1.0}, {theta_fixed_point(0.9, 0.4, 0.4)}};
    const double expected = std::log(1.0 / floor) / reduced_cooling_rate(rough, at_star);
    EXPECT_NEAR(cooling_reach(rough, at_star, floor) / expected, 1.0, 1e-6);
    const double relaxed = cooling_reach(rough, {{1.0}, {0.0}}, floor);
    EXPECT_NEAR(relaxed / expected, 1.0, 0.01);
    EXPECT_NE(relaxed, expected);
    const HcsTheory two({{1.0, 0.5, 0.4, 0.25}, {1.0, 0.5, 0.4, 0.75}}, {{0.9, 0.4}, {0.9, 0.4}, {0.9, 0.4}}, 1.0);
    EXPECT_NEAR(cooling_reach(two, {{1.0, 1.0}, {0.0, 0.0}}, floor) / relaxed, 1.0, 1e-6);
    EXPECT_TRUE(std::isinf(cooling_reach(one_species(1.0, 1.0), {{1.0}, {0.0}}, floor)));
}

// cooling_reach_time: the time at which the trajectory itself gets T_tr/m down to the floor (Haff's
// law for smooth grains, the integrated equations for rough ones started at their fixed point),
// finite although the gas cools for ever; an elastic gas never gets there.
TEST(HcsTheory, CoolingReachTime) {
    const double floor = 1e-300;
    const HcsTheory smooth = one_species(0.8, -1.0, 0.4, 1.5);
    const double t_smooth = cooling_reach_time(smooth, {{2.0}, {0.3}}, floor);
    ASSERT_TRUE(std::isfinite(t_smooth));
    EXPECT_GT(t_smooth, 1e140);
    EXPECT_NEAR(HcsTrajectory(smooth, {{2.0}, {0.3}}).at(t_smooth).T_tr[0] / 1.5 / floor, 1.0, 1e-6);
    const HcsTheory rough = one_species(0.9, 0.4);
    const HcsTemperatures at_star{{1.0}, {theta_fixed_point(0.9, 0.4, 0.4)}};
    const double t_rough = cooling_reach_time(rough, at_star, floor);
    EXPECT_NEAR(HcsTrajectory(rough, at_star).at(t_rough).T_tr[0] / floor, 1.0, 1e-4);
    EXPECT_TRUE(std::isinf(cooling_reach_time(one_species(1.0, 1.0), {{1.0}, {0.0}}, floor)));
}

TEST(HcsTheory, RejectsInvalidParameters) {
    EXPECT_THROW(one_species(-0.1, 0.0), std::invalid_argument);
    EXPECT_THROW(one_species(0.9, 1.5), std::invalid_argument);
    EXPECT_THROW(one_species(0.9, 0.0, 0.0), std::invalid_argument);
    EXPECT_THROW(HcsTheory({{1, 1, 0.4, 1}}, {}, 1.0), std::invalid_argument);
    HcsTrajectory tr(one_species(0.9, 0.0), {{1.0}, {1.0}});
    tr.at(2.0);
    EXPECT_THROW(tr.at(1.0), std::invalid_argument);
}

TEST(HcsTheory, FromRunSpec) {
    RunSpec spec;
    spec.species = {SpeciesSpec{"a", 1, 0.5, 0.4, 1, 1.5, 0.5}};
    spec.pairs = {ConstantRestitution{0.9, 0.5}};
    ASSERT_TRUE(hcs_theory(spec).has_value());
    EXPECT_EQ(initial_temperatures(spec).T_tr[0], 1.5);
    spec.pairs = {CoulombRestitution{0.9, 0.5, 0.1}};
    EXPECT_FALSE(hcs_theory(spec).has_value());
}

} // namespace
} // namespace roughgas
