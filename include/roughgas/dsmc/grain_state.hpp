#pragma once
// The grains of one replica at the end of a run (run.save_state), for a later run to start from
// (initial.from, docs/model.md): every grain's velocity and spin in the run's species-block order
// (dsmc/species.hpp), and its position when the run was a box.
#include "roughgas/core/vec.hpp"

#include <array>
#include <functional>
#include <vector>

namespace roughgas {

struct GrainState {
    std::array<double, 3> box{};          // the box's size; all 0 after a homogeneous run (no positions)
    double t = 0, coll_per_particle = 0;  // when the state was taken
    std::vector<Vec3> x, v, w;            // x empty without a box; v as the run's rows see it (in a
                                          // shear run, homogeneous or a box, about the flow)
};

// Per replica, the state a run starts from (RunSpec::initial_state).
using GrainStateSource = std::function<GrainState(int replica)>;
// Receives each finished replica's last state (RunSpec::final_state), on the replica's thread.
using GrainStateSink = std::function<void(int replica, const GrainState&)>;

} // namespace roughgas
