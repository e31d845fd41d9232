// Persisted restitution tables: a table is reused only under its exact key, and a truncated or
// corrupt cache file is rejected and rebuilt.
#include "roughgas/io/table_cache_file.hpp"
#include "roughgas/restitution/normal_table.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

// A small grid keeps each build cheap; the mechanics do not depend on the grid's size.
NormalTableOptions small_grid() {
    NormalTableOptions o;
    o.e_min = -12;
    o.e_max = 2;
    o.mantissa_bits = 2;
    return o;
}

struct CacheDir : ::testing::Test {
    fs::path dir = fs::temp_directory_path() / ("roughgas_cache_test_" + std::to_string(::getpid()) + "_" +
                                                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::path file = dir / "tables.bin";
    void SetUp() override { fs::create_directories(dir); }
    void TearDown() override { fs::remove_all(dir); }

    // Loads (or builds) the table of `model` through the cache file, as a run would.
    NormalTable load(ContactModel model, bool* was_loaded, std::string* rejected = nullptr) {
        TableCacheFile cache(file);
        if (rejected) *rejected = cache.rejected();
        const NormalTableOptions opt = small_grid();
        NormalTable t = load_or_build<NormalTable>(
            &cache, NormalTable::key_for(model, opt), [&] { return NormalTable::build(model, opt); },
            [&](const std::vector<double>& d) { return NormalTable::deserialize(model, opt, d); }, was_loaded);
        cache.save_if_changed();
        return t;
    }
};

TEST_F(CacheDir, SecondRunLoadsWhatTheFirstBuilt) {
    bool loaded = true;
    const NormalTable built = load({}, &loaded);
    EXPECT_FALSE(loaded);
    ASSERT_TRUE(fs::exists(file));
    const NormalTable again = load({}, &loaded);
    EXPECT_TRUE(loaded);
    for (double w : {1e-5, 0.01, 1.0}) EXPECT_EQ(again.eps_n(w), built.eps_n(w));
}

TEST_F(CacheDir, ChangedParameterRebuildsAndDropsTheStaleEntry) {
    bool loaded = true;
    load({NormalForm::eq24, ContactEnd::force}, &loaded);
    load({NormalForm::eq24, ContactEnd::separation}, &loaded);
    EXPECT_FALSE(loaded) << "a table for another contact end must not come from the cache";
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    const auto entries = TableCacheFile::decode(bytes);
    ASSERT_EQ(entries.size(), 1u);
    EXPECT_NE(entries.begin()->first.find("end=separation"), std::string::npos);
}

TEST_F(CacheDir, TruncatedFileIsRejectedAndRebuilt) {
    bool loaded = true;
    const NormalTable built = load({}, &loaded);
    fs::resize_file(file, fs::file_size(file) - 13);
    std::string rejected;
    const NormalTable rebuilt = load({}, &loaded, &rejected);
    EXPECT_FALSE(loaded);
    EXPECT_NE(rejected.find("checksum"), std::string::npos) << rejected;
    EXPECT_EQ(rebuilt.eps_n(0.3), built.eps_n(0.3));
    load({}, &loaded, &rejected); // the rebuilt file is whole again
    EXPECT_TRUE(loaded);
    EXPECT_TRUE(rejected.empty()) << rejected;
}

TEST_F(CacheDir, FlippedByteIsDetected) {
    bool loaded = true;
    load({}, &loaded);
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(100);
        char c;
        f.read(&c, 1);
        f.seekp(100);
        c ^= 0x10;
        f.write(&c, 1);
    }
    std::string rejected;
    load({}, &loaded, &rejected);
    EXPECT_FALSE(loaded);
    EXPECT_FALSE(rejected.empty());
}

TEST(TableCacheFile, EncodeDecodeRoundTripAndRejectsGarbage) {
    const std::map<std::string, std::vector<double>> e{{"a", {1.0, 2.0}}, {"b b", {}}, {"c", {-0.0, 1e-300}}};
    EXPECT_EQ(TableCacheFile::decode(TableCacheFile::encode(e)), e);
    EXPECT_THROW(TableCacheFile::decode("RGTCACHE"), std::runtime_error);
    EXPECT_THROW(TableCacheFile::decode(std::string(64, 'x')), std::runtime_error);
}

} // namespace
} // namespace roughgas
