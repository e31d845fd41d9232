#pragma once
// A software prefetch of one cache line, for the random accesses of the collision loop.

namespace roughgas {

// A read prefetch. Never faults, whatever the address.
inline void prefetch_line(const void* p) {
    __builtin_prefetch(p, 0, 3);
}

// A write prefetch (prefetchw): the line comes with ownership, ready to be written. For a line about
// to be written, such as the next line of a bucket in the step start's counting sort, or a grain
// that another core's cache holds (dsmc/engine.hpp). Never faults, whatever the address.
inline void prefetch_line_for_write(const void* p) {
    __builtin_prefetch(p, 1, 3);
}

// Either, chosen at run time (a branch that goes the same way for a whole run).
inline void prefetch_line(const void* p, bool for_write) {
    if (for_write)
        prefetch_line_for_write(p);
    else
        prefetch_line(p);
}

} // namespace roughgas
