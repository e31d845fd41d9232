// Collisions per second of several kernels, alternated in short slices within one process
// (for the ratio targets of scripts/bench_targets.py). Run:
//
//   build/tests/bench/slices_bench [--slice 0.25] [--rounds 30] NAME/N/T ...
//
// NAME is a case of bench_gas.hpp (RoughConstant, SmoothConstant, SmoothElastic, Coulomb,
// ViscoelasticSmooth, Viscoelastic, Brilliantov; Layout_* for the stores run_replica does not use),
// N the grains, T the threads: the gases and the timed chunks of dsmc_bench's BM_Case_NAME/N/T. Every gas is
// built and warmed up first; then each round runs every gas for one slice (chunks until `--slice` seconds of
// timed chunks), in the order given in even rounds and reversed in odd ones, so that a linear drift of the
// machine hits every gas alike over two rounds.
//
// Why: on the shared VMs of this project one benchmark's repetitions spread by up to +-25 % within
// a Google Benchmark call, in episodes of seconds to minutes that slow every kernel alike
// (measured: constant rough 3.9-7.1e6/s). Google Benchmark runs each repetition for 2 s and builds a new
// gas for it; a ratio of two kernels then mixes episodes. Slices a quarter of a second apart see
// the same episode: the ratio of two kernels' slices in one round cancels it (measured: the
// per-round smooth/rough ratio spreads by 5 %, each kernel's slices by 4 %, and successive slices
// are uncorrelated, so the round's ratio is as good a sample as the machine gives).
//
// Output (stdout), CSV: round,position,benchmark,collisions,seconds (one row per slice: `position`
// within the round, `seconds` the timed chunks only, rescaling between chunks excluded as in
// dsmc_bench). Errors: exit 2 with a message on stderr.
#include "bench_gas.hpp"

#include <charconv>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace roughgas;

struct SliceResult {
    std::int64_t collisions = 0;
    double seconds = 0;
};
using Slice = std::function<SliceResult(double)>;

// A gas of Case behind a type-erased slice: chunks until `seconds` of timed chunks.
template <class Case> Slice make_slice(std::int64_t N, int threads) {
    auto gas = std::make_shared<decltype(bench::make_case_gas<Case>(N, threads))>(
        bench::make_case_gas<Case>(N, threads));
    return [gas](double seconds) {
        using Clock = std::chrono::steady_clock;
        SliceResult r;
        while (r.seconds < seconds) {
            const auto t0 = Clock::now();
            const std::int64_t done = gas->run_chunk();
            r.seconds += std::chrono::duration<double>(Clock::now() - t0).count();
            r.collisions += done;
            gas->rescale_if_cooled();
        }
        return r;
    };
}

template <std::size_t I = 0> Slice slice_for(std::string_view name, std::int64_t N, int threads) {
    if constexpr (I == std::tuple_size_v<bench::Cases>) {
        std::string known;
        std::apply([&](auto... c) { ((known += (known.empty() ? "" : ", ") + std::string(c.name)), ...); },
                   bench::Cases{});
        throw std::invalid_argument("unknown case '" + std::string(name) + "' (" + known + ")");
    } else {
        using Case = std::tuple_element_t<I, bench::Cases>;
        return name == Case::name ? make_slice<Case>(N, threads) : slice_for<I + 1>(name, N, threads);
    }
}

template <class T> T parse_number(std::string_view s, std::string_view what) {
    T x{};
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
    if (ec != std::errc{} || end != s.data() + s.size())
        throw std::invalid_argument(std::string(what) + ": '" + std::string(s) + "' is not a number");
    return x;
}

struct Spec {
    std::string benchmark; // NAME/N/T
    Slice slice;
};

Spec parse_spec(std::string_view arg) {
    const auto a = arg.find('/'), b = arg.rfind('/');
    if (a == std::string_view::npos || a == b)
        throw std::invalid_argument("'" + std::string(arg) + "': expected NAME/N/T");
    const auto N = parse_number<std::int64_t>(arg.substr(a + 1, b - a - 1), "N");
    const auto T = parse_number<int>(arg.substr(b + 1), "T");
    if (N < 1000 || N > 100000000)
        throw std::invalid_argument("'" + std::string(arg) + "': N must be in [1000, 1e8]");
    if (T < 1 || T > 256)
        throw std::invalid_argument("'" + std::string(arg) + "': T must be in [1, 256]");
    return {std::string(arg), slice_for(arg.substr(0, a), N, T)};
}

int run(int argc, char** argv) {
    double slice = 0.25;
    int rounds = 30;
    std::vector<std::string_view> names;
    for (int k = 1; k < argc; ++k) {
        const std::string_view a = argv[k];
        if ((a == "--slice" || a == "--rounds") && k + 1 < argc) {
            const std::string_view v = argv[++k];
            if (a == "--slice")
                slice = parse_number<double>(v, "--slice");
            else
                rounds = parse_number<int>(v, "--rounds");
        } else if (a.starts_with("--")) {
            throw std::invalid_argument("unknown option " + std::string(a));
        } else {
            names.push_back(a);
        }
    }
    if (!(slice >= 0.01 && slice <= 60))
        throw std::invalid_argument("--slice must be in [0.01, 60] seconds");
    if (rounds < 1 || rounds > 100000)
        throw std::invalid_argument("--rounds must be in [1, 100000]");
    if (names.empty())
        throw std::invalid_argument("no benchmark given (NAME/N/T ...)");
    std::vector<Spec> specs;
    for (std::string_view n : names) // all gases built and warmed up before anything is timed
        specs.push_back(parse_spec(n));
    std::printf("round,position,benchmark,collisions,seconds\n");
    for (int r = 0; r < rounds; ++r) {
        for (std::size_t p = 0; p < specs.size(); ++p) {
            Spec& s = specs[r % 2 == 0 ? p : specs.size() - 1 - p];
            const SliceResult x = s.slice(slice);
            std::printf("%d,%zu,%s,%lld,%.9g\n", r, p, s.benchmark.c_str(),
                        static_cast<long long>(x.collisions), x.seconds);
        }
        std::fflush(stdout);
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "slices_bench: %s\n", e.what());
        return 2;
    }
}
