#pragma once
// Sample statistics of the stochastic tests: the mean over replicas and its standard error.
#include <cmath>
#include <vector>

namespace roughgas::test {

struct MeanErr {
    double mean = 0, err = 0; // err: standard error of the mean, sqrt(sum (x - mean)^2/(n (n - 1)))
};

inline MeanErr mean_err(const std::vector<double>& x) {
    double m = 0;
    for (double v : x)
        m += v;
    m /= static_cast<double>(x.size());
    double s2 = 0;
    for (double v : x)
        s2 += (v - m) * (v - m);
    return {m, std::sqrt(s2 / static_cast<double>(x.size() - 1) / static_cast<double>(x.size()))};
}

} // namespace roughgas::test
