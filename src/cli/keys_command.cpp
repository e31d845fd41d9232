// roughgas keys: prints the generated tables of docs/reference.md (case-file keys, output columns,
// command-line options), so the reference can be refreshed from the code; tests/io/reference_test.cpp
// fails when the reference and these tables differ.
#include "commands.hpp"

#include "roughgas/io/case_schema.hpp"
#include "roughgas/io/histograms_csv.hpp"
#include "roughgas/io/moments_csv.hpp"
#include "roughgas/io/restitution_csv.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <string>

namespace roughgas::cli {

namespace {

// What an option takes: "-" for a flag, else its value's name, "(repeatable)" when it may be given
// more than once.
std::string value_text(const CLI::Option& o) {
    std::string v = o.get_type_name();
    if (v.empty()) // a flag
        return "-";
    if (v.rfind("ENUM", 0) == 0) // the allowed words are in the description
        v = "WORD";
    if (o.get_expected_max() > 1 || o.get_multi_option_policy() == CLI::MultiOptionPolicy::TakeAll)
        v += " (repeatable)";
    return v;
}

std::string options_table(const CLI::App& app, const std::string& command) {
    std::string md = fmt::format("`{}`: {}\n\n", command, markdown_cell(app.get_description()));
    md += "| Option | Value | Required | Description |\n|--------|-------|----------|-------------|\n";
    for (const CLI::Option* o : app.get_options()) {
        std::string name = o->get_name();
        if (o->get_positional() && o->get_lnames().empty() && o->get_snames().empty())
            name = o->get_name(true, false);
        md += fmt::format("| `{}` | {} | {} | {} |\n", name, markdown_cell(value_text(*o)), o->get_required() ? "yes" : "no",
                          markdown_cell(o->get_description()));
    }
    return md;
}

} // namespace

std::string cli_options_markdown(const CLI::App& root) {
    std::string md = options_table(root, "roughgas");
    for (const CLI::App* sub : root.get_subcommands({})) {
        md += '\n';
        md += options_table(*sub, "roughgas " + sub->get_name());
    }
    return md;
}

Subcommand add_keys_command(CLI::App& parent) {
    auto output = std::make_shared<bool>(false);
    auto cli = std::make_shared<bool>(false);
    CLI::App* app = parent.add_subcommand(
        "keys", "print the generated tables of docs/reference.md: case-file keys (default), output "
                "columns (--output) or command-line options (--cli)");
    CLI::Option* output_flag = app->add_flag("--output", *output, "print the tables of output columns");
    app->add_flag("--cli", *cli, "print the tables of command-line options")->excludes(output_flag);
    return {app, [output, cli, &parent] {
                if (*cli) {
                    std::cout << cli_options_markdown(parent);
                } else if (*output) {
                    std::cout << restitution_columns_markdown() << '\n'
                              << moments_columns_markdown() << '\n'
                              << histograms_columns_markdown();
                } else {
                    std::cout << case_tables_markdown() << '\n' << case_keys_markdown();
                }
                return exit_ok;
            }};
}

} // namespace roughgas::cli
