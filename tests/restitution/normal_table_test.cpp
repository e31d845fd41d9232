// The universal eps^N(w) table against the direct integrator (required: <= 1e-8 relative on >= 1e4
// random points), its monotonicity, the series below it and the extrapolation above it.
#include "roughgas/restitution/normal_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <random>

namespace roughgas {
namespace {

// Tables are built once per model and shared by the tests of this file.
const NormalTable& table_for(ContactModel model) {
    static std::map<std::pair<int, int>, std::unique_ptr<NormalTable>> tables;
    auto& slot = tables[{static_cast<int>(model.form), static_cast<int>(model.end)}];
    if (!slot) slot = std::make_unique<NormalTable>(NormalTable::build(model));
    return *slot;
}

class NormalTableTest : public ::testing::TestWithParam<ContactModel> {};

std::string model_name(const ::testing::TestParamInfo<ContactModel>& info) {
    return std::string(name(info.param.form)) + "_" + std::string(name(info.param.end));
}

INSTANTIATE_TEST_SUITE_P(AllModels, NormalTableTest,
                         ::testing::Values(ContactModel{NormalForm::eq24, ContactEnd::force},
                                           ContactModel{NormalForm::eq24, ContactEnd::separation},
                                           ContactModel{NormalForm::eq25, ContactEnd::force},
                                           ContactModel{NormalForm::eq25, ContactEnd::separation}),
                         model_name);

TEST_P(NormalTableTest, MatchesDirectPathOnRandomPoints) {
    const NormalTable& table = table_for(GetParam());
    const DirectNormal direct{GetParam(), Tolerance{1e-13, 1e-15}};
    std::mt19937_64 rng(20261121);
    // log-uniform over the whole table; 1e4 points, the required sample.
    std::uniform_real_distribution<double> lw(std::log(table.w_min()), std::log(table.w_max()));
    double worst = 0, worst_w = 0;
    for (int i = 0; i < 10000; ++i) {
        const double w = std::exp(lw(rng));
        const double ref = direct.eps_n(w);
        const double err = std::abs(table.eps_n(w) - ref) / ref;
        if (err > worst) { worst = err; worst_w = w; }
    }
    std::printf("  [%s/%s] %zu intervals, built in %.2f s, limited %d; worst relative error %.3g at w = %.6g\n",
                std::string(name(GetParam().form)).c_str(), std::string(name(GetParam().end)).c_str(),
                table.intervals(), table.build_seconds(), table.limited_intervals(), worst, worst_w);
    EXPECT_LE(worst, 1e-8) << "at w = " << worst_w;
}

TEST_P(NormalTableTest, IsMonotoneAndBounded) {
    const NormalTable& table = table_for(GetParam());
    // Dense sweep hitting every interval several times, plus both sides of every node.
    double prev = 1.0;
    for (double lw = std::log(table.w_min()) - 30; lw < std::log(table.w_max()) + 10; lw += 1e-3) {
        const double e = table.eps_n(std::exp(lw));
        ASSERT_LE(e, prev) << "w = " << std::exp(lw);
        ASSERT_GE(e, 0.0);
        ASSERT_LE(e, 1.0);
        prev = e;
    }
    EXPECT_EQ(table.eps_n(0.0), 1.0);
}

TEST_P(NormalTableTest, SeriesBelowTableMatchesDirectPath) {
    const NormalTable& table = table_for(GetParam());
    const DirectNormal direct{GetParam(), Tolerance{1e-13, 1e-15}};
    for (double w = table.w_min() * 0.999; w > 1e-30; w /= 7.3) {
        const double ref = direct.eps_n(w);
        EXPECT_NEAR(table.eps_n(w), ref, 1e-8 * ref) << "w = " << w;
    }
}

TEST_P(NormalTableTest, ContinuousAtBothEnds) {
    const NormalTable& table = table_for(GetParam());
    for (double edge : {table.w_min(), table.w_max()}) {
        const double lo = table.eps_n(std::nextafter(edge, 0.0)), hi = table.eps_n(edge);
        EXPECT_NEAR(lo, hi, 1e-9 * hi) << "edge w = " << edge;
    }
}

TEST_P(NormalTableTest, RoundTripsThroughSerializedForm) {
    const NormalTable& table = table_for(GetParam());
    const NormalTable copy = NormalTable::deserialize(GetParam(), table.options(), table.serialize());
    for (double w : {1e-25, 1e-17, 3.3e-9, 0.7, 1e3, 1e6})
        EXPECT_EQ(copy.eps_n(w), table.eps_n(w)) << "w = " << w;
    auto truncated = table.serialize();
    truncated.pop_back();
    EXPECT_THROW(NormalTable::deserialize(GetParam(), table.options(), truncated), std::runtime_error);
}

TEST(NormalTable, SeriesLeadingCoefficientIsPublishedC1) {
    // eq. 24: 1 - eps = C1 u + ..., C1 = 1.15344 (Ramirez, Poeschel, Brilliantov, Schwager 1999).
    const NormalTable& table = table_for({NormalForm::eq24, ContactEnd::separation});
    EXPECT_NEAR(table.series()[0], 1.15344, 5e-5);
}

TEST(NormalTable, CacheKeyNamesEverythingItDependsOn) {
    const NormalTable& a = table_for({NormalForm::eq24, ContactEnd::force});
    const NormalTable& b = table_for({NormalForm::eq24, ContactEnd::separation});
    const NormalTable& c = table_for({NormalForm::eq25, ContactEnd::force});
    EXPECT_NE(a.cache_key(), b.cache_key());
    EXPECT_NE(a.cache_key(), c.cache_key());
    EXPECT_NE(b.cache_key(), c.cache_key());
}

} // namespace
} // namespace roughgas
