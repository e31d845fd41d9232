#pragma once
// One replica's run for one compiled kernel: run_replica (run.cpp) picks the policy type once per
// run and calls drive_kernel<Policy, Mixture>, which picks the collision kernel (hard spheres or
// Maxwell) and runs the engine to the end. Its body is in drive_impl.hpp; each drive_*.cpp
// instantiates it for one family of policies (the list below), so that the 17 engine
// instantiations compile in parallel rather than in one translation unit.
#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/dsmc/species.hpp"
#include "roughgas/dsmc/tables.hpp"

#include <algorithm>
#include <type_traits>
#include <variant>
#include <vector>

namespace roughgas::detail {

inline bool has_brilliantov(const RunSpec& spec) {
    return std::any_of(spec.pairs.begin(), spec.pairs.end(), [](const PairRestitution& p) {
        return std::holds_alternative<BrilliantovRestitution>(p);
    });
}

// What a replica reports to and is steered by: run_replica's arguments after the replica index.
struct ReplicaIo {
    const RowSink& sink;
    const ProgressSink& progress;
    ReplicaSummary* summary;
    const HistogramSink& histograms;
    const ReplicaCheckpoints* checkpoints;
    const FieldSink& fields;
};

// Constant restitution: the policies the Maxwell kernel (validated: constant only) and the
// same-type mixture loop are compiled for. Every other mixture runs the per-pair variant policies,
// whose per-collision dispatch is small beside a table look-up or a contact integration; fewer
// instantiations of the engine keep the build (and the sanitizer build in CI) short.
template <class P>
constexpr bool is_constant_policy = std::is_same_v<P, SmoothConstant> || std::is_same_v<P, RoughConstant>;

template <class Policy, bool Mixture>
ReplicaEnd drive_kernel(const RunSpec& spec, const std::vector<SpeciesBlock>& blocks,
                        std::vector<Policy> policies, int replica, const ReplicaIo& io);

// Instantiated in (one species: Mixture = false; mixtures: true)
//   drive_smooth_constant.cpp      SmoothConstant, both
//   drive_rough_constant.cpp       RoughConstant, both
//   drive_contact.cpp              Coulomb, ViscoelasticSmooth, Viscoelastic, ViscoelasticSmoothDirect,
//                                  ViscoelasticDirect: one species
//   drive_brilliantov.cpp          Brilliantov, BrilliantovDirect: one species
//   drive_mixture_variant.cpp      AnySmoothPolicy, AnyRoughPolicy: mixtures
// A spatially resolved replica (spec.domain; drive_spatial.cpp), with the per-pair variant policies.
ReplicaEnd drive_spatial(const RunSpec& spec, const std::vector<SpeciesBlock>& blocks,
                         const std::vector<AnyPolicy>& policies, int replica, const ReplicaIo& io);

#define ROUGHGAS_DRIVE_KERNEL(P, M)                                                                          \
    template ReplicaEnd drive_kernel<P, M>(const RunSpec&, const std::vector<SpeciesBlock>&, std::vector<P>, \
                                           int, const ReplicaIo&)

} // namespace roughgas::detail
