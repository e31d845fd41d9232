// The collision rule of docs/model.md §3 (collision/rule.hpp), typed over every restitution
// policy: random states of unequal grains (masses, radii, q), random restitution, and the
// conservation laws and restitution identities checked per collision.
#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/collision/rule.hpp"
#include "roughgas/core/rng.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

namespace roughgas {
namespace {

// ---- fixtures: tables for the table policies, built once per binary ----
// Ice of Brilliantov et al. (1996) Fig. 2c.

ContactPair ice_pair() {
    const double R = 0.01, m = 4.0 / 3.0 * std::numbers::pi * R * R * R * 1000.0;
    Material mat{1e10, 0.3, 1e-5, std::sqrt(1e-3), 1e-3 * R / 2};
    return make_contact_pair(mat, {}, m, R, 0.4, m, R, 0.4);
}
const NormalTable& normal_table() {
    static const NormalTable t = NormalTable::build({});
    return t;
}
const TangentialTable& tangential_table() {
    static const TangentialTable t = [] {
        TangentialTableOptions opt;
        opt.g_min = 1e-3; // the states below have g_N < 0.9: few direct fall-backs, a 3 s build
        opt.g_max = 1.0;
        return TangentialTable::build(ice_pair(), opt);
    }();
    return t;
}

double log_uniform(Rng& r, double lo, double hi) {
    return lo * std::pow(hi / lo, uniform01(r));
}
double uniform(Rng& r, double lo, double hi) {
    return lo + (hi - lo) * uniform01(r);
}

// How each policy type is drawn at random.
template <class P> struct Draw;
template <> struct Draw<SmoothConstant> {
    static constexpr int trials = 10000;
    static SmoothConstant make(Rng& r, const PairConstants&) { return make_smooth_constant(uniform01(r)); }
};
template <> struct Draw<RoughConstant> {
    static constexpr int trials = 10000;
    static RoughConstant make(Rng& r, const PairConstants&) {
        return make_rough_constant(uniform01(r), uniform(r, -1, 1));
    }
};
template <> struct Draw<Coulomb> {
    static constexpr int trials = 10000;
    static Coulomb make(Rng& r, const PairConstants& pc) {
        return make_coulomb(uniform01(r), uniform(r, -1, 1), uniform(r, 0, 1), pc.kappa);
    }
};
template <> struct Draw<ViscoelasticSmooth> {
    static constexpr int trials = 10000;
    static ViscoelasticSmooth make(Rng&, const PairConstants&) {
        return make_viscoelastic_smooth(normal_table(), ice_pair());
    }
};
template <> struct Draw<Viscoelastic> {
    static constexpr int trials = 10000;
    static Viscoelastic make(Rng& r, const PairConstants&) {
        return make_viscoelastic(normal_table(), ice_pair(), uniform(r, -1, 1));
    }
};
template <> struct Draw<Brilliantov> {
    static constexpr int trials = 10000;
    static Brilliantov make(Rng&, const PairConstants&) {
        return make_brilliantov(normal_table(), tangential_table(), ice_pair());
    }
};
// Direct paths integrate each contact (~0.1 ms): fewer trials.
template <> struct Draw<ViscoelasticDirect> {
    static constexpr int trials = 500;
    static ViscoelasticDirect make(Rng& r, const PairConstants&) {
        return make_viscoelastic_direct(ice_pair(), uniform(r, -1, 1), Tolerance{});
    }
};
template <> struct Draw<BrilliantovDirect> {
    static constexpr int trials = 500;
    static BrilliantovDirect make(Rng&, const PairConstants&) {
        return make_brilliantov_direct(ice_pair(), Tolerance{});
    }
};

struct Grain {
    double m, R, q;
    Vec3 v, w;
    double J() const { return q * m * R * R; }
};

Vec3 random_vector(Rng& r, double scale) {
    return {scale * uniform(r, -1, 1), scale * uniform(r, -1, 1), scale * uniform(r, -1, 1)};
}

Vec3 random_unit(Rng& r) {
    for (;;) {
        const Vec3 x = random_vector(r, 1.0);
        const double n2 = norm2(x);
        if (n2 > 1e-4 && n2 <= 1.0)
            return (1.0 / std::sqrt(n2)) * x;
    }
}

// Contact velocity of docs/model.md §1.
Vec3 contact_velocity(const Grain& i, const Grain& j, const Vec3& n) {
    return i.v - j.v - cross(i.R * i.w, n) - cross(j.R * j.w, n);
}
double energy(const Grain& g) {
    return 0.5 * g.m * norm2(g.v) + 0.5 * g.J() * norm2(g.w);
}
// Angular momentum about the contact point: centres at +R_i n and -R_j n from it.
Vec3 angular_momentum(const Grain& i, const Grain& j, const Vec3& n) {
    return i.m * cross(i.R * n, i.v) + i.J() * i.w + j.m * cross(-j.R * n, j.v) + j.J() * j.w;
}
double angular_momentum_scale(const Grain& i, const Grain& j) {
    return i.m * i.R * norm(i.v) + i.J() * norm(i.w) + j.m * j.R * norm(j.v) + j.J() * norm(j.w);
}

template <class Policy>
CollisionRecord apply(const PairConstants& pc, const Policy& p, Grain& i, Grain& j, const Vec3& n) {
    if constexpr (Policy::needs_rotation)
        return collide(pc, p, i.v, i.w, j.v, j.w, n);
    else
        return collide(pc, p, i.v, j.v, n);
}

template <class Policy> class CollisionRuleTest : public ::testing::Test {};
using Policies = ::testing::Types<SmoothConstant, RoughConstant, Coulomb, ViscoelasticSmooth, Viscoelastic,
                                  Brilliantov, ViscoelasticDirect, BrilliantovDirect>;
TYPED_TEST_SUITE(CollisionRuleTest, Policies);

TYPED_TEST(CollisionRuleTest, ConservesMomentumAndAngularMomentumAndRestitutes) {
    using P = TypeParam;
    Rng rng = make_stream(11, Stream::test, 0, 0);
    int clamped = 0;
    for (int trial = 0; trial < Draw<P>::trials; ++trial) {
        // Unequal grains over two decades of mass and radius and the physical range of q.
        Grain i{log_uniform(rng, 0.1, 10), log_uniform(rng, 0.1, 10), uniform(rng, 0.05, 2.0 / 3.0), {}, {}};
        Grain j{log_uniform(rng, 0.1, 10), log_uniform(rng, 0.1, 10), uniform(rng, 0.05, 2.0 / 3.0), {}, {}};
        // Speeds up to 0.25 (m/s: inside the tables' g_N range), surface speeds R omega alike.
        i.v = random_vector(rng, 0.25);
        j.v = random_vector(rng, 0.25);
        i.w = random_vector(rng, 0.25 / i.R);
        j.w = random_vector(rng, 0.25 / j.R);
        Vec3 n = random_unit(rng);
        if (dot(i.v - j.v, n) > 0)
            n = -n; // approaching
        const PairConstants pc = make_pair_constants({i.m, i.R, i.q}, {j.m, j.R, j.q});
        const P policy = Draw<P>::make(rng, pc);

        const Grain i0 = i, j0 = j;
        const Vec3 g = contact_velocity(i0, j0, n);
        const double g_dot_n = dot(g, n);
        const Vec3 gN = g_dot_n * n, gT = g - gN;
        const CollisionRecord rec = apply(pc, policy, i, j, n);
        clamped += rec.beta_clamped;
        const double alpha = rec.alpha, beta = rec.beta;
        ASSERT_GE(alpha, 0.0);
        ASSERT_LE(alpha, 1.0);
        ASSERT_GE(beta, -1.0);
        ASSERT_LE(beta, 1.0);
        ASSERT_NEAR(rec.g_n, std::abs(g_dot_n), 1e-14 * norm(g));
        if constexpr (P::needs_rotation)
            ASSERT_NEAR(rec.g_t, norm(gT), 1e-14 * norm(g));
        else
            EXPECT_EQ(beta, -1.0);

        // Momentum, relative to the sum of the momenta's magnitudes: round-off of a few ulp.
        const Vec3 p0 = i0.m * i0.v + j0.m * j0.v, p1 = i.m * i.v + j.m * j.v;
        const double p_scale = i0.m * norm(i0.v) + j0.m * norm(j0.v) + i.m * norm(i.v) + j.m * norm(j.v);
        ASSERT_LE(norm(p1 - p0), 1e-13 * p_scale) << "trial " << trial;

        // Angular momentum about the contact point.
        const Vec3 L0 = angular_momentum(i0, j0, n), L1 = angular_momentum(i, j, n);
        ASSERT_LE(norm(L1 - L0), 1e-13 * (angular_momentum_scale(i0, j0) + angular_momentum_scale(i, j)))
            << "trial " << trial;

        // Energy: docs/model.md §3 with the pair's m_eff and kappa; measured from the states, whose
        // energies carry round-off of order 1e-16 E, so the bound is relative to the pair's energy.
        const double m_eff = i.m * j.m / (i.m + j.m);
        const double kappa = 1.0 / (1.0 + m_eff * (1.0 / (i.q * i.m) + 1.0 / (j.q * j.m)));
        const double dE = 0.5 * m_eff * (alpha * alpha - 1.0) * norm2(gN) +
                          0.5 * kappa * m_eff * (beta * beta - 1.0) * norm2(gT);
        const double E0 = energy(i0) + energy(j0), E1 = energy(i) + energy(j);
        ASSERT_LE(std::abs((E1 - E0) - dE), 1e-12 * E0) << "trial " << trial << " dE = " << dE;
        ASSERT_LE(dE, 0.0) << "a collision created energy";
        ASSERT_LE(std::abs(rec.dE_tr + rec.dE_rot - dE), 1e-12 * E0);
        const double dE_tr =
            0.5 * (i.m * norm2(i.v) + j.m * norm2(j.v) - i0.m * norm2(i0.v) - j0.m * norm2(j0.v));
        ASSERT_LE(std::abs(rec.dE_tr - dE_tr), 1e-12 * E0);

        // Restitution of the contact velocity: (g^N)' = -alpha g^N, (g^T)' = -beta g^T.
        const Vec3 g1 = contact_velocity(i, j, n);
        const Vec3 g1N = dot(g1, n) * n, g1T = g1 - g1N;
        const double g_scale = norm(i0.v) + norm(j0.v) + i0.R * norm(i0.w) + j0.R * norm(j0.w);
        ASSERT_LE(norm(g1N + alpha * gN), 1e-13 * g_scale) << "trial " << trial;
        ASSERT_LE(norm(g1T + beta * gT), 1e-13 * g_scale) << "trial " << trial;

        if constexpr (!P::needs_rotation) { // the smooth overload never writes omega
            ASSERT_EQ(std::memcmp(&i.w, &i0.w, sizeof(Vec3)), 0);
            ASSERT_EQ(std::memcmp(&j.w, &j0.w, sizeof(Vec3)), 0);
        }
    }
    if (clamped)
        std::printf("  beta clamped to [-1, 1] in %d of %d collisions\n", clamped, Draw<P>::trials);
}

TEST(CollisionRule, BetaMinusOneLeavesOmegaBitwiseUnchanged) {
    // The rough overload with beta = -1: (1 + beta) = 0 multiplies the whole angular update, so omega
    // is unchanged to the last bit, for any alpha, masses, radii, q.
    Rng rng = make_stream(12, Stream::test, 0, 0);
    for (int trial = 0; trial < 10000; ++trial) {
        Grain i{log_uniform(rng, 0.1, 10),
                log_uniform(rng, 0.1, 10),
                uniform(rng, 0.05, 2.0 / 3.0),
                random_vector(rng, 1),
                {}};
        Grain j{log_uniform(rng, 0.1, 10),
                log_uniform(rng, 0.1, 10),
                uniform(rng, 0.05, 2.0 / 3.0),
                random_vector(rng, 1),
                {}};
        i.w = random_vector(rng, 10);
        j.w = random_vector(rng, 10);
        const Grain i0 = i, j0 = j;
        const Vec3 n = random_unit(rng);
        const PairConstants pc = make_pair_constants({i.m, i.R, i.q}, {j.m, j.R, j.q});
        collide(pc, make_rough_constant(uniform01(rng), -1.0), i.v, i.w, j.v, j.w, n);
        ASSERT_EQ(std::memcmp(&i.w, &i0.w, sizeof(Vec3)), 0) << "trial " << trial;
        ASSERT_EQ(std::memcmp(&j.w, &j0.w, sizeof(Vec3)), 0) << "trial " << trial;
    }
}

TEST(CollisionRule, EqualSpheresMatchTheLiteratureForm) {
    // docs/model.md §3: v_1' = v_1 - ((1+alpha)/2) g^N - (q(1+beta)/(2(1+q))) g^T for equal spheres.
    const double m = 1.3, R = 0.7, q = 0.4, alpha = 0.8, beta = 0.3;
    Grain i{m, R, q, {0.3, -0.2, 0.5}, {1.0, 2.0, -0.5}}, j{m, R, q, {-0.4, 0.1, 0.2}, {-0.3, 0.4, 0.9}};
    const Vec3 n = (1.0 / std::sqrt(3.0)) * Vec3{1, 1, 1};
    const Vec3 g = contact_velocity(i, j, n);
    const Vec3 gN = dot(g, n) * n, gT = g - gN;
    const Vec3 expected = i.v - ((1 + alpha) / 2) * gN - (q * (1 + beta) / (2 * (1 + q))) * gT;
    collide(make_pair_constants({m, R, q}, {m, R, q}), make_rough_constant(alpha, beta), i.v, i.w, j.v, j.w,
            n);
    EXPECT_NEAR(i.v.x, expected.x, 1e-15);
    EXPECT_NEAR(i.v.y, expected.y, 1e-15);
    EXPECT_NEAR(i.v.z, expected.z, 1e-15);
    EXPECT_NEAR(make_pair_constants({m, R, q}, {m, R, q}).kappa, q / (1 + q), 1e-16); // 2/7 for q = 2/5
}

TEST(Coulomb, SlidesWithTangentialImpulseMuTimesNormal) {
    // Walton: sticking while kappa (1 + beta0) g_T <= mu (1 + alpha) g_N, else |P_T| = mu |P_N| exactly.
    Rng rng = make_stream(13, Stream::test, 0, 0);
    int sticking = 0, sliding = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        Grain i{log_uniform(rng, 0.1, 10),
                log_uniform(rng, 0.1, 10),
                uniform(rng, 0.05, 2.0 / 3.0),
                random_vector(rng, 1),
                {}};
        Grain j{log_uniform(rng, 0.1, 10),
                log_uniform(rng, 0.1, 10),
                uniform(rng, 0.05, 2.0 / 3.0),
                random_vector(rng, 1),
                {}};
        i.w = random_vector(rng, 1 / i.R);
        j.w = random_vector(rng, 1 / j.R);
        Vec3 n = random_unit(rng);
        if (dot(i.v - j.v, n) > 0)
            n = -n;
        const double alpha = uniform01(rng), beta0 = uniform(rng, -1, 1), mu = uniform(rng, 0, 0.5);
        const PairConstants pc = make_pair_constants({i.m, i.R, i.q}, {j.m, j.R, j.q});
        const Vec3 v0 = i.v;
        const CollisionRecord r =
            collide(pc, make_coulomb(alpha, beta0, mu, pc.kappa), i.v, i.w, j.v, j.w, n);
        // The impulse measured from the state change, which carries round-off of order
        // 1e-16 m |v| (a small impulse on a fast grain).
        const Vec3 P = i.m * (i.v - v0);
        const double P_N = std::abs(dot(P, n)), P_T = norm(P - dot(P, n) * n);
        const double tol = 1e-12 * (P_N + P_T) + 1e-14 * i.m * (norm(v0) + norm(i.v));
        if (r.beta == beta0) {
            ++sticking;
            ASSERT_LE(P_T, mu * P_N + tol);
        } else {
            ++sliding;
            ASSERT_LT(r.beta, beta0);
            ASSERT_NEAR(P_T, mu * P_N, tol);
        }
    }
    EXPECT_GT(sticking, 1000);
    EXPECT_GT(sliding, 1000);
}

TEST(AsperityModel, BetaAboveOneIsClampedAndCreatesNoEnergy) {
    // tests/contact/tangential_integrator_test.cpp: for an elastic normal motion (A = 0, u = 0),
    // (mu/kappa)/z = 1.54, z = zeta_0/(g_N T) = 1 and no asperity break, eps^T = -1.24, i.e. beta = 1.24.
    ContactPair pair =
        make_contact_pair(Material{1e10, 0.3, 0.0, 0.0, 0.0}, {}, 1e-3, 0.01, 0.4, 1e-3, 0.01, 0.4);
    const double g_n = 1.0;
    pair.mu = 1.54 * pair.kappa;
    pair.zeta0 = g_n * pair.hertz_time(g_n);
    const BrilliantovDirect policy = make_brilliantov_direct(pair, Tolerance{});
    const ContactResult raw = integrate_contact(pair, g_n, 1e-3 * g_n);
    ASSERT_GT(raw.beta, 1.2) << "the asperity model should exceed perfect reversal here";
    const Coefficients c = policy(g_n, 1e-3 * g_n);
    EXPECT_TRUE(c.beta_clamped);
    EXPECT_EQ(c.beta, 1.0);
    EXPECT_NEAR(c.alpha, 1.0, 1e-9);

    // Through the rule: the energy is conserved (alpha = 1 and |beta| = 1), never increased.
    const double m = 1e-3, R = 0.01;
    Grain i{m, R, 0.4, {0, 0, -0.5 * g_n}, {0, 1e-3 * g_n / R, 0}}, j{m, R, 0.4, {0, 0, 0.5 * g_n}, {}};
    const Vec3 n{0, 0, 1};
    const double E0 = energy(i) + energy(j);
    const CollisionRecord r =
        collide(make_pair_constants({m, R, 0.4}, {m, R, 0.4}), policy, i.v, i.w, j.v, j.w, n);
    EXPECT_TRUE(r.beta_clamped);
    EXPECT_LE(energy(i) + energy(j), E0 * (1 + 1e-12));
    EXPECT_EQ(clamp_beta(0.5, -1.3).beta, -1.0);
    EXPECT_TRUE(clamp_beta(0.5, -1.3).beta_clamped);
    EXPECT_FALSE(clamp_beta(0.5, 0.99).beta_clamped);
}

} // namespace
} // namespace roughgas
