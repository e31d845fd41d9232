// One replica of a spatially resolved run ([domain]): the restitution policy's compiled loop
// (box_flight.hpp, one translation unit per policy) picked for the run's pairs.
#include "box_flight.hpp"

#include <algorithm>

namespace roughgas::detail {

ReplicaEnd drive_spatial(const RunSpec& spec, const std::vector<SpeciesBlock>& blocks,
                         const std::vector<AnyPolicy>& policies, int replica, const ReplicaIo& io) {
    // Constant restitution of one kind for every pair (per-pair alpha, beta): a loop without the
    // per-collision dispatch of the variant policies below.
    for (const bool rough : {false, true}) {
        std::vector<SmoothConstant> smooth;
        std::vector<RoughConstant> rough_v;
        for (const AnyPolicy& p : policies) {
            if (const auto* s = std::get_if<SmoothConstant>(&p); s && !rough)
                smooth.push_back(*s);
            const AnyPolicy r = as_rough(p);
            if (const auto* q = std::get_if<RoughConstant>(&r); q && rough)
                rough_v.push_back(*q);
        }
        if (!rough && smooth.size() == policies.size())
            return run_box(spec, blocks, std::move(smooth), replica, io);
        if (rough && rough_v.size() == policies.size() &&
            std::any_of(policies.begin(), policies.end(), [](const AnyPolicy& p) { return needs_rotation(p); }))
            return run_box(spec, blocks, std::move(rough_v), replica, io);
    }
    // The contact model from its tables for every pair (ice, the shipped brilliantov cases): its own
    // loop too, without the variant's dispatch around the table look-ups.
    {
        std::vector<Brilliantov> v;
        for (const AnyPolicy& p : policies)
            if (const auto* b = std::get_if<Brilliantov>(&p))
                v.push_back(*b);
        if (v.size() == policies.size())
            return run_box(spec, blocks, std::move(v), replica, io);
    }
    if (std::none_of(policies.begin(), policies.end(), [](const AnyPolicy& p) { return needs_rotation(p); })) {
        std::vector<AnySmoothPolicy> v;
        for (const AnyPolicy& p : policies)
            v.push_back(to_any_smooth(p));
        return run_box(spec, blocks, std::move(v), replica, io);
    }
    std::vector<AnyRoughPolicy> v;
    for (const AnyPolicy& p : policies)
        v.push_back(to_any_rough(as_rough(p)));
    return run_box(spec, blocks, std::move(v), replica, io);
}

} // namespace roughgas::detail
