// The order of pass 2: which table is built, checked and noted when. Each table's own build, checks
// and emission are in its file (run_table.cpp, species_table.cpp, ...); messages without a position
// in the file (keys set with --set, missing keys) are listed in the order they are found here.
// A new table: its keys in io/case_schema.cpp, a file of its own beside these, and its calls in
// build_tables and check_tables below and in emit_case (case_emission.cpp).
#include "case_builder.hpp"

#include "build_context.hpp"
#include "collision_tables.hpp"
#include "contact_table.hpp"
#include "domain_table.hpp"
#include "fields_table.hpp"
#include "initial_table.hpp"
#include "material_table.hpp"
#include "restitution_table.hpp"
#include "run_table.hpp"
#include "shear_table.hpp"
#include "species_table.hpp"
#include "spectra_table.hpp"
#include "thermostat_table.hpp"
#include "toml_access.hpp"
#include "wall_tables.hpp"

namespace roughgas::case_file {
namespace {

CaseConfig build_tables(BuildContext& ctx) {
    const toml::table& root = ctx.root();
    CaseConfig c;
    c.run = build_run(Reader(root["run"].as_table(), "run"));
    if (const toml::array* a = root["species"].as_array()) {
        for (const toml::node& n : *a)
            c.species.push_back(build_species(ctx, Reader(n.as_table(), "species")));
    }
    const toml::table* collision = root["collision"].as_table();
    c.collision = build_collision(Reader(collision, "collision"));
    if (const toml::array* a = root["pair"].as_array()) {
        for (const toml::node& n : *a)
            c.pairs.push_back(build_pair(*n.as_table(), collision));
    }
    if (const toml::table* m = root["material"].as_table())
        c.material = build_material(ctx, Reader(m, "material"));
    c.contact = build_contact(Reader(root["contact"].as_table(), "contact"));
    c.shear = build_shear(root);
    c.thermostat = build_thermostat(root);
    c.species_thermostats = build_species_thermostats(root);
    c.domain = build_domain(ctx);
    build_walls(root, c);
    c.initial = build_initial(root);
    c.spectra = build_spectra(root);
    c.fields = build_fields(root);
    c.restitution = build_restitution_grid(Reader(root["restitution"].as_table(), "restitution"));
    return c;
}

void check_tables(BuildContext& ctx, const CaseConfig& c) {
    check_species(ctx, c);
    check_collisions(ctx, c); // records which models need [material]
    check_material(ctx, c);
    check_shear(ctx, c);
    check_thermostat(ctx, c);
    if (c.domain) {
        check_domain(ctx, c);
        check_walls(ctx, c);
        check_wave_resolution(ctx, c);
        check_cell_size(ctx, c);
    }
    check_initial(ctx, c);
    check_spectra(ctx, c);
    check_fields(ctx, c);
    check_run(ctx, c);
    check_restitution_grid(ctx, c.restitution);
}

// Keys and tables the run will not read: kept in the case (a --set may switch the model or the
// run kind), reported as warnings (CaseConfig::unused).
void note_unused(const BuildContext& ctx, CaseConfig& c) {
    note_unused_collision_keys(ctx.root(), c);
    note_unused_walls(ctx.root(), c);
    note_unused_shear(ctx.root(), c);
    note_unused_enskog(ctx.root(), c);
    note_unused_material(ctx, c);
}

} // namespace

CaseConfig build_case(const toml::table& root, CaseUse use, Diagnostics& d) {
    BuildContext ctx(root, use, d);
    CaseConfig c = build_tables(ctx);
    check_tables(ctx, c);
    note_unused(ctx, c);
    return c;
}

} // namespace roughgas::case_file
