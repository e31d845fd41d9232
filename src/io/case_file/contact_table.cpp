// [contact]: its build and its emission.
#include "contact_table.hpp"

namespace roughgas::case_file {

ContactConfig build_contact(const Reader& r) {
    ContactConfig c;
    c.model.form = r.choice<NormalForm>("form", normal_form_names);
    c.model.end = r.choice<ContactEnd>("end", contact_end_names);
    c.cache = r.boolean("cache");
    c.cache_file = r.string("cache_file");
    const double tol = r.real("tolerance");
    c.tolerance = Tolerance{tol, tol / 100}; // the Hertz-scaled state is O(1)
    return c;
}

void emit_contact(Emitter& e, const ContactConfig& c) {
    e.header("[contact]");
    e.put("form", name(c.model.form));
    e.put("end", name(c.model.end));
    e.put("cache", c.cache);
    e.put("cache_file", c.cache_file);
    e.put("tolerance", c.tolerance.rel);
}

} // namespace roughgas::case_file
