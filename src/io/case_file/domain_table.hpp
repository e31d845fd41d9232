#pragma once
// [domain]: a spatially resolved run, grains with positions in a box of collision cells. Its checks:
// the box's boundaries against the run kind, keys of the homogeneous gas the box has not, the number
// of cells, and cells small enough to resolve the mean free path.
#include "build_context.hpp"
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"

#include <optional>

namespace roughgas::case_file {

std::optional<DomainConfig> build_domain(BuildContext& ctx); // unset without [domain]
// With [domain]: the box against the run kind and the homogeneous gas's keys, and its cell count.
void check_domain(BuildContext& ctx, const CaseConfig& c);
// With [domain]: cells at most a mean free path wide (a density wave's crest counted), unless allowed.
void check_cell_size(BuildContext& ctx, const CaseConfig& c);
void emit_domain(Emitter& e, const DomainConfig& d);

} // namespace roughgas::case_file
