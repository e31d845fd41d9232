#pragma once
// The mean over replicas and its standard error, as every X / X_err column pair reports it.
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

} // namespace roughgas
