#include "restitution_tables.hpp"

#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/io/table_cache_file.hpp"

#include <fmt/format.h>

#include <iostream>
#include <optional>

namespace roughgas::cli {

CachedTables load_or_build_tables(const CaseConfig& cfg, const ContactPair& pc) {
    std::optional<TableCacheFile> cache;
    if (!cfg.contact.cache_file.empty()) {
        cache.emplace(cfg.contact.cache_file);
        if (!cache->rejected().empty())
            std::cerr << fmt::format("roughgas: cache file {} rejected ({}): rebuilding\n", cfg.contact.cache_file,
                                     cache->rejected());
    }
    TableCacheFile* file = cache ? &*cache : nullptr;
    // Exactly the tables a DSMC run of this case uses (dsmc/tables.cpp: the run's g_N range, the
    // tables' own options), so that `roughgas run` finds them in the cache file instead of building
    // them again; grid points outside that range are integrated directly by the table, as in a run.
    const NormalTableOptions nopt{};
    const RunSpec run_defaults{};
    TangentialTableOptions topt;
    topt.g_min = run_defaults.table_g_min;
    topt.g_max = run_defaults.table_g_max;
    bool loaded_n = false, loaded_t = false;
    NormalTable normal = load_or_build<NormalTable>(
        file, NormalTable::key_for(pc.model, nopt), [&] { return NormalTable::build(pc.model, nopt); },
        [&](const std::vector<double>& d) { return NormalTable::deserialize(pc.model, nopt, d); }, &loaded_n);
    TangentialTable tangential = load_or_build<TangentialTable>(
        file, TangentialTable::key_for(pc, topt), [&] { return TangentialTable::build(pc, topt); },
        [&](const std::vector<double>& d) { return TangentialTable::deserialize(pc, topt, d); }, &loaded_t);
    if (cache) cache->save_if_changed();
    std::cerr << fmt::format("roughgas: eps_N table {}; eps_T table {}\n",
                             loaded_n ? "loaded from " + cfg.contact.cache_file
                                      : fmt::format("built in {:.2f} s", normal.build_seconds()),
                             loaded_t ? "loaded from " + cfg.contact.cache_file
                                      : fmt::format("built in {:.2f} s ({} samples)", tangential.stats().build_seconds,
                                                    tangential.stats().breaking.samples + tangential.stats().unbroken.samples +
                                                        tangential.stats().critical.samples));
    return {std::move(normal), std::move(tangential)};
}

} // namespace roughgas::cli
