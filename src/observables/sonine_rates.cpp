// The first-Sonine production rates of rough spheres: the closed forms of observables/sonine_rates.hpp.
#include "roughgas/observables/sonine_rates.hpp"

namespace roughgas {

SonineRates sonine_rates(double alpha, double beta, double q, double theta) {
    const double at = (1 + alpha) / 2, bt = q * (1 + beta) / (2 * (1 + q)), br = bt / q;
    const double a = at * (1 - at), b = bt * (1 - bt), c = br * (1 - br);
    const double X = bt * bt * theta / q, Y = bt * bt / (q * theta), d = bt * br;
    const double ab2 = a * a + a * b + b * b;
    const double tr = 11 - 8 * a - 16 * b; // recurring translational factor
    SonineRates r;
    r.c2 = {2 * (a + b) - 2 * X, 3.0 / 8 * (a + b) + X / 8, 0.0, -X / 2};
    r.w2 = {2 * c - 2 * Y, -c / 8 - 3.0 / 8 * Y, 0.0, c / 2};
    r.c4 = {11 * (a + b) - 8 * ab2 - X * tr - 8 * X * X,
            (237 * (a + b) + 32 * (at + bt) - 64 * at * bt - 120 * ab2) / 16 -
                X * (41 - 24 * a - 48 * b) / 16 + X * X / 2,
            -4 * X * X, -0.75 * X * tr - 4 * X * X};
    r.w4 = {2 * c * (5 - 4 * c) - 2 * Y * (5 - 8 * c) - 8 * Y * Y,
            -c * (5 - 4 * c) / 8 - 3.0 / 8 * Y * (5 - 8 * c) - 7.5 * Y * Y, 9 * c + br - 4 * c * c,
            c * (5 - 4 * c) - 1.5 * Y * (5 - 8 * c)};
    r.c2w2 = {(6 * a + 6 * b + 7 * c + 4 * d - 8 * a * c - 16 * b * c - 16 * d * d) / 2 -
                  Y * (9 - 8 * a - 16 * b) / 2 - 4 * X * (1 - 2 * c),
              (18 * a + 18 * b + 29 * c + 12 * d - 24 * a * c - 48 * b * c - 48 * d * d) / 32 -
                  3.0 / 32 * Y * (53 - 40 * a - 80 * b) + X * (1 - 2 * c) / 4,
              -X * (5 - 8 * c) / 2,
              (18 * a + 18 * b + 21 * c + 12 * at + 12 * bt + 16 * br - 12 * d - 24 * a * c - 48 * b * c -
               48 * d * d - 16 * at * br) /
                      8 -
                  2 * X * (1 - 2 * c)};
    return r;
}

} // namespace roughgas
