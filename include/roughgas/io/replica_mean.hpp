#pragma once
// The mean over replicas and its standard error, as every X / X_err column pair reports it.
#include <algorithm>
#include <cmath>
#include <span>

namespace roughgas {

struct ReplicaMean {
    double mean = 0;
    double error = 0; // sqrt(sum (x_r - mean)^2/(K (K - 1))); 0 for K = 1
};

inline ReplicaMean replica_mean(std::span<const double> x) {
    const double K = static_cast<double>(x.size());
    double sum = 0;
    for (double v : x)
        sum += v;
    ReplicaMean r;
    r.mean = sum / K;
    if (x.size() > 1) {
        double ss = 0;
        for (double v : x)
            ss += (v - r.mean) * (v - r.mean);
        r.error = std::sqrt(ss / (K * (K - 1)));
    }
    return r;
}

// The same for a value the replicas may share exactly, the row times t of the time clock
// (run.end_time): then that value itself, error 0, where sum/K can differ from it in the last bit
// (three times 0.05 over 3 is 0.05000000000000001), so that the rows of every run with those output
// times carry the same t. Values that differ (the collision clock's t) get replica_mean.
inline ReplicaMean replica_mean_of_shared(std::span<const double> x) {
    if (!x.empty() && std::all_of(x.begin(), x.end(), [&](double v) { return v == x.front(); }))
        return {x.front(), 0.0};
    return replica_mean(x);
}

} // namespace roughgas
