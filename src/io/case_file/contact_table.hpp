#pragma once
// [contact]: how the contacts of viscoelastic and brilliantov are integrated and cached. Every key
// has a default and no rule involves other keys: build and emission only.
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"
#include "toml_access.hpp"

namespace roughgas::case_file {

ContactConfig build_contact(const Reader& r);
void emit_contact(Emitter& e, const ContactConfig& c);

} // namespace roughgas::case_file
