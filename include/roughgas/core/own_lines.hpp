#pragma once
// A value alone in its cache lines: for the tallies that parallel work units keep side by side in a
// vector and write at every collision or wall hit. Packed, neighbouring units' tallies share lines,
// and two threads running neighbouring units pass those lines back and forth at every write
// (measured: N = 1e5, two threads, a row per collision per particle: 1.4 CPU seconds against 0.78
// on one thread, 1.05 with the tallies apart; docs/performance.md, "Runs on a shared machine").
namespace roughgas {

template <class T> struct alignas(64) OwnLines {
    T value;
};

} // namespace roughgas
