#include "memory_check.hpp"

#include "roughgas/core/available_memory.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/io/input_error.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace roughgas::cli {

void refuse_if_too_large(const RunSpec& spec, int at_once, const std::string& case_file) {
    const std::optional<AvailableMemory> free = available_memory();
    if (!free)
        return;
    const double per_grain = static_cast<double>(memory_per_particle_bound(spec));
    const double cells = static_cast<double>(memory_per_replica_fixed_bound(spec));
    double need = (static_cast<double>(spec.particles) * per_grain + cells) * at_once;
    // An address-space limit also counts what the threads map once they start: a stack (8 MiB by
    // default) and a malloc arena (64 MiB of address space in glibc) each.
    if (free->source.starts_with("address-space"))
        need += std::max(1, spec.threads) * 72.0 * (1 << 20);
    if (need <= static_cast<double>(free->bytes))
        return;
    throw InputError(case_file, "run.particles",
                     fmt::format("run.particles = {}: needs about {:.3g} GB ({:.0f} bytes per grain x {} grains{} per "
                                 "replica, {} replica{} at a time), more than the {:.3g} GB this process may use ({}); "
                                 "take fewer grains{}, or fewer threads (--threads) to run fewer replicas at a time",
                                 spec.particles, need / 1e9, per_grain, spec.particles,
                                 cells > 0 ? fmt::format(" + {:.3g} GB for the cells and rows", cells / 1e9) : "", at_once,
                                 at_once > 1 ? "s" : "", static_cast<double>(free->bytes) / 1e9, free->source,
                                 cells > 0 ? ", cells or rows" : ""));
}

} // namespace roughgas::cli
