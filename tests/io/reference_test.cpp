// docs/reference.md is the contract users script against: it lists every case-file key, output
// column, command-line option, script flag, configure option and environment variable exactly as the
// code defines them. On failure, refresh it from `roughgas keys`, `roughgas keys --output` and
// `roughgas keys --cli`, or add the line the message names.
#include "io_test_support.hpp"

#include "roughgas/io/case_schema.hpp"
#include "roughgas/io/histograms_csv.hpp"
#include "roughgas/io/moments_csv.hpp"
#include "roughgas/io/restitution_csv.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <set>

namespace roughgas {
namespace {

const std::string source_dir = ROUGHGAS_SOURCE_DIR;

// With a leading newline, so that every heading is preceded by one.
std::string reference() {
    std::string text = "\n";
    text += test::read_file(source_dir + "/docs/reference.md");
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

// Every match of group 1 of `pattern` in the files of `dir` whose names end in `suffix`.
std::set<std::string> matches_in(const std::string& dir, const std::string& suffix, const std::regex& pattern) {
    std::set<std::string> found;
    for (const auto& e : test::fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (!e.is_regular_file() || name.size() < suffix.size() ||
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
            continue;
        const std::string text = test::read_file(e.path());
        for (std::sregex_iterator m(text.begin(), text.end(), pattern), end; m != end; ++m)
            found.insert((*m)[1].str());
    }
    return found;
}

TEST(Reference, DocumentsEveryCaseKey) {
    const std::string keys = section(reference(), "Case-file keys");
    ASSERT_FALSE(keys.empty()) << "docs/reference.md has no section '## Case-file keys'";
    for (const KeySpec& k : case_schema()) {
        EXPECT_NE(keys.find("| `" + k.path + "` |"), std::string::npos) << k.path << " is not in docs/reference.md";
    }
    // Units, defaults and ranges too: the whole generated table, verbatim.
    EXPECT_NE(keys.find(case_keys_markdown()), std::string::npos) << "regenerate with `roughgas keys`:\n"
                                                                  << case_keys_markdown();
    EXPECT_NE(keys.find(case_tables_markdown()), std::string::npos) << case_tables_markdown();
}

TEST(Reference, DocumentsEveryOutputColumn) {
    const std::string columns = section(reference(), "Output files");
    ASSERT_FALSE(columns.empty()) << "docs/reference.md has no section '## Output files'";
    for (const std::string& table :
         {restitution_columns_markdown(), moments_columns_markdown(), histograms_columns_markdown()}) {
        EXPECT_NE(columns.find(table), std::string::npos) << "regenerate with `roughgas keys --output`:\n" << table;
    }
}

// The option tables come from the command-line parser itself (`roughgas keys --cli`), so an option
// added to a command without its line in the reference fails here.
TEST(Reference, DocumentsEveryCommandLineOption) {
    const std::string commands = section(reference(), "Commands");
    ASSERT_FALSE(commands.empty()) << "docs/reference.md has no section '## Commands'";
    const test::ScratchDir dir;
    const test::CommandResult r = test::run_roughgas("keys --cli", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_NE(r.out.find("`roughgas run`"), std::string::npos) << r.out;
    EXPECT_NE(commands.find(r.out), std::string::npos) << "regenerate with `roughgas keys --cli`:\n" << r.out;
}

// Every command's --help points to the reference.
TEST(Reference, EveryHelpEndsWithAPointerToTheReference) {
    const test::ScratchDir dir;
    for (const std::string command : {"", "run ", "check ", "restitution ", "sweep ", "keys "}) {
        const test::CommandResult r = test::run_roughgas(command + "--help", dir);
        EXPECT_EQ(r.status, 0) << command;
        EXPECT_NE(r.out.find("docs/reference.md"), std::string::npos) << "roughgas " << command << "--help:\n" << r.out;
    }
}

TEST(Reference, DocumentsEveryExitStatus) {
    const std::string text = section(reference(), "Exit status");
    ASSERT_FALSE(text.empty()) << "docs/reference.md has no section '## Exit status'";
    for (const std::string status : {"0", "1", "2", "130", "143"})
        EXPECT_NE(text.find("| " + status + " |"), std::string::npos) << "exit status " << status;
}

// The flags of every script in scripts/ (argparse: each on its script's row of the table), the
// environment variables the shell scripts read and the configure options of CMakeLists.txt.
TEST(Reference, DocumentsEveryScriptFlagVariableAndConfigureOption) {
    const std::string scripts = section(reference(), "Scripts");
    ASSERT_FALSE(scripts.empty()) << "docs/reference.md has no section '## Scripts'";
    const std::regex flag_pattern(R"~(add_argument\(\s*"(--[a-z0-9-]+)")~");
    std::size_t flags = 0;
    for (const auto& e : test::fs::directory_iterator(source_dir + "/scripts")) {
        if (e.path().extension() != ".py")
            continue;
        const std::string name = "scripts/" + e.path().filename().string();
        const std::string text = test::read_file(e.path());
        for (std::sregex_iterator m(text.begin(), text.end(), flag_pattern), end; m != end; ++m) {
            ++flags;
            const std::string flag = (*m)[1].str();
            const std::size_t at = scripts.find(name + " ");
            ASSERT_NE(at, std::string::npos) << name << " has no row in '## Scripts'";
            const std::string row = scripts.substr(at, scripts.find('\n', at) - at);
            EXPECT_TRUE(std::regex_search(row, std::regex(flag + "(?![a-z0-9-])"))) << name << " " << flag;
        }
    }
    EXPECT_GT(flags, 10U);

    const std::string environment = section(reference(), "Environment and build options");
    ASSERT_FALSE(environment.empty()) << "docs/reference.md has no section '## Environment and build options'";
    std::set<std::string> variables =
        matches_in(source_dir + "/scripts", ".sh", std::regex(R"~(\$\{(ROUGHGAS_[A-Z_]+))~"));
    for (const std::string& v : matches_in(source_dir + "/.ci", "run", std::regex(R"~(\b(ROUGHGAS_[A-Z_]+)=)~")))
        variables.insert(v);
    EXPECT_GE(variables.size(), 3U);
    for (const std::string& v : variables)
        EXPECT_NE(environment.find("`" + v + "`"), std::string::npos) << "environment variable " << v;
    const std::set<std::string> options =
        matches_in(source_dir, "CMakeLists.txt", std::regex(R"~(option\((ROUGHGAS_[A-Z_]+))~"));
    EXPECT_GE(options.size(), 2U);
    for (const std::string& o : options)
        EXPECT_NE(environment.find("`" + o + "`"), std::string::npos) << "configure option " << o;
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
            if (k.type == KeyType::string_list) {
                EXPECT_FALSE(k.default_list().empty()) << k.path;
                for (const std::string& w : k.default_list())
                    EXPECT_TRUE(k.allows(w)) << k.path << ": " << w;
            } else {
                EXPECT_TRUE(k.allows(*s)) << k.path;
            }
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
