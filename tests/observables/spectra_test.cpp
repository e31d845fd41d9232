// Fourier spectra of the box's fields (observables/spectra.hpp): the transforms against direct sums
// and Parseval's theorem to round-off, every wave vector in one shell, and the amplitudes of waves
// planted on the grid exactly.
#include "roughgas/observables/spectra.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>

namespace roughgas {
namespace {

using cplx = std::complex<double>;

std::vector<SpeciesBlock> blocks(std::size_t n1, double m1, std::size_t n2, double m2) {
    std::vector<SpeciesBlock> b(2);
    b[0].grain.mass = m1;
    b[0].count = n1;
    b[1].grain.mass = m2;
    b[1].offset = n1;
    b[1].count = n2;
    return b;
}

int signed_index(int i, int G) { return i <= G / 2 ? i : i - G; }

// A grid odd along x and y, even along z (the Nyquist plane), a box of unequal sides, and two
// species of different mass at random positions and velocities.
struct Scene {
    SpectraGeometry g;
    std::vector<Vec3> x, v, w;
    std::vector<SpeciesBlock> species = blocks(300, 1.0, 200, 2.5);
    Scene() {
        g.grid = {7, 5, 8};
        g.box = {10.0, 8.0, 13.0};
        g.modes = 2;
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> u(0, 1);
        std::normal_distribution<double> normal;
        for (int i = 0; i < 500; ++i) {
            x.push_back({u(rng) * g.box[0], u(rng) * g.box[1], u(rng) * g.box[2]});
            v.push_back({normal(rng), normal(rng) + 0.3, normal(rng)});
            w.push_back({normal(rng), 2 * normal(rng), normal(rng)});
        }
        Vec3 p{};
        double M = 0;
        for (std::size_t i = 0; i < v.size(); ++i) {
            p += mass(i) * v[i];
            M += mass(i);
        }
        U = (1.0 / M) * p;
        for (const auto& [first, last] : {std::pair{0, 300}, std::pair{300, 500}}) {
            double sum = 0;
            for (int j = first; j < last; ++j)
                sum += energy(static_cast<std::size_t>(j));
            for (int j = first; j < last; ++j)
                excess.push_back(energy(static_cast<std::size_t>(j)) - sum / (last - first));
            double rot = 0;
            for (int j = first; j < last; ++j)
                rot += rotational_energy(static_cast<std::size_t>(j));
            for (int j = first; j < last; ++j)
                rot_excess.push_back(rotational_energy(static_cast<std::size_t>(j)) - rot / (last - first));
        }
    }
    Vec3 U;                     // the mass-weighted mean velocity
    std::vector<double> excess;     // each grain's kinetic energy about U minus its species' mean
    std::vector<double> rot_excess; // each grain's rotational energy minus its species' mean
    double mass(std::size_t i) const { return i < 300 ? 1.0 : 2.5; }
    // The grain's cell index along each axis.
    std::array<int, 3> cell(std::size_t i) const {
        const double q[3] = {x[i].x, x[i].y, x[i].z};
        std::array<int, 3> c{};
        for (std::size_t a = 0; a < 3; ++a)
            c[a] = static_cast<int>(std::floor(q[a] * g.grid[a] / g.box[a]));
        return c;
    }
    double energy(std::size_t i) const { return 0.5 * mass(i) * norm2(v[i] - U); }
    double rotational_energy(std::size_t i) const {
        return 0.5 * species[i < 300 ? 0 : 1].moment_of_inertia() * norm2(w[i]);
    }
    // The grain's value of field f (rho, p_x, p_y, p_z, h).
    double q(int f, std::size_t i) const {
        const Vec3 c = v[i] - U;
        return f == 0 ? 1.0 : f == 1 ? mass(i) * c.x : f == 2 ? mass(i) * c.y : f == 3 ? mass(i) * c.z : excess[i];
    }
    // Direct sum of field f at wave numbers n, with the phase of the cell corners.
    cplx direct(int f, const std::array<int, 3>& n) const {
        cplx sum = 0;
        for (std::size_t p = 0; p < x.size(); ++p) {
            const std::array<int, 3> c = cell(p);
            double phase = 0;
            for (std::size_t a = 0; a < 3; ++a)
                phase += 2 * std::numbers::pi * n[a] * c[a] / static_cast<double>(g.grid[a]);
            sum += q(f, p) * std::polar(1.0, -phase);
        }
        return sum;
    }
};

// Each field's transform is the direct sum over the grains of q_j exp(-i k.X_c) (X_c the corner of
// grain j's cell) at every stored wave vector, and sum over all k of |F_k|^2 = G sum_c f_c^2
// (Parseval; the half spectrum counts n_z > 0 twice except on an even grid's Nyquist plane), both to
// round-off.
TEST(Spectra, TransformsAreTheDirectSumsAndKeepParseval) {
    Scene s;
    Spectra sp(s.g);
    WorkerTeam team(2);
    sp.compute(s.x, s.v, s.w, s.species, team);
    const int Gx = s.g.grid[0], Gy = s.g.grid[1], Gz = s.g.grid[2], Hz = Gz / 2 + 1;
    for (int f = 0; f < 5; ++f) {
        const std::vector<double>& F = sp.transform(f);
        ASSERT_EQ(F.size(), static_cast<std::size_t>(2 * Gx * Gy * Hz));
        double power = 0;
        for (int i = 0; i < Gx; ++i)
            for (int j = 0; j < Gy; ++j)
                for (int l = 0; l < Hz; ++l) {
                    const std::size_t at = static_cast<std::size_t>((i * Gy + j) * Hz + l);
                    const cplx Fk(F[2 * at], F[2 * at + 1]);
                    power += (l == 0 || 2 * l == Gz ? 1.0 : 2.0) * std::norm(Fk);
                    const cplx d = s.direct(f, {i, j, l});
                    ASSERT_NEAR(std::abs(Fk - d), 0.0, 1e-11 * (1 + std::abs(d))) << f << ": " << i << " " << j << " " << l;
                }
        double squares = 0;
        for (double c : sp.field(f))
            squares += c * c;
        EXPECT_NEAR(power / (static_cast<double>(Gx * Gy * Gz) * squares), 1.0, 1e-13) << "field " << f;
    }
}

// The spectra.csv values from their definitions by direct sums over the grains: every shell (its
// wave vectors: every k of the grid with 0 < |k| within the shell's edges, no Nyquist plane; most of
// them oblique, so that k^ projects the currents) and the axis bins; the first mode of modes.csv
// with its phase referred to the cell centres.
TEST(Spectra, ValuesFollowTheirDefinitions) {
    Scene s;
    Spectra sp(s.g);
    WorkerTeam team(1);
    const std::vector<double> out = sp.compute(s.x, s.v, s.w, s.species, team);
    const std::vector<SpectrumBin> bins = spectrum_bins(s.g);
    double N = 0, M = 0, squares = 0;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
        N += 1;
        M += s.mass(i);
        squares += s.excess[i] * s.excess[i];
    }
    // The four spectra of one wave vector, by direct sums.
    const auto spectra_of = [&](const std::array<int, 3>& n) {
        double k[3], k2 = 0;
        for (std::size_t a = 0; a < 3; ++a) {
            k[a] = 2 * std::numbers::pi * n[a] / s.g.box[a];
            k2 += k[a] * k[a];
        }
        const cplx rho = s.direct(0, n), p[3] = {s.direct(1, n), s.direct(2, n), s.direct(3, n)}, h = s.direct(4, n);
        cplx par = 0;
        for (std::size_t a = 0; a < 3; ++a)
            par += k[a] / std::sqrt(k2) * p[a];
        double perp = 0;
        for (std::size_t a = 0; a < 3; ++a)
            perp += std::norm(p[a] - par * (k[a] / std::sqrt(k2)));
        return std::array<double, 4>{std::norm(rho) / N, perp / (2 * M), std::norm(par) / M, std::norm(h) / squares};
    };
    const double dk = 2 * std::numbers::pi / 13.0; // the longest side
    int oblique = 0;
    for (std::size_t r = 0; r < bins.size(); ++r) {
        const SpectrumBin& b = bins[r];
        std::array<double, 4> expected{};
        int count = 0;
        if (b.axis == 0) {
            for (int i = -3; i <= 3; ++i) // |n_x| <= (7 - 1)/2, |n_y| <= (5 - 1)/2, |n_z| <= (8 - 1)/2
                for (int j = -2; j <= 2; ++j)
                    for (int l = -3; l <= 3; ++l) {
                        const double kn = std::hypot(2 * std::numbers::pi * i / 10.0, 2 * std::numbers::pi * j / 8.0,
                                                     2 * std::numbers::pi * l / 13.0);
                        if (kn < (b.n - 0.5) * dk || kn >= (b.n + 0.5) * dk)
                            continue;
                        const std::array<double, 4> e = spectra_of({i, j, l});
                        for (std::size_t f = 0; f < 4; ++f)
                            expected[f] += e[f];
                        ++count;
                        oblique += (i != 0) + (j != 0) + (l != 0) > 1;
                    }
            ASSERT_EQ(count, b.modes) << "shell " << b.n;
            for (double& e : expected)
                e /= count;
        } else {
            std::array<int, 3> n{0, 0, 0};
            n[static_cast<std::size_t>(b.axis - 1)] = b.n;
            expected = spectra_of(n);
        }
        for (std::size_t f = 0; f < 4; ++f)
            EXPECT_NEAR(out[r * spectrum_field_count + f], expected[f], 1e-12 * (1 + expected[f]))
                << "axis " << b.axis << ", n = " << b.n << ", " << spectrum_fields[f];
    }
    EXPECT_GT(oblique, 20);
    // modes.csv, n = 1 along x: the phase at the cell centres, exp(-i k dx/2) times the corners'.
    const double k = 2 * std::numbers::pi / s.g.box[0], dx = s.g.box[0] / s.g.grid[0];
    const cplx centre = std::polar(1.0, -k * dx / 2);
    const double* m = out.data() + bins.size() * spectrum_field_count;
    double e_mean = 0;
    for (std::size_t i = 0; i < s.x.size(); ++i)
        e_mean += s.energy(i) / N;
    const cplx expected[5] = {2.0 / N * centre * s.direct(0, {1, 0, 0}), 2.0 / M * centre * s.direct(1, {1, 0, 0}),
                              2.0 / M * centre * s.direct(2, {1, 0, 0}), 2.0 / M * centre * s.direct(3, {1, 0, 0}),
                              2.0 / (N * e_mean) * centre * s.direct(4, {1, 0, 0})};
    for (std::size_t f = 0; f < 5; ++f) {
        EXPECT_NEAR(m[2 * f], expected[f].real(), 1e-14) << mode_fields[2 * f];
        EXPECT_NEAR(m[2 * f + 1], expected[f].imag(), 1e-14) << mode_fields[2 * f + 1];
    }
    // T_rot's: (2/(N r)) sum_j (r_j - r_s(j)) exp(-i k x_c), x_c the centre of grain j's cell, grain by grain.
    double r_mean = 0;
    for (std::size_t i = 0; i < s.x.size(); ++i)
        r_mean += s.rotational_energy(i) / N;
    cplx rot = 0;
    for (std::size_t i = 0; i < s.x.size(); ++i)
        rot += s.rot_excess[i] * std::polar(1.0, -k * (s.cell(i)[0] + 0.5) * dx);
    rot *= 2.0 / (N * r_mean);
    EXPECT_GT(std::abs(rot), 0.01);
    EXPECT_NEAR(m[mode_T_rot_first], rot.real(), 1e-14);
    EXPECT_NEAR(m[mode_T_rot_first + 1], rot.imag(), 1e-14);
}

// Shells: every wave vector of the grid with 0 < |k| up to the reach (the largest |k| every axis
// has; the Nyquist planes left out) in exactly one shell, the shell's mean |k| within its edges;
// the axis bins n = 1 ... (G_a - 1)/2; the modes as many as asked where the axis has them.
TEST(Spectra, ShellsHoldEveryWaveVectorOnce) {
    SpectraGeometry g;
    g.grid = {12, 7, 1}; // a slab: no wave vectors along z
    g.box = {24.0, 10.0, 2.0};
    g.modes = 4;
    const std::vector<SpectrumBin> bins = spectrum_bins(g);
    const double dk = 2 * std::numbers::pi / 24.0;
    const double reach = std::min(2 * std::numbers::pi * 5 / 24.0, 2 * std::numbers::pi * 3 / 10.0);
    int expected = 0;
    for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 7; ++j) {
            const int nx = signed_index(i, 12), ny = signed_index(j, 7);
            if (std::abs(nx) == 6)
                continue;
            const double k = std::hypot(2 * std::numbers::pi * nx / 24.0, 2 * std::numbers::pi * ny / 10.0);
            expected += k > 0 && std::floor(k / dk + 0.5) <= std::floor(reach / dk + 1e-9);
        }
    int counted = 0, along[4] = {0, 0, 0, 0};
    for (const SpectrumBin& b : bins) {
        if (b.axis == 0) {
            counted += b.modes;
            EXPECT_GE(b.k, (b.n - 0.5) * dk);
            EXPECT_LT(b.k, (b.n + 0.5) * dk);
        } else {
            EXPECT_EQ(b.n, ++along[b.axis]);
            EXPECT_EQ(b.modes, 2);
        }
    }
    EXPECT_EQ(counted, expected);
    EXPECT_EQ(along[1], 5);
    EXPECT_EQ(along[2], 3);
    EXPECT_EQ(along[3], 0);
    const std::vector<ModeIndex> modes = mode_indices(g);
    ASSERT_EQ(modes.size(), 4u + 3u);
    EXPECT_EQ(modes[4].axis, 2);
    EXPECT_EQ(modes[6].n, 3);
}

// Grains at the cell centres carrying exact waves along y on a uniform density (in every cell two
// grains of mass 1 and two of mass 2.5): the velocity v_x = U sin(k y_c), v_z = +-(what makes
// each grain's kinetic energy e (1 + B cos(k y_c))), one of each sign, and the spin omega_z that
// makes its rotational energy r (1 + C sin(k y_c)). modes.csv at n = 1 along y has the flow's -i U,
// the temperature's B (the mean energy is e) and T_rot's -i C, the density's 0; at n = 2 nothing;
// to round-off.
TEST(Spectra, WavesOnTheGridHaveTheirAmplitudes) {
    SpectraGeometry g;
    g.grid = {3, 8, 2};
    g.box = {3.0, 16.0, 2.0};
    g.modes = 2;
    const double U = 0.3, B = 0.2, C = 0.15, k = 2 * std::numbers::pi / 16.0, e = 1.5, r = 0.7;
    const std::vector<SpeciesBlock> species = blocks(96, 1.0, 96, 2.5);
    std::vector<Vec3> x, v, w;
    for (const double m : {1.0, 2.5})
        for (const double sign : {1.0, -1.0})
            for (int c = 0; c < 3 * 8 * 2; ++c) {
                const int i = c / 16, j = c / 2 % 8, l = c % 2;
                const double y = 2.0 * j + 1.0;
                const double vx = U * std::sin(k * y);
                const double vz = std::sqrt(2 * e * (1 + B * std::cos(k * y)) / m - vx * vx);
                x.push_back({i + 0.5, y, l + 0.5});
                v.push_back({vx, 0.0, sign * vz});
                w.push_back({0.0, 0.0, std::sqrt(2 * r * (1 + C * std::sin(k * y)) / species[m == 1.0 ? 0 : 1].moment_of_inertia())});
            }
    Spectra sp(g);
    WorkerTeam team(1);
    const std::vector<double> out = sp.compute(x, v, w, species, team);
    const std::vector<ModeIndex> modes = mode_indices(g);
    const std::size_t first = spectrum_bins(g).size() * spectrum_field_count;
    for (std::size_t r = 0; r < modes.size(); ++r) {
        const double* a = out.data() + first + r * mode_field_count;
        const bool wave = modes[r].axis == 2 && modes[r].n == 1;
        SCOPED_TRACE(::testing::Message() << "axis " << modes[r].axis << ", n = " << modes[r].n);
        const double expected[mode_field_count] = {0, 0, 0, wave ? -U : 0, 0, 0, 0, 0, wave ? B : 0, 0, 0, wave ? -C : 0};
        for (std::size_t f = 0; f < mode_field_count; ++f)
            EXPECT_NEAR(a[f], expected[f], 1e-14) << mode_fields[f];
    }
}

} // namespace
} // namespace roughgas
