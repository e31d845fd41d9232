#pragma once
// f(k) for k in [0, n) over OpenMP threads, in chunks of `chunk` taken as threads free up (the
// contacts' integration times differ by orders of magnitude); results go to preallocated slots, so
// the output order does not depend on the schedule. The first exception is rethrown after the loop.
// Used by `roughgas restitution` and the Python module's eps_n and eps_t.
#include <cstddef>
#include <exception>

namespace roughgas::cli {

template <class F> void parallel_for(std::size_t n, int threads, F&& f, int chunk = 1) {
    std::exception_ptr error;
#pragma omp parallel for schedule(dynamic, chunk) num_threads(threads)
    for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t>(n); ++k) {
        try {
            f(static_cast<std::size_t>(k));
        } catch (...) {
#pragma omp critical(roughgas_parallel_for_error)
            if (!error)
                error = std::current_exception();
        }
    }
    if (error)
        std::rethrow_exception(error);
}

} // namespace roughgas::cli
