// Cost of one direct contact integration (Brilliantov et al. (1996) eqs. 24-26, 37; docs/model.md §6-7):
//  - eps_n per evaluation at rel = 1e-6, 1e-8, 1e-10, 1e-11, 1e-12 (abs = rel/100, as the default
//    Tolerance), cycling over 16 values u = 1e-3 ... 10; counter `max_error` = max |eps_n -
//    eps_n(rel = 1e-14)| over them;
//  - one tangential contact with few and with many asperity breaks (counter `breaks`).
#include "roughgas/contact/normal_integrator.hpp"
#include "roughgas/contact/tangential_integrator.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace {

using namespace roughgas;

constexpr std::array<ContactModel, 4> models{{{NormalForm::eq24, ContactEnd::force},
                                              {NormalForm::eq24, ContactEnd::separation},
                                              {NormalForm::eq25, ContactEnd::force},
                                              {NormalForm::eq25, ContactEnd::separation}}};

std::array<double, 16> u_values() {
    std::array<double, 16> u{};
    for (std::size_t i = 0; i < u.size(); ++i) {
        u[i] = 1e-3 * std::pow(1e4, i / (u.size() - 1.0)); // w = 1e-15 ... 1e5
    }
    return u;
}

void normal_restitution(benchmark::State& state) {
    const double rel = std::pow(10.0, -static_cast<double>(state.range(0)));
    const ContactModel model = models[static_cast<std::size_t>(state.range(1))];
    const Tolerance tol{rel, 1e-2 * rel};
    const auto u = u_values();
    double max_error = 0;
    for (const double x : u) {
        const double reference = integrate_normal(x, model, {1e-14, 1e-16}).eps_n;
        max_error = std::max(max_error, std::abs(integrate_normal(x, model, tol).eps_n - reference));
    }
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(integrate_normal(u[i], model, tol).eps_n);
        i = (i + 1) % u.size();
    }
    state.counters["max_error"] = max_error;
    state.SetItemsProcessed(state.iterations());
    state.SetLabel(std::string(name(model.form)) + "/" + std::string(name(model.end)));
}
BENCHMARK(normal_restitution)->ArgsProduct({{6, 8, 10, 11, 12}, {0, 1, 2, 3}})->Unit(benchmark::kMicrosecond);

// u = 0.3, mu = 0.5 with kappa = 2/7; few breaks: z = 0.1, g_T/g_N = 0.5; many: z = 1e-3, 3.
void tangential_contact(benchmark::State& state) {
    const bool many = state.range(0) != 0;
    const TangentialParameters p{0.3, 0.5 / (2.0 / 7.0), many ? 1e-3 : 0.1, {}};
    const double ratio = many ? 3.0 : 0.5;
    int breaks = 0;
    for (auto _ : state) {
        const TangentialResult r = integrate_tangential(p, ratio);
        breaks = r.breaks;
        benchmark::DoNotOptimize(r.eps_t);
    }
    state.counters["breaks"] = breaks;
    // Seconds per break (printed with an SI prefix, e.g. 820n = 0.82 us).
    state.counters["time_per_break"] =
        benchmark::Counter(static_cast<double>(breaks) * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(tangential_contact)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

} // namespace
