#pragma once
// Fourier spectra of a periodic box's fields (spectra.csv and modes.csv, docs/reference.md): the
// structure factor S(k), the longitudinal and transverse current spectra E_par(k), E_perp(k) and
// the spectrum S_T(k) of the kinetic energy at fixed density, from the grains on the grid of the
// collision cells, and the complex amplitudes of the lowest modes along each axis.
//
// Assignment: nearest grid point. Each grain counts in its cell, at the cell's corner X_c (the
// transforms' phase; modes.csv refers the phase to the cell's centre). With N grains of masses m_j,
// total mass M, mass-weighted mean velocity U, peculiar velocities c_j = v_j - U, kinetic energies
// e_j = m_j |c_j|^2 / 2, e_s the mean of e_j over species s and, for a wave vector
// k = (2 pi n_x / L_x, 2 pi n_y / L_y, 2 pi n_z / L_z) of the grid,
//   rho_k = sum_j exp(-i k.X_j),  p_k = sum_j m_j c_j exp(-i k.X_j),  h_k = sum_j (e_j - e_s(j)) exp(-i k.X_j),
//   S = |rho_k|^2 / N,
//   E_par = |k^.p_k|^2 / M,   E_perp = |p_k - k^ (k^.p_k)|^2 / (2 M)   (k^ = k / |k|),
//   S_T = |h_k|^2 / sum_j (e_j - e_s(j))^2.
// Why these normalisations: when the positions are uniform and independent of each other and of the
// velocities, E|rho_k|^2 = N, E|k^.p_k|^2 = sum_j m_j^2 <c_a^2>_j and E|h_k|^2 = sum_j (e_j - e_s)^2 at
// every k != 0 of the grid whatever the cell size: S = S_T = 1, and E_par = E_perp = sum_j m_j^2
// |c_j|^2 / (3M), which is T for one species (T_tr; for a mixture sum_s x_s m_s T_s / (mean mass)).
// So the shot noise is the value 1 (T), with no term to subtract, for a Maxwellian or not (a
// cooling gas's a20 changes the energies' variance, which S_T divides by). S_T is the spectrum of the
// kinetic energy at fixed density and composition (the species' mean energies taken away). The
// DSMC keeps an elastic gas in that state (its cell collisions leave the product of Maxwellians
// invariant). Nearest-grid-point assignment multiplies a field's long waves by the cell's window,
// prod_a sinc(k_a Delta_a / 2), and folds the wave numbers beyond the grid's onto it (aliasing):
// below a quarter of the grid's wave numbers the window costs less than 20 % of a spectrum.
//
// Spectra are given over shells of |k| (axis 0: shell s holds the wave vectors with
// (s - 1/2) dk <= |k| < (s + 1/2) dk, dk = 2 pi / max L_a over the axes of more than two cells, up
// to the largest |k| every such axis reaches) and along each axis (axis 1, 2, 3: k = 2 pi n / L_a along x, y, z). The wave numbers
// |n_a| = G_a/2 of an even grid (the Nyquist planes, real and without a direction) are left out.
// A shell's n_modes counts k and -k apart: they are one mode of the real fields, so the independent
// modes are half of it.
//
// modes.csv: for the lowest `modes` wave numbers n = 1, 2, ... along each axis a (k = 2 pi n / L_a)
// the amplitudes (2/N) sum_j q_j exp(-i k.x_j) with the cell centre for x_j, of q = 1 (density
// relative to its mean), of the velocity (2/M) sum_j m_j c_j exp(-i k.x_j) (the flow's amplitude),
// of (e_j - e_s(j)) / e, e the mean of e_j (the kinetic temperature's, relative), and of
// (r_j - r_s(j)) / r with the rotational energies r_j = J_j |omega_j|^2 / 2 (T_rot's, relative; 0
// when no grain spins): a wave A sin(k.x) sampled at the cell centres has the amplitude -i A
// (A cos(k.x): A); grains spread through their cells see it through the window, -i A sinc(k Delta / 2).
// The rotational field enters no spectrum: its modes are sums over the cells' slabs along the axis,
// without a transform of its own.
//
// The transforms: FFTW's real-to-complex 3-D transform of each field, planned once per run
// (FFTW_ESTIMATE: the same plan, and so the same bits, in every run) for one thread; the five
// fields are transformed on the team's threads at once. A plan for several threads may order its
// arithmetic otherwise and change the last bits with the thread count, which the results must not.
#include "roughgas/core/vec.hpp"
#include "roughgas/core/worker_team.hpp"
#include "roughgas/dsmc/output_columns.hpp"
#include "roughgas/dsmc/species.hpp"

#include <array>
#include <memory>
#include <vector>

namespace roughgas {

inline constexpr const char* spectrum_fields[] = {"S", "E_perp", "E_par", "S_T"};
inline constexpr std::size_t spectrum_field_count = std::size(spectrum_fields);
inline constexpr std::size_t spectrum_S_T = 3; // index of S_T in spectrum_fields
inline constexpr const char* mode_fields[] = {"n_re",   "n_im",   "u_x_re", "u_x_im", "u_y_re",   "u_y_im",
                                              "u_z_re", "u_z_im", "T_re",   "T_im",   "T_rot_re", "T_rot_im"};
inline constexpr std::size_t mode_field_count = std::size(mode_fields);
inline constexpr std::size_t mode_T_first = 8;      // T_re, T_im
inline constexpr std::size_t mode_T_rot_first = 10; // T_rot_re, T_rot_im

struct SpectraGeometry {
    std::array<int, 3> grid{1, 1, 1};      // G_a: the collision cells
    std::array<double, 3> box{1, 1, 1};    // L_a
    int modes = 3;                         // per axis in modes.csv (fewer where the grid has fewer)
};

// A row of spectra.csv: axis 0 (shell n) or 1, 2, 3 (wave number n along x, y, z), its |k| (the
// shell's mean) and how many wave vectors it averages.
struct SpectrumBin {
    int axis = 0, n = 0;
    double k = 0;
    int modes = 0;
};
std::vector<SpectrumBin> spectrum_bins(const SpectraGeometry& g);

// A row of modes.csv: axis 1, 2, 3 and wave number n along it.
struct ModeIndex {
    int axis = 1, n = 1;
    double k = 0;
};
std::vector<ModeIndex> mode_indices(const SpectraGeometry& g);

// The units of spectrum_fields and mode_fields.
std::vector<Column> spectrum_field_columns();
std::vector<Column> mode_field_columns();

// The transforms of one replica (its buffers and FFTW plans, made once).
class Spectra {
  public:
    explicit Spectra(const SpectraGeometry& g);
    ~Spectra();
    Spectra(const Spectra&) = delete;
    Spectra& operator=(const Spectra&) = delete;

    // Every spectrum bin's fields (spectrum_bins order, spectrum_field_count each), then every
    // mode's (mode_indices order, mode_field_count each). Grains outside the box are taken in
    // the nearest cell.
    // `w`: the angular velocities (T_rot's modes).
    std::vector<double> compute(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const std::vector<Vec3>& w,
                                const std::vector<SpeciesBlock>& species, WorkerTeam& team);

    // The same from the box engine's sums per cell (SpatialEngine::cell_sums: per cell of the grid,
    // x fastest, and species, `fields` numbers of which the first five are the count of its
    // grains, the sum of their velocities and the sum of |v|^2; SpatialEngine::cell_spin_sums: the
    // sum of |omega|^2 per cell and species, needed only with modes) and the velocities (for the
    // variance of the energies): the grains counted in the cells the engine put them in, with no
    // pass over their positions. Equal to compute's results to round-off.
    std::vector<double> compute_from_cell_sums(const std::vector<double>& cell_sums, std::size_t fields,
                                               const std::vector<double>& spin_sums, const std::vector<Vec3>& v,
                                               const std::vector<SpeciesBlock>& species, WorkerTeam& team);

    // The five fields' transforms from the last compute (rho, p_x, p_y, p_z, h), each
    // G_x x G_y x (G_z/2 + 1) complex values (re, im), z fastest: for tests (Parseval).
    const std::vector<double>& transform(int field) const;
    // The five fields on the grid from the last compute, G_x x G_y x G_z, z fastest.
    const std::vector<double>& field(int field) const;

  private:
    // The transforms of fields_ and the rows from them.
    std::vector<double> finish(double N, double M, double e_mean, double squares, double r_mean, WorkerTeam& team);
    struct Plan;
    SpectraGeometry g_;
    std::vector<SpectrumBin> bins_;
    std::vector<ModeIndex> modes_;
    std::vector<int> shell_of_; // per stored wave vector: its shell (0: none)
    std::array<std::vector<double>, 5> fields_, transforms_;
    std::vector<double> rotation_; // sum_j (r_j - r_s(j)) per cell, z fastest as fields_ (with modes only)
    std::unique_ptr<Plan> plan_;
};

} // namespace roughgas
