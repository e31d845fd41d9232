#pragma once
// An observer of the engines' collisions that keeps nothing (ForkableObserver of dsmc/engine.hpp).
#include "roughgas/dsmc/spatial_engine.hpp"

namespace roughgas::test {

struct NoObserver {
    void operator()(const CollisionRecord&, std::size_t) {}
    NoObserver fork() const { return {}; }
    void merge(const NoObserver&) {}
};

} // namespace roughgas::test
