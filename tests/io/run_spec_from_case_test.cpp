// CaseConfig -> RunSpec (io/run_spec_from_case.hpp): output times, species, per-pair models.
#include "roughgas/io/run_spec_from_case.hpp"

#include <gtest/gtest.h>

namespace roughgas {
namespace {

TEST(OutputTimes, LinearAndLogarithmic) {
    EXPECT_EQ(output_times(1.0, 4.0, OutputSpacing::linear), (std::vector<double>{1, 2, 3, 4}));
    EXPECT_EQ(output_times(1.5, 4.0, OutputSpacing::linear), (std::vector<double>{1.5, 3, 4}));
    EXPECT_EQ(output_times(5.0, 4.0, OutputSpacing::linear), (std::vector<double>{4}));
    const auto t = output_times(0.1, 10.0, OutputSpacing::log); // ten per decade from 0.1 to 10
    ASSERT_EQ(t.size(), 21u);
    EXPECT_DOUBLE_EQ(t[0], 0.1);
    EXPECT_NEAR(t[10], 1.0, 1e-15);
    EXPECT_EQ(t.back(), 10.0);
    for (std::size_t k = 1; k < t.size(); ++k)
        EXPECT_GT(t[k], t[k - 1]);
    EXPECT_THROW(output_times(0.0, 1.0, OutputSpacing::linear), std::invalid_argument);
}

CaseConfig mixture_case() {
    CaseConfig c;
    c.run.particles = 1000;
    c.run.density = 2;
    c.run.seed = 9;
    c.run.replicas = 3;
    c.run.end = 3;
    SpeciesConfig a, b;
    a.name = "a";
    a.mass = 1;
    a.radius = 0.5;
    a.fraction = 0.4;
    b.name = "b";
    b.mass = 2;
    b.radius = 0.7;
    b.inertia = 0.5;
    b.fraction = 0.6;
    b.temperature = 3;
    c.species = {a, b};
    c.collision.model = CollisionModel::constant;
    c.collision.alpha = 0.9;
    c.collision.beta = 0.2;
    PairConfig p;
    p.species = {"b", "a"};
    p.collision.model = CollisionModel::coulomb;
    p.collision.alpha = 0.8;
    p.collision.beta0 = 0.5;
    p.collision.friction = 0.3;
    c.pairs = {p};
    return c;
}

TEST(RunSpecFromCase, CopiesSpeciesRunAndPairModels) {
    const RunSpec s = run_spec_from_case(mixture_case());
    ASSERT_EQ(s.species.size(), 2u);
    EXPECT_EQ(s.species[1].name, "b");
    EXPECT_EQ(s.species[1].inertia, 0.5);
    EXPECT_EQ(s.species[1].temperature, 3);
    EXPECT_EQ(s.particles, 1000);
    EXPECT_EQ(s.density, 2);
    EXPECT_EQ(s.seed, 9u);
    EXPECT_EQ(s.replicas, 3);
    EXPECT_EQ(s.output_times, (std::vector<double>{1, 2, 3}));
    ASSERT_EQ(s.pairs.size(), 3u);
    const auto& aa = std::get<ConstantRestitution>(s.pairs[pair_index(0, 0, 2)]);
    EXPECT_EQ(aa.alpha, 0.9);
    EXPECT_EQ(aa.beta, 0.2);
    const auto& ab = std::get<CoulombRestitution>(s.pairs[pair_index(0, 1, 2)]); // the [[pair]] table
    EXPECT_EQ(ab.alpha, 0.8);
    EXPECT_EQ(ab.beta0, 0.5);
    EXPECT_EQ(ab.mu, 0.3);
    EXPECT_TRUE(std::holds_alternative<ConstantRestitution>(s.pairs[pair_index(1, 1, 2)]));
}

TEST(RunSpecFromCase, ViscoelasticPairsCarryTheirContactConstants) {
    CaseConfig c = mixture_case();
    c.pairs.clear();
    c.collision.model = CollisionModel::viscoelastic;
    c.collision.beta.reset();
    c.collision.direct = true;
    c.material = MaterialConfig{1e10, 0.3, 1e-5, {}, {}, {}, {}};
    c.contact.cache = false;
    c.contact.cache_file = "tables.bin";
    const RunSpec s = run_spec_from_case(c);
    const auto& ab = std::get<ViscoelasticRestitution>(s.pairs[pair_index(0, 1, 2)]);
    EXPECT_EQ(ab.beta, -1.0); // viscoelastic without beta: smooth
    EXPECT_TRUE(ab.direct);
    EXPECT_EQ(ab.pair, contact_pair(c, 0, 1));
    EXPECT_FALSE(s.use_cache);
    EXPECT_EQ(s.cache_file, "tables.bin");
}

TEST(RunSpecFromCase, ShearCarriesRateAndStep) {
    CaseConfig c = mixture_case();
    c.run.kind = RunKind::shear;
    EXPECT_THROW(run_spec_from_case(c), std::invalid_argument); // no [shear]: the parser rejects it first
    c.shear = ShearConfig{0.25, 0.05};
    const RunSpec s = run_spec_from_case(c);
    ASSERT_TRUE(s.shear.has_value());
    EXPECT_EQ(s.shear->rate, 0.25);
    EXPECT_EQ(s.shear->time_step, 0.05);
    c.run.kind = RunKind::cooling; // [shear] is ignored by cooling runs
    EXPECT_FALSE(run_spec_from_case(c).shear.has_value());
}

} // namespace
} // namespace roughgas
