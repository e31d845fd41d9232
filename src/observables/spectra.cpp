// Fourier spectra of a periodic box's fields: observables/spectra.hpp.
#include "roughgas/observables/spectra.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace roughgas {
namespace {

using cplx = std::complex<double>;

// The largest wave number along an axis of G cells, leaving out the Nyquist plane of an even grid.
int top(int G) { return (G - 1) / 2; }

// Signed wave number of index i of G (FFT order: 0, 1, ..., then the negative ones).
int signed_index(int i, int G) { return i <= G / 2 ? i : i - G; }

// 2 pi over the longest side among the axes of more than two cells (the others have no wave vectors
// of their own: shell 1 is then the smallest |k| there is).
double shell_width(const SpectraGeometry& g) {
    double L = 0;
    for (std::size_t a = 0; a < 3; ++a)
        if (g.grid[a] > 2)
            L = std::max(L, g.box[a]);
    return L > 0 ? 2 * std::numbers::pi / L : 1.0;
}

// The largest |k| every axis reaches: the shells go up to it.
double shell_reach(const SpectraGeometry& g) {
    double k = HUGE_VAL;
    for (std::size_t a = 0; a < 3; ++a)
        if (g.grid[a] > 2)
            k = std::min(k, 2 * std::numbers::pi * top(g.grid[a]) / g.box[a]);
    return std::isfinite(k) ? k : 0.0;
}

// Which shell a wave vector of modulus k belongs to (0: none, k = 0 or beyond the reach).
int shell(double k, double dk, int shells) {
    const auto s = static_cast<int>(std::floor(k / dk + 0.5));
    return s >= 1 && s <= shells ? s : 0;
}

int shell_count(const SpectraGeometry& g) {
    return static_cast<int>(std::floor(shell_reach(g) / shell_width(g) + 1e-9));
}

// The shell of the wave vector of wave numbers n (0: none: k = 0, beyond the reach, or on a Nyquist
// plane) and its modulus.
std::pair<int, double> shell_of(const SpectraGeometry& g, const int n[3]) {
    bool inside = true;
    double k2 = 0;
    for (std::size_t a = 0; a < 3; ++a) {
        inside &= std::abs(n[a]) <= top(g.grid[a]);
        const double ka = 2 * std::numbers::pi * n[a] / g.box[a];
        k2 += ka * ka;
    }
    const double k = std::sqrt(k2);
    return {inside ? shell(k, shell_width(g), shell_count(g)) : 0, k};
}

// FFTW's planner is one state per process and not thread-safe: plans are made one at a time
// (replicas of a run set up on several threads, each with its own Spectra).
std::mutex& planner_mutex() {
    static std::mutex m;
    return m;
}

} // namespace

struct Spectra::Plan {
    fftw_plan plan = nullptr;
};

std::vector<SpectrumBin> spectrum_bins(const SpectraGeometry& g) {
    std::vector<SpectrumBin> bins;
    const int shells = shell_count(g);
    std::vector<double> ksum(static_cast<std::size_t>(shells) + 1, 0.0);
    std::vector<int> count(static_cast<std::size_t>(shells) + 1, 0);
    // The half spectrum n_z >= 0, as the transforms store it: n_z > 0 stands for -k too.
    for (int i = 0; i < g.grid[0]; ++i)
        for (int j = 0; j < g.grid[1]; ++j)
            for (int l = 0; l <= g.grid[2] / 2; ++l) {
                const int n[3] = {signed_index(i, g.grid[0]), signed_index(j, g.grid[1]), l};
                const auto [s, k] = shell_of(g, n);
                const int mirrors = l == 0 ? 1 : 2;
                if (s > 0) {
                    ksum[static_cast<std::size_t>(s)] += mirrors * k;
                    count[static_cast<std::size_t>(s)] += mirrors;
                }
            }
    for (int s = 1; s <= shells; ++s)
        if (count[static_cast<std::size_t>(s)] > 0)
            bins.push_back({0, s, ksum[static_cast<std::size_t>(s)] / count[static_cast<std::size_t>(s)],
                            count[static_cast<std::size_t>(s)]});
    for (int a = 0; a < 3; ++a)
        for (int n = 1; n <= top(g.grid[static_cast<std::size_t>(a)]); ++n)
            bins.push_back({a + 1, n, 2 * std::numbers::pi * n / g.box[static_cast<std::size_t>(a)], 2});
    return bins;
}

std::vector<ModeIndex> mode_indices(const SpectraGeometry& g) {
    std::vector<ModeIndex> m;
    for (int a = 0; a < 3; ++a)
        for (int n = 1; n <= std::min(g.modes, top(g.grid[static_cast<std::size_t>(a)])); ++n)
            m.push_back({a + 1, n, 2 * std::numbers::pi * n / g.box[static_cast<std::size_t>(a)]});
    return m;
}

std::vector<Column> spectrum_field_columns() {
    return {{"S", "-"}, {"E_perp", "energy"}, {"E_par", "energy"}, {"S_T", "-"}};
}

std::vector<Column> mode_field_columns() {
    std::vector<Column> c;
    for (const char* f : mode_fields) {
        const std::string name = f;
        c.push_back({name, name.starts_with("u_") ? "length/time" : "-"});
    }
    return c;
}

Spectra::Spectra(const SpectraGeometry& g) : g_(g), bins_(spectrum_bins(g)), modes_(mode_indices(g)) {
    for (std::size_t a = 0; a < 3; ++a)
        if (g.grid[a] < 1 || !(g.box[a] > 0))
            throw std::invalid_argument("Spectra: grid and box must be positive");
    const auto G = static_cast<std::size_t>(g.grid[0]) * static_cast<std::size_t>(g.grid[1]) *
                   static_cast<std::size_t>(g.grid[2]);
    const std::size_t H = static_cast<std::size_t>(g.grid[0]) * static_cast<std::size_t>(g.grid[1]) *
                          (static_cast<std::size_t>(g.grid[2]) / 2 + 1);
    for (int f = 0; f < 5; ++f) {
        fields_[static_cast<std::size_t>(f)].assign(G, 0.0);
        transforms_[static_cast<std::size_t>(f)].assign(2 * H, 0.0);
    }
    if (!modes_.empty())
        rotation_.assign(G, 0.0);
    plan_ = std::make_unique<Plan>();
    {
        const std::lock_guard<std::mutex> lock(planner_mutex());
        // FFTW_UNALIGNED: the plan is executed on each field's own arrays (std::vector's alignment,
        // not necessarily the SIMD alignment FFTW would assume from the planning arrays).
        plan_->plan = fftw_plan_dft_r2c_3d(g.grid[0], g.grid[1], g.grid[2], fields_[0].data(),
                                           reinterpret_cast<fftw_complex*>(transforms_[0].data()),
                                           FFTW_ESTIMATE | FFTW_UNALIGNED);
    }
    if (!plan_->plan)
        throw std::runtime_error("Spectra: FFTW could not plan the transform");
    // Each stored wave vector's shell, for the shell sums.
    shell_of_.assign(H, 0);
    const int Hz = g.grid[2] / 2 + 1;
    for (int i = 0; i < g.grid[0]; ++i)
        for (int j = 0; j < g.grid[1]; ++j)
            for (int l = 0; l < Hz; ++l) {
                const int n[3] = {signed_index(i, g.grid[0]), signed_index(j, g.grid[1]), l};
                shell_of_[(static_cast<std::size_t>(i) * static_cast<std::size_t>(g.grid[1]) +
                           static_cast<std::size_t>(j)) * static_cast<std::size_t>(Hz) + static_cast<std::size_t>(l)] =
                    shell_of(g, n).first;
            }
}

Spectra::~Spectra() {
    if (plan_ && plan_->plan) {
        const std::lock_guard<std::mutex> lock(planner_mutex());
        fftw_destroy_plan(plan_->plan);
    }
}

const std::vector<double>& Spectra::transform(int f) const { return transforms_.at(static_cast<std::size_t>(f)); }
const std::vector<double>& Spectra::field(int f) const { return fields_.at(static_cast<std::size_t>(f)); }

std::vector<double> Spectra::compute(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const std::vector<Vec3>& w,
                                     const std::vector<SpeciesBlock>& species, WorkerTeam& team) {
    const std::array<int, 3>& G = g_.grid;
    // The mass-weighted mean velocity U: the currents and energies are of c = v - U (a drift would
    // add U times the mass density's wave to the currents).
    double N = 0, M = 0;
    Vec3 P{};
    for (const SpeciesBlock& b : species)
        for (std::size_t i = b.offset; i < b.offset + b.count; ++i) {
            N += 1;
            M += b.grain.mass;
            P += b.grain.mass * v[i];
        }
    const Vec3 U = M > 0 ? (1.0 / M) * P : Vec3{};
    // Each species' mean kinetic energy e_s, the grains' mean e and the sum of (e_j - e_s)^2.
    std::vector<double> e_species(species.size(), 0.0);
    double E = 0, squares = 0;
    for (std::size_t s = 0; s < species.size(); ++s) {
        const SpeciesBlock& b = species[s];
        double sum = 0, sum2 = 0;
        for (std::size_t i = b.offset; i < b.offset + b.count; ++i) {
            const double e = 0.5 * b.grain.mass * norm2(v[i] - U);
            sum += e;
            sum2 += e * e;
        }
        e_species[s] = b.count > 0 ? sum / static_cast<double>(b.count) : 0.0;
        E += sum;
        squares += sum2 - e_species[s] * sum;
    }
    const double e_mean = N > 0 ? E / N : 0.0;
    // Each species' mean rotational energy r_s and the grains' mean r (T_rot's modes).
    std::vector<double> r_species(species.size(), 0.0);
    double R = 0;
    if (!modes_.empty())
        for (std::size_t s = 0; s < species.size(); ++s) {
            const SpeciesBlock& b = species[s];
            double sum = 0;
            for (std::size_t i = b.offset; i < b.offset + b.count; ++i)
                sum += 0.5 * b.moment_of_inertia() * norm2(w[i]);
            r_species[s] = b.count > 0 ? sum / static_cast<double>(b.count) : 0.0;
            R += sum;
        }
    // Nearest grid point, grain by grain in store order (a deterministic sum per cell).
    for (std::vector<double>& f : fields_)
        std::fill(f.begin(), f.end(), 0.0);
    std::fill(rotation_.begin(), rotation_.end(), 0.0);
    std::array<double, 3> per_length{};
    for (std::size_t a = 0; a < 3; ++a)
        per_length[a] = G[a] / g_.box[a];
    for (std::size_t s = 0; s < species.size(); ++s) {
        const SpeciesBlock& b = species[s];
        const double m = b.grain.mass;
        for (std::size_t i = b.offset; i < b.offset + b.count; ++i) {
            const double q[3] = {x[i].x, x[i].y, x[i].z};
            std::size_t c = 0;
            for (std::size_t a = 0; a < 3; ++a) {
                const double r = std::floor(q[a] * per_length[a]); // NaN: cell 0 (the row then reports the NaN)
                const int k = r >= 0 ? static_cast<int>(std::min(r, static_cast<double>(G[a] - 1))) : 0;
                c = c * static_cast<std::size_t>(G[a]) + static_cast<std::size_t>(k);
            }
            const Vec3 cv = v[i] - U;
            fields_[0][c] += 1;
            fields_[1][c] += m * cv.x;
            fields_[2][c] += m * cv.y;
            fields_[3][c] += m * cv.z;
            fields_[4][c] += 0.5 * m * norm2(cv) - e_species[s];
            if (!modes_.empty())
                rotation_[c] += 0.5 * b.moment_of_inertia() * norm2(w[i]) - r_species[s];
        }
    }
    return finish(N, M, e_mean, squares, N > 0 ? R / N : 0.0, team);
}

std::vector<double> Spectra::compute_from_cell_sums(const std::vector<double>& cell_sums, std::size_t fields,
                                                    const std::vector<double>& spin_sums, const std::vector<Vec3>& v,
                                                    const std::vector<SpeciesBlock>& species, WorkerTeam& team) {
    const std::array<int, 3>& G = g_.grid;
    const std::size_t S = species.size(), nx = static_cast<std::size_t>(G[0]), ny = static_cast<std::size_t>(G[1]),
                      nz = static_cast<std::size_t>(G[2]), cells = nx * ny * nz;
    if (fields < 5 || cell_sums.size() != cells * S * fields)
        throw std::logic_error("Spectra: the cell sums do not fit the grid and species");
    if (!modes_.empty() && spin_sums.size() != cells * S)
        throw std::logic_error("Spectra: the modes need the spins' sums per cell and species");
    const auto at = [&](std::size_t c, std::size_t s) { return cell_sums.data() + (c * S + s) * fields; };
    // U from the cells' momenta; each species' mean kinetic energy about it,
    // sum_j m |v_j - U|^2 / 2 = (m/2) (sum |v|^2 - 2 U.sum v + n |U|^2), from the cells' sums too.
    double N = 0, M = 0;
    Vec3 P{};
    std::vector<double> n_species(S, 0.0);
    std::vector<Vec3> v_species(S, Vec3{});
    std::vector<double> v2_species(S, 0.0);
    for (std::size_t c = 0; c < cells; ++c)
        for (std::size_t s = 0; s < S; ++s) {
            const double* t = at(c, s);
            n_species[s] += t[0];
            v_species[s] += Vec3{t[1], t[2], t[3]};
            v2_species[s] += t[4];
        }
    for (std::size_t s = 0; s < S; ++s) {
        N += n_species[s];
        M += species[s].grain.mass * n_species[s];
        P += species[s].grain.mass * v_species[s];
    }
    const Vec3 U = M > 0 ? (1.0 / M) * P : Vec3{};
    std::vector<double> e_species(S, 0.0);
    double E = 0;
    for (std::size_t s = 0; s < S; ++s) {
        const double sum =
            0.5 * species[s].grain.mass * (v2_species[s] - 2 * dot(U, v_species[s]) + n_species[s] * norm2(U));
        e_species[s] = n_species[s] > 0 ? sum / n_species[s] : 0.0;
        E += sum;
    }
    const double e_mean = N > 0 ? E / N : 0.0;
    // Each species' mean rotational energy r_s and the grains' mean r, from the spins' sums.
    std::vector<double> r_species(S, 0.0);
    double R = 0;
    if (!modes_.empty()) {
        for (std::size_t c = 0; c < cells; ++c)
            for (std::size_t s = 0; s < S; ++s)
                r_species[s] += spin_sums[c * S + s];
        for (std::size_t s = 0; s < S; ++s) {
            const double sum = 0.5 * species[s].moment_of_inertia() * r_species[s];
            r_species[s] = n_species[s] > 0 ? sum / n_species[s] : 0.0;
            R += sum;
        }
    }
    // sum_j (e_j - e_s(j))^2 needs the grains themselves: one pass over the velocities.
    double squares = 0;
    for (std::size_t s = 0; s < S; ++s) {
        const SpeciesBlock& b = species[s];
        double sum2 = 0;
        for (std::size_t i = b.offset; i < b.offset + b.count; ++i) {
            const double d = 0.5 * b.grain.mass * norm2(v[i] - U) - e_species[s];
            sum2 += d * d;
        }
        squares += sum2;
    }
    // The fields per cell from its sums: sum_j m c_j = m (sum v - n U), sum_j (e_j - e_s) as above
    // less n e_s; the cells x fastest here, z fastest in the transforms' order.
    const double U2 = norm2(U);
    for (std::size_t z = 0; z < nz; ++z)
        for (std::size_t y = 0; y < ny; ++y)
            for (std::size_t x = 0; x < nx; ++x) {
                const std::size_t c = (z * ny + y) * nx + x, to = (x * ny + y) * nz + z;
                double n = 0, px = 0, py = 0, pz = 0, h = 0;
                for (std::size_t s = 0; s < S; ++s) {
                    const double* t = at(c, s);
                    const double m = species[s].grain.mass;
                    const Vec3 sv{t[1], t[2], t[3]};
                    n += t[0];
                    px += m * (sv.x - t[0] * U.x);
                    py += m * (sv.y - t[0] * U.y);
                    pz += m * (sv.z - t[0] * U.z);
                    h += 0.5 * m * (t[4] - 2 * dot(U, sv) + t[0] * U2) - t[0] * e_species[s];
                }
                fields_[0][to] = n;
                fields_[1][to] = px;
                fields_[2][to] = py;
                fields_[3][to] = pz;
                fields_[4][to] = h;
                if (!modes_.empty()) {
                    double r = 0;
                    for (std::size_t s = 0; s < S; ++s)
                        r += 0.5 * species[s].moment_of_inertia() * spin_sums[c * S + s] - at(c, s)[0] * r_species[s];
                    rotation_[to] = r;
                }
            }
    return finish(N, M, e_mean, squares, N > 0 ? R / N : 0.0, team);
}

std::vector<double> Spectra::finish(double N, double M, double e_mean, double squares, double r_mean,
                                    WorkerTeam& team) {
    const std::array<int, 3>& G = g_.grid;
    const fftw_plan plan = plan_->plan;
    team.for_each(5, [&](std::size_t f) {
        fftw_execute_dft_r2c(plan, fields_[f].data(), reinterpret_cast<fftw_complex*>(transforms_[f].data()));
    });

    const auto at = [&](int f, std::size_t s) {
        const std::vector<double>& t = transforms_[static_cast<std::size_t>(f)];
        return cplx(t[2 * s], t[2 * s + 1]);
    };
    const auto stored = [&](int i, int j, int l) { // index of (n_x, n_y, n_z >= 0) in the half spectrum
        const int ii = i < 0 ? i + G[0] : i, jj = j < 0 ? j + G[1] : j;
        return (static_cast<std::size_t>(ii) * static_cast<std::size_t>(G[1]) + static_cast<std::size_t>(jj)) *
                   static_cast<std::size_t>(G[2] / 2 + 1) +
               static_cast<std::size_t>(l);
    };
    // The four spectra at stored wave vector s of wave numbers n.
    const auto spectra_at = [&](std::size_t s, const int n[3], double out[4]) {
        double k[3], k2 = 0;
        for (std::size_t a = 0; a < 3; ++a) {
            k[a] = 2 * std::numbers::pi * n[a] / g_.box[a];
            k2 += k[a] * k[a];
        }
        const double kn = std::sqrt(k2);
        const cplx rho = at(0, s), p[3] = {at(1, s), at(2, s), at(3, s)}, h = at(4, s);
        const cplx par = (k[0] * p[0] + k[1] * p[1] + k[2] * p[2]) / kn;
        double perp = 0;
        for (std::size_t a = 0; a < 3; ++a)
            perp += std::norm(p[a] - par * (k[a] / kn));
        out[0] += std::norm(rho) / N;
        out[1] += perp / (2 * M);
        out[2] += std::norm(par) / M;
        out[3] += std::norm(h) / squares;
    };

    std::vector<double> result;
    result.reserve(bins_.size() * spectrum_field_count + modes_.size() * mode_field_count);
    // Shells: every stored wave vector, its mirror -k counted too where it is not stored itself.
    std::vector<double> shell_sums(bins_.size() * spectrum_field_count, 0.0);
    std::vector<std::size_t> shell_row; // shell number -> its row in bins_
    for (std::size_t r = 0; r < bins_.size() && bins_[r].axis == 0; ++r) {
        shell_row.resize(static_cast<std::size_t>(bins_[r].n) + 1, 0);
        shell_row[static_cast<std::size_t>(bins_[r].n)] = r;
    }
    const int Hz = G[2] / 2 + 1;
    for (int i = 0; i < G[0]; ++i)
        for (int j = 0; j < G[1]; ++j)
            for (int l = 0; l < Hz; ++l) {
                const std::size_t s = stored(i, j, l);
                const int sh = shell_of_[s];
                if (sh == 0)
                    continue;
                const int n[3] = {signed_index(i, G[0]), signed_index(j, G[1]), l};
                double out[4] = {0, 0, 0, 0};
                spectra_at(s, n, out);
                const double twice = l == 0 ? 1.0 : 2.0; // -k is not stored for n_z > 0
                double* sum = shell_sums.data() + shell_row[static_cast<std::size_t>(sh)] * spectrum_field_count;
                for (std::size_t f = 0; f < spectrum_field_count; ++f)
                    sum[f] += twice * out[f];
            }
    for (std::size_t r = 0; r < bins_.size(); ++r) {
        const SpectrumBin& b = bins_[r];
        double out[4] = {0, 0, 0, 0};
        if (b.axis == 0) {
            for (std::size_t f = 0; f < spectrum_field_count; ++f)
                out[f] = shell_sums[r * spectrum_field_count + f] / b.modes;
        } else {
            int n[3] = {0, 0, 0};
            n[b.axis - 1] = b.n;
            spectra_at(stored(n[0], n[1], n[2]), n, out);
        }
        result.insert(result.end(), out, out + spectrum_field_count);
    }
    // T_rot's field summed over the slabs normal to each axis (its modes lie along the axes).
    std::array<std::vector<double>, 3> slabs;
    if (!modes_.empty()) {
        for (std::size_t a = 0; a < 3; ++a)
            slabs[a].assign(static_cast<std::size_t>(G[a]), 0.0);
        std::size_t c = 0;
        for (std::size_t i = 0; i < static_cast<std::size_t>(G[0]); ++i)
            for (std::size_t j = 0; j < static_cast<std::size_t>(G[1]); ++j)
                for (std::size_t l = 0; l < static_cast<std::size_t>(G[2]); ++l, ++c) {
                    slabs[0][i] += rotation_[c];
                    slabs[1][j] += rotation_[c];
                    slabs[2][l] += rotation_[c];
                }
    }
    // Modes: the transforms at k along the axis, their phase referred to the cell centres
    // (exp(-i k Delta/2)), normalised to amplitudes; T_rot's from its slabs at their centres.
    for (const ModeIndex& m : modes_) {
        int n[3] = {0, 0, 0};
        n[m.axis - 1] = m.n;
        const std::size_t s = stored(n[0], n[1], n[2]);
        const double delta = g_.box[static_cast<std::size_t>(m.axis - 1)] / G[static_cast<std::size_t>(m.axis - 1)];
        const cplx centre = std::polar(1.0, -0.5 * m.k * delta);
        const cplx a[5] = {2.0 / N * centre * at(0, s), 2.0 / M * centre * at(1, s), 2.0 / M * centre * at(2, s),
                           2.0 / M * centre * at(3, s), 2.0 / (N * e_mean) * centre * at(4, s)};
        for (const cplx& z : a) {
            result.push_back(z.real());
            result.push_back(z.imag());
        }
        cplx rot = 0;
        if (r_mean > 0) {
            const std::vector<double>& slab = slabs[static_cast<std::size_t>(m.axis - 1)];
            for (std::size_t i = 0; i < slab.size(); ++i)
                rot += slab[i] * std::polar(1.0, -m.k * (static_cast<double>(i) + 0.5) * delta);
            rot *= 2.0 / (N * r_mean);
        }
        result.push_back(rot.real());
        result.push_back(rot.imag());
    }
    return result;
}

} // namespace roughgas
