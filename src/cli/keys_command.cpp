// roughgas keys (hidden): prints the README's generated tables, so the README can be refreshed
// from the schema (tests/io/readme_test.cpp fails when they differ).
#include "commands.hpp"

#include "roughgas/io/case_schema.hpp"
#include "roughgas/io/histograms_csv.hpp"
#include "roughgas/io/moments_csv.hpp"
#include "roughgas/io/restitution_csv.hpp"

#include <iostream>
#include <memory>

namespace roughgas::cli {

Subcommand add_keys_command(CLI::App& parent) {
    auto output = std::make_shared<bool>(false);
    CLI::App* app = parent.add_subcommand("keys", "print the README tables of case-file keys");
    app->group(""); // hidden from --help: a maintenance tool
    app->add_flag("--output", *output, "print the tables of output columns instead");
    return {app, [output] {
                if (*output) {
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
