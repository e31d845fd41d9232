#pragma once
// The cached tables of eps_N(g_N) and eps_T(g_N, g_T) that a DSMC run of a case uses for one pair
// (contact.cache = true), through the case's cache file if it names one: `roughgas restitution`
// writes them beside the direct integration, and the Python module's eps_n and eps_t evaluate them.
#include "roughgas/contact/contact_pair.hpp"
#include "roughgas/io/case_config.hpp"
#include "roughgas/restitution/normal_table.hpp"
#include "roughgas/restitution/tangential_table.hpp"

namespace roughgas::cli {

struct CachedTables {
    NormalTable normal;
    TangentialTable tangential;
};

// Loads the tables from cfg.contact.cache_file or builds them (saving them there); the build times
// or the file they came from go to stderr.
CachedTables load_or_build_tables(const CaseConfig& cfg, const ContactPair& pc);

} // namespace roughgas::cli
