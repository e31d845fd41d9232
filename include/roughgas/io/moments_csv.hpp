#pragma once
// The rows of moments.csv (docs/reference.md "Output"): the solver's columns (dsmc_columns), with
// replicas > 1 each followed by its standard error X_err; for cooling runs the reduced cooling rate
//   zeta_star = -ln(T_tr/T_tr,prev)/(coll_per_particle - coll_per_particle,prev),
// the translational temperature's decay per collision per particle since the replica's previous row
// (NaN in the first), taken per replica and then averaged like the solver's columns (the scaled
// homogeneous cooling state has T_tr ~ exp(-zeta_star coll_per_particle): the interval's value is
// exact there however far apart the rows are); then, for constant-restitution runs, the
// Maxwellian-approximation theory (observables/theory.hpp) at the row's t:
//   T_tr_theory, T_rot_theory, theta_theory          (over all grains)
//   T_tr_theory.NAME, T_rot_theory.NAME, theta_theory.NAME   (mixtures: per species, in order)
//   T_tr.A/T_tr.B_theory, T_rot.A/T_rot.B_theory     (mixtures: every pair A before B)
//   zeta_star_theory = -(dT_tr/dt)/(T_tr nu_c)       (cooling runs; nu_c the collisions per particle
//                                                      and unit time of the same Maxwellian state)
//   theta_sonine, zeta_star_sonine, a20_sonine, a02_sonine, a11_sonine
//                                                     (one species, hard-sphere kernel: the scaled
//                                                      cooling state in the first Sonine approximation,
//                                                      observables/sonine_cooling_state.hpp, the same
//                                                      in every row)
//   T_tr_steady_theory, T_rot_steady_theory, theta_steady_theory, then T_tr_sonine, a20_sonine
//                                                     (driven runs: the steady state's theory, the same
//                                                      in every row)
//   a_star_grad, eta_star_grad, P_xx_star_grad, P_yy_star_grad, P_zz_star_grad, N1_star_grad, N2_star_grad
//                                                     (shear runs of one species of smooth grains with a
//                                                      constant alpha < 1: the steady state in Grad's
//                                                      approximation, observables/enskog_usf_theory.hpp)
// and the rule that no value is NaN or infinite unless it is undefined by definition.
#include "roughgas/dsmc/output_columns.hpp"
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/observables/spectra.hpp"
#include "roughgas/observables/theory.hpp"

#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace roughgas {

// A row holds a value that is neither finite nor undefined by definition: the run must stop.
class NonFiniteValue : public std::runtime_error {
  public:
    NonFiniteValue(std::string column, double t, double value, const std::string& what)
        : std::runtime_error(what), column_(std::move(column)), t_(t), value_(value) {}
    const std::string& column() const { return column_; }
    double t() const { return t_; }
    double value() const { return value_; }

  private:
    std::string column_;
    double t_, value_;
};

class MomentsTable {
  public:
    explicit MomentsTable(const RunSpec& spec);

    // Every CSV column in order, with its unit.
    const std::vector<Column>& columns() const { return columns_; }
    std::vector<std::string> names() const { return column_names(columns_); }
    std::vector<std::string> units() const { return column_units(columns_); }
    const std::vector<Column>& solver_columns() const { return solver_; }
    // walls.csv (runs with walls; empty otherwise): t, coll_per_particle, then wall_columns
    // (dsmc/run.hpp), with replicas > 1 each followed by X_err.
    const std::vector<Column>& wall_table_columns() const { return wall_columns_; }
    // profiles.csv (box runs; empty otherwise): t, coll_per_particle, bin, the bin centre's
    // coordinate (named x, y or z), then the fields of observables/profiles.hpp, with replicas > 1
    // each followed by X_err; one row per bin.
    const std::vector<Column>& profile_table_columns() const { return profile_columns_; }
    // spectra.csv and modes.csv (box runs with spectra; empty otherwise; observables/spectra.hpp):
    // t, coll_per_particle, axis (0: shells of |k|; 1, 2, 3: along x, y, z), n (the shell or wave
    // number), k, n_modes (spectra.csv only), then the fields, with replicas > 1 each followed by
    // X_err; one row per shell or wave number; modes.csv ends with the theory's rates where
    // shear_mode_theory applies (gamma_perp_theory; where longitudinal_mode_theory applies, the
    // Boltzmann equation, also gamma_heat_theory, gamma_sound_theory, omega_sound_theory).
    const std::vector<Column>& spectra_table_columns() const { return spectra_columns_; }
    const std::vector<Column>& modes_table_columns() const { return modes_columns_; }
    bool has_theory() const { return trajectory_.has_value(); }
    bool has_sonine() const { return !sonine_.empty(); }
    int replicas() const { return replicas_; }

    // Throws NonFiniteValue, naming the column and t, unless every value of a replica's row
    // (replica_row_columns order: dsmc_columns, then wall_columns) is finite or undefined by definition:
    //   the wall columns and the profiles' collisional fields in the row at t = 0 (no interval yet);
    //   a profile bin's fields but n when the bin holds no grain, its theta when its T_tr is 0;
    //   coll_rate, coll_rate.NAME, E_diss_rate in the row at t = 0 (no interval yet);
    //   theta, a20, a11, T_tr.A/T_tr.B with the T_tr they divide by equal to 0;
    //   a02, a11, A_cw, T_rot.A/T_rot.B with the T_rot they divide by equal to 0 (e.g. smooth
    //   grains started without rotation).
    void check(std::span<const double> solver_row) const;

    // The CSV row from the replicas' solver rows of the same output time (one per replica, in
    // replica order): the mean, with replicas > 1 the standard error of the mean
    // sqrt(sum (x - mean)^2/(K (K - 1))), zeta_star, then the theory at the mean t. Call once per
    // output time, in order (zeta_star takes each replica's previous row, the theory is integrated
    // on from the previous row).
    std::vector<double> combine(std::span<const std::span<const double>> replica_rows);
    // The walls.csv row from the same replica rows.
    std::vector<double> combine_walls(std::span<const std::span<const double>> replica_rows) const;
    // The profiles.csv rows (one per bin) from the same replica rows.
    std::vector<std::vector<double>> combine_profiles(std::span<const std::span<const double>> replica_rows) const;
    // The spectra.csv and modes.csv rows from the same replica rows.
    std::vector<std::vector<double>> combine_spectra(std::span<const std::span<const double>> replica_rows) const;
    std::vector<std::vector<double>> combine_modes(std::span<const std::span<const double>> replica_rows) const;

  private:
    const Column& row_column(std::size_t j) const;
    void require_replicas(std::size_t rows) const; // one row per replica, else std::invalid_argument
    std::vector<Column> solver_, columns_, wall_solver_, wall_columns_, profile_solver_, profile_columns_;
    std::vector<Column> spectra_solver_, spectra_columns_, modes_columns_;
    std::size_t profile_start_ = 0;     // the first profile value in a replica row
    std::size_t spectra_start_ = 0;     // the first spectra value in a replica row
    std::vector<SpectrumBin> spectrum_bins_;
    std::vector<ModeIndex> modes_;
    std::vector<std::vector<double>> mode_theory_; // per mode, its theory columns (empty: none)
    // One block of profiles.csv, spectra.csv or modes.csv rows: per entry, t and coll_per_particle,
    // head(entry), then the replicas' mean (and error) of its `count` fields from `first` in the row.
    std::vector<std::vector<double>> combine_entries(std::span<const std::span<const double>> rows,
                                                     std::size_t entries,
                                                     const std::function<std::vector<double>(std::size_t)>& head,
                                                     std::size_t first, std::size_t count) const;
    std::vector<double> bin_centres_;
    std::vector<std::string> species_names_;
    int replicas_ = 1;
    std::optional<HcsTrajectory> trajectory_;
    std::vector<double> sonine_; // the *_sonine columns' values (empty: not written)
    std::vector<double> constant_theory_; // a driven gas's steady-state columns (empty: not written)
    std::vector<double> shear_theory_;    // the *_grad columns of a smooth sheared gas (empty: not written)
    bool zeta_ = false;                          // cooling runs: the zeta_star column
    // Enskog runs: p_theory, from the trajectory at t and the previous row's collisional part.
    bool enskog_ = false;
    double t_prev_ = 0, p_coll_prev_ = std::numeric_limits<double>::quiet_NaN();
    double pressure_theory(double t, const HcsTemperatures& T, double p_coll_mid);
    std::vector<double> prev_T_tr_, prev_cpp_;  // per replica, its previous row's (NaN: none yet)
};

// The docs/reference.md table of moments.csv columns (`roughgas keys --output`): every column the solver and
// the writer can produce, with its unit (from the code) and meaning; mixture columns with the
// placeholders NAME (a species) and A, B (two species, A before B).
std::string moments_columns_markdown();
// The meaning of a column, "" if it has none (a test requires one for every column).
std::string moments_column_meaning(const std::string& name);

} // namespace roughgas
