#pragma once
// The restitution tables of a run, through the cache file spec.cache_file ([contact] cache_file):
// the physics library builds them (dsmc/tables.hpp) and this adapter reads and writes the file.
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/dsmc/tables.hpp"

#include <memory>

namespace roughgas {

// Tables for `spec`: loaded from spec.cache_file where it holds them, built otherwise, and the file
// rewritten (atomically) if anything was built. Without a cache file (or with !spec.use_cache)
// the same as RestitutionTables::build(spec). A cache file that fails its checks is ignored and
// rebuilt; the reason is in cache_rejected().
std::shared_ptr<const RestitutionTables> build_run_tables(const RunSpec& spec);

} // namespace roughgas
