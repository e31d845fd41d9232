// [fields]: its build, its checks and its emission.
#include "fields_table.hpp"

#include "roughgas/observables/field_quantity.hpp"
#include "toml_access.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace roughgas::case_file {

std::optional<FieldsConfig> build_fields(const toml::table& root) {
    const toml::table* t = root["fields"].as_table();
    if (t == nullptr)
        return std::nullopt;
    const Reader r(t, "fields");
    FieldsConfig f;
    for (const std::string& q : r.strings("quantities"))
        f.quantities.push_back(static_cast<FieldQuantity>(
            std::find(field_quantity_names.begin(), field_quantity_names.end(), q) - field_quantity_names.begin()));
    f.every = r.integer("every");
    f.replicas = r.integer("replicas");
    return f;
}

void check_fields(BuildContext& ctx, const CaseConfig& c) {
    if (!c.fields)
        return;
    if (!c.domain)
        ctx.add("fields", "[fields] without [domain]: fields are of a box's cells (give the box in [domain])");
    else if (c.fields->replicas > c.run.replicas)
        ctx.add("fields.replicas", fmt::format("fields.replicas = {}: more than the run's replicas (must be "
                                               "<= run.replicas = {})",
                                               c.fields->replicas, c.run.replicas));
}

void emit_fields(Emitter& e, const FieldsConfig& f) {
    e.header("[fields]");
    std::vector<std::string> names;
    for (const FieldQuantity q : f.quantities)
        names.emplace_back(field_quantity_names[static_cast<std::size_t>(q)]);
    e.put("quantities", names);
    e.put("every", f.every);
    e.put("replicas", f.replicas);
}

} // namespace roughgas::case_file
