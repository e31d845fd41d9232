#pragma once
// Standard normal deviates by the ziggurat method (Marsaglia & Tsang 2000), 256 layers, one 64-bit
// word per deviate on the fast path (98.8 % of draws): 8 bits choose the layer, 1 the sign, 53 the
// abscissa. The base layer's excess is the tail beyond R, drawn by Marsaglia's (1964) exact method;
// the wedges by rejection against exp(-x^2/2). Exact up to the 53-bit resolution of the abscissa.
//
// Why not boost::random::normal_distribution: a thermostat draws three to six deviates per grain per
// step, and Boost's ziggurat took 8.5 ns per deviate with the engines' generator, this one about
// 3 ns (measured, Zen 4 VM): with Boost's deviates (and a sequential bridge), a driven run kept 0.84
// of the free gas's collisions per second, with these 0.88-0.90 (docs/performance.md, "Driven gases").
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace roughgas {

class ZigguratNormal {
  public:
    static constexpr std::size_t layers = 256;
    static constexpr double R = 3.6541528853610088;     // the base layer's edge (Marsaglia & Tsang 2000)
    static constexpr double V = 4.92867323399e-3;       // the area of every layer

    // A standard normal deviate from the generator `g` (64-bit words).
    template <class G> double operator()(G& g) const {
        const Tables& t = tables();
        for (;;) {
            const std::uint64_t w = g();
            const unsigned i = static_cast<unsigned>(w & 0xff);
            const std::uint64_t sign = (w & 0x100) << 55; // bit 8 to the sign bit: no branch to mispredict
            const double u = static_cast<double>(w >> 11) * 0x1.0p-53; // [0, 1)
            const double x = u * t.x[i];
            if (x < t.x[i + 1]) [[likely]]
                return signed_by(x, sign);
            if (i == 0)
                return signed_by(tail(g), sign);
            const double y = t.f[i] + unit(g) * (t.f[i + 1] - t.f[i]);
            if (y < std::exp(-0.5 * x * x))
                return signed_by(x, sign);
        }
    }

  private:
    static double signed_by(double x, std::uint64_t sign) {
        return std::bit_cast<double>(std::bit_cast<std::uint64_t>(x) ^ sign);
    }
    struct Tables {
        // x[0] = V/f(R) (the base layer's width, its part beyond R standing for the tail), x[1] = R,
        // x[i + 1] the edge of the layer above x[i], x[256] = 0; f = exp(-x^2/2) at them.
        std::array<double, layers + 1> x{}, f{};
    };
    static Tables make_tables() {
        Tables s;
        const auto pdf = [](double x) { return std::exp(-0.5 * x * x); };
        s.x[0] = V / pdf(R);
        s.x[1] = R;
        for (std::size_t i = 1; i + 1 < layers; ++i)
            s.x[i + 1] = std::sqrt(-2.0 * std::log(V / s.x[i] + pdf(s.x[i])));
        s.x[layers] = 0.0;
        for (std::size_t i = 0; i <= layers; ++i)
            s.f[i] = pdf(s.x[i]);
        return s;
    }
    // Built during static initialisation: a draw reads it without the guard of a function-local static.
    static const Tables& tables() { return tables_; }
    inline static const Tables tables_ = make_tables();
    template <class G> static double unit(G& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }
    // The normal's tail beyond R: a = -ln(u1)/R, b = -ln(u2), accepted when 2b > a^2; R + a.
    template <class G> static double tail(G& g) {
        for (;;) {
            const double a = -std::log(1.0 - unit(g)) / R;
            const double b = -std::log(1.0 - unit(g));
            if (b + b > a * a)
                return R + a;
        }
    }
};

} // namespace roughgas
