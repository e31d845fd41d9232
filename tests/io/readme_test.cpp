// The README documents every case-file key and output column exactly as the code defines them
// (style.md §2.13). On failure, refresh the README from `roughgas keys` and `roughgas keys --output`.
#include "io_test_support.hpp"

#include "roughgas/io/case_schema.hpp"
#include "roughgas/io/histograms_csv.hpp"
#include "roughgas/io/moments_csv.hpp"
#include "roughgas/io/restitution_csv.hpp"

#include <gtest/gtest.h>

namespace roughgas {
namespace {

// With a leading newline, so that every heading is preceded by one.
std::string readme() {
    std::string text = "\n";
    text += test::read_file(std::string(ROUGHGAS_SOURCE_DIR) + "/README.md");
    return text;
}

// The text of the section `## title`, up to the next `## ` heading.
std::string section(const std::string& text, const std::string& title) {
    const std::size_t start = text.find(std::string("\n## ").append(title).append("\n"));
    if (start == std::string::npos)
        return {};
    const std::size_t end = text.find("\n## ", start + 1);
    return text.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

TEST(Readme, DocumentsEveryCaseKey) {
    const std::string keys = section(readme(), "Case file keys");
    ASSERT_FALSE(keys.empty()) << "README.md has no section '## Case file keys'";
    for (const KeySpec& k : case_schema()) {
        EXPECT_NE(keys.find("| `" + k.path + "` |"), std::string::npos) << k.path << " is not in the README";
    }
    // Units, defaults and ranges too: the whole generated table, verbatim.
    EXPECT_NE(keys.find(case_keys_markdown()), std::string::npos) << "regenerate with `roughgas keys`:\n"
                                                                  << case_keys_markdown();
    EXPECT_NE(keys.find(case_tables_markdown()), std::string::npos) << case_tables_markdown();
}

TEST(Readme, DocumentsRestitutionColumns) {
    const std::string output = section(readme(), "Output");
    ASSERT_FALSE(output.empty()) << "README.md has no section '## Output'";
    EXPECT_NE(output.find(restitution_columns_markdown()), std::string::npos)
        << "regenerate with `roughgas keys --output`:\n"
        << restitution_columns_markdown();
}

// Enforced once README.md has the section (the DSMC's README text is merged separately).
TEST(Readme, DocumentsMomentsColumns) {
    const std::string columns = section(readme(), "moments.csv columns");
    if (columns.empty()) GTEST_SKIP() << "README.md has no section '## moments.csv columns' yet";
    EXPECT_NE(columns.find(moments_columns_markdown()), std::string::npos)
        << "regenerate with `roughgas keys --output`:\n"
        << moments_columns_markdown();
}

TEST(Readme, DocumentsHistogramsColumns) {
    const std::string columns = section(readme(), "histograms.csv columns");
    ASSERT_FALSE(columns.empty()) << "README.md has no section '## histograms.csv columns'";
    EXPECT_NE(columns.find(histograms_columns_markdown()), std::string::npos)
        << "regenerate with `roughgas keys --output`:\n"
        << histograms_columns_markdown();
}

TEST(Schema, EveryKeyIsWellFormed) {
    for (const KeySpec& k : case_schema()) {
        EXPECT_NE(find_table(k.table()), nullptr) << k.path;
        EXPECT_FALSE(k.description.empty()) << k.path;
        EXPECT_EQ(find_key(k.path), &k) << "duplicate " << k.path;
        if (k.need == Need::defaulted) {
            EXPECT_FALSE(std::holds_alternative<std::monostate>(k.default_value)) << k.path;
        }
        if (k.need == Need::conditional) {
            EXPECT_FALSE(k.note.empty()) << k.path;
        }
        if (const auto* d = std::get_if<double>(&k.default_value)) {
            EXPECT_TRUE(k.allows(*d)) << k.path << ": default outside the allowed range";
        }
        if (const auto* s = std::get_if<std::string>(&k.default_value)) {
            EXPECT_TRUE(k.allows(*s)) << k.path;
        }
    }
}

TEST(Schema, AllowedTexts) {
    EXPECT_EQ(find_key("material.young_modulus")->allowed(), "> 0");
    EXPECT_EQ(find_key("material.poisson_ratio")->allowed(), "in (-1, 0.5)");
    EXPECT_EQ(find_key("collision.alpha")->allowed(), "in [0, 1]");
    EXPECT_EQ(find_key("species.inertia")->allowed(), "in (0, 2/3]");
    EXPECT_EQ(find_key("contact.form")->allowed(), "one of \"eq24\", \"eq25\"");
    EXPECT_EQ(toml_real(1.0), "1.0");
    EXPECT_EQ(toml_real(1e-12), "1e-12");
    EXPECT_EQ(toml_real(0.1), "0.1");
}

} // namespace
} // namespace roughgas
