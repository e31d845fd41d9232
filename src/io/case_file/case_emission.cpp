// emit_case: the resolved case as TOML, its tables in this order; each table's file writes its keys.
#include "roughgas/io/case_file.hpp"

#include "collision_tables.hpp"
#include "contact_table.hpp"
#include "domain_table.hpp"
#include "emitter.hpp"
#include "fields_table.hpp"
#include "initial_table.hpp"
#include "material_table.hpp"
#include "restitution_table.hpp"
#include "run_table.hpp"
#include "shear_table.hpp"
#include "species_table.hpp"
#include "spectra_table.hpp"
#include "thermostat_table.hpp"
#include "wall_tables.hpp"

namespace roughgas {

std::string emit_case(const CaseConfig& c) {
    case_file::Emitter e;
    case_file::emit_run(e, c.run);
    case_file::emit_species(e, c.species);
    case_file::emit_collision(e, c.collision);
    case_file::emit_pairs(e, c.pairs);
    if (c.material)
        case_file::emit_material(e, *c.material);
    case_file::emit_contact(e, c.contact);
    if (c.shear)
        case_file::emit_shear(e, *c.shear);
    if (c.thermostat)
        case_file::emit_thermostat(e, *c.thermostat);
    case_file::emit_species_thermostats(e, c.species_thermostats);
    if (c.initial)
        case_file::emit_initial(e, *c.initial);
    if (c.domain)
        case_file::emit_domain(e, *c.domain);
    if (c.spectra)
        case_file::emit_spectra(e, *c.spectra);
    if (c.fields)
        case_file::emit_fields(e, *c.fields);
    case_file::emit_walls(e, c);
    case_file::emit_restitution_grid(e, c.restitution);
    return e.str();
}

} // namespace roughgas
