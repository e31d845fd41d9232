// `roughgas run` of a spatially resolved case ([domain]; src/dsmc/drive_spatial.cpp): the same
// bytes for any thread count and for merged replica ranges; the box reported in mean free paths;
// what the box cannot run refused before any work; a small box cools as the homogeneous gas; the
// cell fields in HDF5 files with their XDMF sidecars.
#include "io_test_support.hpp"

#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/io/fields_file.hpp"
#include "roughgas/io/fields_series.hpp"
#include "roughgas/observables/longitudinal_modes.hpp"
#include "roughgas/observables/shear_mode.hpp"

#include <fmt/format.h>
#include "roughgas/io/case_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace roughgas {
namespace {

namespace fs = std::filesystem;
using test::replaced;

// Rough grains, alpha = 0.9, beta = 0.4, n = 0.02 (mean free path 11.25 for sigma = 1); a box of
// 4.4 mean free paths (below the shear-mode instability length, about 20 mean free paths at this
// alpha), cells of 0.89 of them.
std::string box_case(int particles = 4000, int replicas = 2, double end = 6.0) {
    return "[run]\nparticles = " + std::to_string(particles) + "\nreplicas = " + std::to_string(replicas) +
           "\nend = " + std::to_string(end) +
           "\noutput_every = 0.5\noutput_spacing = \"log\"\ndensity = 0.02\nseed = 4\n\n"
           "[[species]]\nmass = 1.0\nradius = 0.5\n\n"
           "[collision]\nmodel = \"constant\"\nalpha = 0.9\nbeta = 0.4\n\n"
           "[domain]\nsize = [50.0, 50.0, 50.0]\ncells = [5, 5, 5]\n";
}

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size()))
        ++n;
    return n;
}

TEST(BoxCli, ThreadsAndReplicaRangesGiveTheSameBytes) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("box.toml", box_case() + "\n[spectra]\nmodes = 2\n");
    const std::string run = "run " + q(f) + " --quiet --out ";
    ASSERT_EQ(test::run_roughgas(run + q(dir / "t1") + " --threads 1", dir).status, 0);
    ASSERT_EQ(test::run_roughgas(run + q(dir / "t2") + " --threads 2", dir).status, 0);
    ASSERT_EQ(test::run_roughgas(run + q(dir / "a") + " --replicas 0:1", dir).status, 0);
    ASSERT_EQ(test::run_roughgas(run + q(dir / "b") + " --replicas 1:2", dir).status, 0);
    const test::CommandResult m =
        test::run_roughgas("merge " + q(dir / "a") + " " + q(dir / "b") + " --quiet --out " + q(dir / "m"), dir);
    ASSERT_EQ(m.status, 0) << m.err;
    const std::string one = test::read_file(dir / "t1" / "moments.csv");
    EXPECT_FALSE(one.empty());
    EXPECT_EQ(test::read_file(dir / "t2" / "moments.csv"), one);
    EXPECT_EQ(test::read_file(dir / "m" / "moments.csv"), one);
    for (const char* file : {"spectra.csv", "modes.csv"}) {
        const std::string s = test::read_file(dir / "t1" / file);
        EXPECT_FALSE(s.empty()) << file;
        EXPECT_EQ(test::read_file(dir / "t2" / file), s) << file;
        EXPECT_EQ(test::read_file(dir / "m" / file), s) << file;
    }
    // The header gives the box and its cells in mean free paths.
    EXPECT_NE(one.find("periodic box 50 x 50 x 50 = 4.443 x 4.443 x 4.443 mean free paths"), std::string::npos);
    EXPECT_NE(one.find("5 x 5 x 5 collision cells (edge up to 0.889 lambda)"), std::string::npos);
    // Cells of 0.89 mean free paths: the set-up's warning in moments.csv and in each replica's own
    // file, once (the densest slab's 0.89 and its noise in the first row do not repeat it), the same
    // bytes however the run was split.
    const std::string warning = "warning: cells of up to 0.889 mean free paths (more than 0.5)";
    EXPECT_EQ(count(one, warning), 1u) << one;
    EXPECT_EQ(count(one, "(more than 0.5)"), 1u) << one;
    for (const char* replica : {"moments_0.csv", "moments_1.csv"}) {
        const std::string own = test::read_file(dir / "t1" / "replicas" / replica);
        EXPECT_EQ(count(own, "(more than 0.5)"), 1u) << replica;
        EXPECT_NE(own.find(warning), std::string::npos) << replica;
        EXPECT_EQ(test::read_file(dir / "t2" / "replicas" / replica), own) << replica;
        EXPECT_EQ(test::read_file(dir / "m" / "replicas" / replica), own) << replica;
    }
    // The densest cell of this uniform gas (32 grains per cell) reads as the mean density: the
    // cells' edge of 10 over lambda = 1/(sqrt(2) pi n sigma^2), in every row, and no warning of
    // the densest cell beside the slabs' (the cell's 0.89 would give one).
    const auto rows = test::read_csv(dir / "t1" / "moments.csv");
    for (const double x : rows.at("cell_over_lambda_cells"))
        EXPECT_NEAR(x, 10.0 * std::sqrt(2.0) * std::numbers::pi * 0.02, 1e-12);
    EXPECT_EQ(one.find("in the densest cell"), std::string::npos);
}

TEST(BoxCli, RefusesWhatTheBoxCannotRunBeforeAnyWork) {
    const test::ScratchDir dir;
    const std::string base = box_case();
    const std::string walls = replaced(base, "cells = [5, 5, 5]", "cells = [5, 5, 5]\nboundary = [\"periodic\", \"walls\", \"periodic\"]") + "\n";
    const std::string lower = "[wall_lower]\nkind = \"diffuse\"\ntemperature = 1.0\nvelocity = [0.0, 0.0, 0.3]\n";
    const std::string upper = "[wall_upper]\nkind = \"rough\"\nalpha = 0.9\nbeta = 0.5\n";
    const struct {
        std::string text, key, says;
    } bad[] = {
        {replaced(base, "cells = [5, 5, 5]", "cells = [2, 5, 5]"), "domain.cells",
         "cells of 2.22 mean free paths"},
        {replaced(base, "size = [50.0, 50.0, 50.0]", "size = [50.0, 0.0, 50.0]"), "domain.size[1]", "must be > 0"},
        {replaced(base, "cells = [5, 5, 5]", "cells = [5, 5]"), "domain.cells", "an array of three integers"},
        {replaced(base, "cells = [5, 5, 5]", "cells = [5, 5, 5]\nboundary = [\"periodic\", \"wall\", \"periodic\"]"),
         "domain.boundary[1]", "must be one of \"periodic\""},
        {replaced(base, "seed = 4", "seed = 4\nhistogram_every = 1.0"), "run.histogram_every", "[domain]"},
        {base.substr(0, base.find("[domain]")) + "[initial]\nmode = \"transverse\"\n", "initial.mode",
         "without [domain]"},
        {base + "\n[initial]\nmode = \"density\"\nwave = [0, 0, 0]\n", "initial.wave", "other than 0"},
        {base + "\n[initial]\nmode = \"density\"\namplitude = 1.0\n", "initial.amplitude",
         "initial.amplitude = 1: must be in (-1, 1) (A in units of sqrt(T/m) for a velocity wave, of the mean for a "
         "density or temperature wave: |A| < 1 keeps the flow below the thermal speed sqrt(T/m) and the density and "
         "temperature positive)"},
        {base + "\n[initial]\nmode = \"transverse\"\nwave = [3, 0, 0]\n", "initial.wave",
         "spans fewer than two cells"},
        {replaced(base, "particles = 4000", "particles = 4000000000000"), "run.particles", "GB"},
        {replaced(walls, "seed = 4", "seed = 4\nkind = \"shear\"") + lower + upper + "\n[shear]\nrate = 1.0\n",
         "domain.boundary", "Lees-Edwards boundaries along y"},
        {walls + "[wall_upper]\nkind = \"specular\"\n", "wall_lower", "[wall_lower] is missing"},
        {replaced(walls, "[\"periodic\", \"walls\", \"periodic\"]", "[\"walls\", \"walls\", \"periodic\"]") +
             replaced(lower, "[wall_lower]", "[wall_lower_y]") + upper,
         "wall_lower", "or axis x's own [wall_lower_x]"},
        {walls + lower + upper + "[wall_upper_y]\nkind = \"rough\"\nvelocity = [0.0, 0.1, 0.0]\n",
         "wall_upper_y.velocity", "moves along itself only"},
        {walls + lower + "[wall_upper]\nkind = \"diffuse\"\n", "wall_upper.temperature",
         "required for wall_upper.kind = \"diffuse\""},
        {walls + replaced(lower, "[0.0, 0.0, 0.3]", "[0.0, 0.2, 0.3]") + upper, "wall_lower.velocity",
         "moves along itself only"},
        {walls + lower + replaced(upper, "alpha = 0.9", "alpha = 0.0"), "wall_upper.alpha", "in (0, 1]"},
        {walls + lower + replaced(upper, "beta = 0.5", "beta = 1.5"), "wall_upper.beta", "in [-1, 1]"},
        {walls + lower + upper + "[spectra]\n", "domain.boundary", "[spectra] with walls"},
        {base.substr(0, base.find("[domain]")) + "[spectra]\n", "spectra", "[spectra] without [domain]"},
        {replaced(base, "seed = 4", "seed = 4\nkind = \"shear\"") + "\n[shear]\nrate = 0.01\n[spectra]\n", "spectra",
         "Lees-Edwards box is periodic only in its sheared frame"},
        {base + "\n[spectra]\nmodes = -1\n", "spectra.modes", "must be in [0, 4096]"},
        {base.substr(0, base.find("[domain]")) + "[fields]\n", "fields", "[fields] without [domain]"},
        {base + "\n[fields]\nreplicas = 3\n", "fields.replicas", "must be <= run.replicas = 2"},
        {base + "\n[fields]\nquantities = [\"n\", \"rho\"]\n", "fields.quantities[1]", "must be one of \"n\""},
        {base + "\n[fields]\nquantities = [\"n\", \"u\", \"n\"]\n", "fields.quantities", "\"n\" is given twice"},
        {base + "\n[fields]\nquantities = []\n", "fields.quantities", "an array of distinct strings"},
        {base + "\n[fields]\nevery = 0\n", "fields.every", "must be in [1, 1000000]"},
    };
    for (const auto& b : bad) {
        const fs::path f = dir.write("bad.toml", b.text);
        const test::CommandResult r = test::run_roughgas("run " + q(f) + " --out " + q(dir / "out"), dir);
        EXPECT_EQ(r.status, 2) << b.key << "\n" << r.err;
        EXPECT_NE(r.err.find(b.key), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(b.says), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir / "out"));
    }
    // Coarse cells on request.
    const fs::path f = dir.write("coarse.toml", replaced(replaced(base, "cells = [5, 5, 5]", "cells = [2, 2, 2]\nallow_coarse = true"),
                                                        "end = 6.000000", "end = 1.000000"));
    const test::CommandResult r = test::run_roughgas("run " + q(f) + " --out " + q(dir / "coarse"), dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("warning: cells of up to 2.22 mean free paths"), std::string::npos) << r.err;
}

// Walls on y of a sheared box: one error, the conflict, and none asking for or checking the walls'
// tables (which walls on z would need).
TEST(BoxCli, AShearedBoxWithWallsOnYIsOneError) {
    const test::ScratchDir dir;
    const std::string sheared =
        replaced(replaced(box_case(), "seed = 4", "seed = 4\nkind = \"shear\""), "cells = [5, 5, 5]",
                 "cells = [5, 5, 5]\nboundary = [\"periodic\", \"walls\", \"periodic\"]") +
        "\n[shear]\nrate = 0.01\n";
    for (const std::string walls : {"", "[wall_lower]\nkind = \"diffuse\"\nvelocity = [0.0, 0.1, 0.0]\n"}) {
        const fs::path f = dir.write("sheared.toml", sheared + walls);
        const test::CommandResult r = test::run_roughgas("check " + q(f), dir);
        EXPECT_EQ(r.status, 2) << r.err;
        EXPECT_NE(r.err.find("domain.boundary[1] = \"walls\" with run.kind = \"shear\""), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

// The set-up's warnings of a box's cells, on stderr once each from check and from run (also with
// --quiet) and in moments.csv's header: 60^3 cells of edge 0.83 (sigma = 1) hold 0.019 grains each;
// the shipped box's 5^3 cells of 10 hold 32 and warn of neither. The box of 0.89 mean free paths
// warns of that once on run's stderr: the densest slab's first row, 0.89 and its noise, does not
// say it again.
TEST(BoxCli, WarnsOfCellsSmallerThanAGrainAndOfFewGrainsOnce) {
    const test::ScratchDir dir;
    const std::string small = "cells of edge up to 0.8333, smaller than a grain (diameter sigma = 1";
    const std::string few = "warning: 0.0185 grains per cell on average (fewer than 5)";
    const fs::path f = dir.write("fine.toml", replaced(box_case(4000, 1, 1.0), "cells = [5, 5, 5]", "cells = [60, 60, 60]"));
    const test::CommandResult c = test::run_roughgas("check " + q(f), dir);
    EXPECT_EQ(c.status, 0) << c.err;
    EXPECT_EQ(count(c.err, small), 1u) << c.err;
    EXPECT_EQ(count(c.err, few), 1u) << c.err;
    const test::CommandResult r = test::run_roughgas("run " + q(f) + " --quiet --out " + q(dir / "fine"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(count(r.err, small), 1u) << r.err;
    EXPECT_EQ(count(r.err, few), 1u) << r.err;
    const std::string moments = test::read_file(dir / "fine" / "moments.csv");
    EXPECT_EQ(count(moments, "# warning: " + small), 1u) << moments;
    EXPECT_EQ(count(moments, "# " + few), 1u) << moments;

    const fs::path g = dir.write("coarse.toml", box_case(4000, 1, 1.0));
    const test::CommandResult k = test::run_roughgas("check " + q(g), dir);
    EXPECT_EQ(k.status, 0) << k.err;
    EXPECT_EQ(k.err.find("grains per cell"), std::string::npos) << k.err;
    EXPECT_EQ(k.err.find("smaller than a grain"), std::string::npos) << k.err;
    EXPECT_EQ(count(k.err, "warning: cells of up to 0.889 mean free paths (more than 0.5)"), 1u) << k.err;
    const test::CommandResult once = test::run_roughgas("run " + q(g) + " --out " + q(dir / "coarse"), dir);
    ASSERT_EQ(once.status, 0) << once.err;
    EXPECT_EQ(count(once.err, "(more than 0.5)"), 1u) << once.err;
    EXPECT_EQ(count(once.err, "warning: cells of up to 0.889 mean free paths"), 1u) << once.err;
}

// What the set-up did not warn of, the watch of the rows does: cells of 0.40 mean free paths at the
// mean density (no set-up warning) under a density wave of amplitude 0.6 along x put the densest
// of the 11 slabs at about 0.40 x 1.59 = 0.64 local mean free paths in the first row (its noise, 4 %
// for 730 grains, well inside 0.5 and 1): one warning, on stderr and in moments.csv.
TEST(BoxCli, TheRowsWarnOfWhatTheSetUpDidNot) {
    const test::ScratchDir dir;
    const fs::path f = dir.write(
        "wave.toml", replaced(box_case(8000, 1, 1.0), "cells = [5, 5, 5]", "cells = [11, 11, 11]") +
                         "\n[initial]\nmode = \"density\"\namplitude = 0.6\n");
    const test::CommandResult r = test::run_roughgas("run " + q(f) + " --quiet --out " + q(dir / "out"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.find("cells of up to"), std::string::npos) << r.err;
    EXPECT_EQ(count(r.err, "the cells reach"), 1u) << r.err;
    EXPECT_EQ(count(r.err, "local mean free paths in the densest slab (more than 0.5)"), 1u) << r.err;
    EXPECT_EQ(count(test::read_file(dir / "out" / "moments.csv"), "# warning: from t = 0"), 1u);
}

// [spectra] with a transverse wave u_y = A sqrt(T/m) sin(2 pi 2 x / L) (A = 0.3, T = 1: two
// wavelengths on 8 cells along x, so that the cells' window sinc(k dx/2) = sinc(pi/4) = 0.900 is
// seen): at t = 0 modes.csv has, at n = 2 along x, the flow amplitude u_y = -i A sqrt(T/m) sinc(pi/4),
// the density's and u_x's near 0, each within 5 of its sampling errors sqrt(2 T/(m N)) (velocity)
// and sqrt(2/N) (density); spectra.csv holds every row's block of shells and axis bins, and the
// transverse current of that wave vector carries the wave's energy N m (A sqrt(T/m) sinc)^2 / 8
// within 5 % (its thermal part T, and the cross term of wave and noise, 2 % of it); without the
// window both would be off by 10 and 19 %. modes.csv is not written with spectra.modes = 0.
TEST(BoxCli, SpectraAndModesOfATransverseWave) {
    const test::ScratchDir dir;
    const std::string c = replaced(replaced(box_case(200000, 1, 1.0), "cells = [5, 5, 5]", "cells = [8, 5, 5]"),
                                   "output_spacing = \"log\"", "output_spacing = \"linear\"") +
                          "\n[initial]\nmode = \"transverse\"\namplitude = 0.3\nwave = [2, 0, 0]\n\n[spectra]\nmodes = 2\n";
    const fs::path f = dir.write("wave.toml", c);
    const test::CommandResult r = test::run_roughgas("run " + q(f) + " --quiet --out " + q(dir / "w"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto m = test::read_csv(dir / "w" / "modes.csv");
    const auto s = test::read_csv(dir / "w" / "spectra.csv");
    const auto rows = test::read_csv(dir / "w" / "moments.csv").at("t").size();
    const double N = 200000, A = 0.3, window = std::sin(std::numbers::pi / 4) / (std::numbers::pi / 4);
    const double se_u = std::sqrt(2 / N), se_n = std::sqrt(2 / N);
    ASSERT_EQ(m.at("t").size(), rows * (2 + 2 + 2)); // n = 1, 2 along x, y, z
    EXPECT_EQ(m.at("axis")[1], 1);
    EXPECT_EQ(m.at("n")[1], 2);
    EXPECT_NEAR(m.at("u_y_im")[1], -A * window, 5 * se_u);
    EXPECT_NEAR(m.at("u_y_re")[1], 0.0, 5 * se_u);
    EXPECT_NEAR(m.at("u_x_im")[1], 0.0, 5 * se_u);
    EXPECT_NEAR(m.at("n_re")[1], 0.0, 5 * se_n);
    EXPECT_NEAR(m.at("n_im")[1], 0.0, 5 * se_n);
    // gamma_perp_theory: the transverse wave's Navier-Stokes rate at each row's k, the same in every
    // block: growth - damping (k lambda)^2 with lambda = 1/(sqrt(2) pi n sigma^2) of the case.
    const ShearModeTheory theory = rough_shear_mode(0.9, 0.4, 0.4);
    const double lambda = 1 / (std::sqrt(2.0) * std::numbers::pi * 0.02);
    for (std::size_t i = 0; i < m.at("t").size(); ++i) {
        const double kl = m.at("k")[i] * lambda;
        EXPECT_NEAR(m.at("gamma_perp_theory")[i], theory.growth - theory.damping * kl * kl, 1e-12 * kl * kl) << i;
    }
    EXPECT_EQ(s.at("t").size() % rows, 0u);
    const std::size_t block = s.at("t").size() / rows;
    int seen = 0;
    for (std::size_t i = 0; i < block; ++i) {
        ASSERT_EQ(s.at("t")[i], 0.0);
        if (s.at("axis")[i] == 1 && s.at("n")[i] == 2) {
            EXPECT_NEAR(s.at("E_perp")[i] / (N * std::pow(A * window, 2) / 8), 1.0, 0.05);
            ++seen;
        }
    }
    EXPECT_EQ(seen, 1);
    EXPECT_GT(s.at("t")[block], 0.0);
    // Rough grains: the longitudinal modes of their theory (rough_longitudinal_modes) too.
    const LongitudinalModeTheory rough = rough_longitudinal_modes(0.9, 0.4, 0.4);
    for (std::size_t i = 0; i < m.at("t").size(); ++i) {
        const LongitudinalModeRates r = longitudinal_mode_rates(rough, m.at("k")[i] * lambda);
        EXPECT_EQ(m.at("gamma_heat_theory")[i], r.heat.real()) << i;
        EXPECT_EQ(m.at("gamma_sound_theory")[i], r.sound[0].real()) << i;
        EXPECT_EQ(m.at("omega_sound_theory")[i], std::abs(r.sound[0].imag())) << i;
    }
    // Smooth grains: the longitudinal modes' eigenvalues at each row's k beside the transverse one.
    const fs::path smooth = dir.write("smooth.toml", replaced(c, "beta = 0.4", "beta = -1.0"));
    ASSERT_EQ(test::run_roughgas("run " + q(smooth) + " --quiet --set run.end=0.5 --out " + q(dir / "smooth"), dir).status,
              0);
    const auto ms = test::read_csv(dir / "smooth" / "modes.csv");
    const LongitudinalModeTheory lt = smooth_longitudinal_modes(0.9);
    for (std::size_t i = 0; i < ms.at("t").size(); ++i) {
        const double kl = ms.at("k")[i] * lambda;
        const LongitudinalModeRates r = longitudinal_mode_rates(lt, kl);
        EXPECT_EQ(ms.at("gamma_perp_theory")[i], shear_mode_rate(lt.shear, kl)) << i;
        EXPECT_EQ(ms.at("gamma_heat_theory")[i], r.heat.real()) << i;
        EXPECT_EQ(ms.at("gamma_sound_theory")[i], r.sound[0].real()) << i;
        EXPECT_EQ(ms.at("omega_sound_theory")[i], std::abs(r.sound[0].imag())) << i;
    }
    const fs::path none = dir.write("none.toml", replaced(c, "modes = 2", "modes = 0"));
    ASSERT_EQ(test::run_roughgas("run " + q(none) + " --quiet --out " + q(dir / "none"), dir).status, 0);
    EXPECT_TRUE(fs::exists(dir / "none" / "spectra.csv"));
    EXPECT_FALSE(fs::exists(dir / "none" / "modes.csv"));
}

// [fields]: the cells' fields of the replicas below fields.replicas at every fields.every-th row,
// one HDF5 file each and an XDMF sidecar per replica listing them; the grains the files count are
// the run's (n summed over the cells times the cell volume over the weight n V / N), the flow
// averages to the box's mean (zero: the grains start at rest on average and collisions keep the
// momentum), and the same run on another thread count writes the same bytes. An earlier run's
// fields are not overwritten without --force.
TEST(BoxCli, FieldsOfTheCellsInHdf5WithAnXdmfSidecar) {
    const test::ScratchDir dir;
    const std::string c =
        replaced(box_case(6000, 3, 2.0), "output_spacing = \"log\"", "output_spacing = \"linear\"") +
        "\n[fields]\nquantities = [\"n\", \"u\", \"P\"]\nevery = 2\nreplicas = 2\n";
    const fs::path f = dir.write("fields.toml", c);
    const std::string run = "run " + q(f) + " --quiet --out ";
    const test::CommandResult r = test::run_roughgas(run + q(dir / "a") + " --threads 1", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(test::run_roughgas(run + q(dir / "b") + " --threads 2", dir).status, 0);
    const std::size_t rows = test::read_csv(dir / "a" / "moments.csv").at("t").size();
    ASSERT_EQ(rows, 5u); // t = 0, 0.5, ..., 2
    for (int replica = 0; replica < 3; ++replica) {
        const fs::path d = fields_replica_dir(dir / "a", replica);
        EXPECT_EQ(fs::exists(d), replica < 2) << d;
        EXPECT_EQ(fs::exists(fields_xdmf_path(dir / "a", replica)), replica < 2);
        if (replica == 2)
            continue;
        const std::string xdmf = test::read_file(fields_xdmf_path(dir / "a", replica));
        for (std::size_t row = 0; row < rows; ++row) {
            const fs::path file = d / fmt::format("row_{:06d}.h5", row);
            ASSERT_EQ(fs::exists(file), row % 2 == 0) << file;
            if (row % 2 != 0)
                continue;
            EXPECT_NE(xdmf.find(">" + fs::relative(file, fields_dir(dir / "a")).string() + ":/u<"), std::string::npos)
                << xdmf;
            const FieldsFileHeader h = read_fields_header(file);
            EXPECT_EQ(h.row, row);
            EXPECT_EQ(h.replica, replica);
            EXPECT_EQ(h.cells, (std::array<std::int64_t, 3>{5, 5, 5}));
            const FieldsDataset n = read_fields_dataset(file, "n");
            EXPECT_EQ(n.shape, (std::vector<std::size_t>{5, 5, 5}));
            EXPECT_EQ(n.unit, "1/volume");
            double grains = 0;
            for (double x : n.values)
                grains += x * (10.0 * 10.0 * 10.0) / (0.02 * 50.0 * 50.0 * 50.0 / 6000);
            EXPECT_NEAR(grains, 6000, 1e-9);
            const FieldsDataset u = read_fields_dataset(file, "u"), P = read_fields_dataset(file, "P");
            EXPECT_EQ(u.shape, (std::vector<std::size_t>{5, 5, 5, 3}));
            EXPECT_EQ(P.shape, (std::vector<std::size_t>{5, 5, 5, 6}));
            Vec3 momentum{};
            for (std::size_t k = 0; k < 125; ++k)
                momentum += n.values[k] * Vec3{u.values[3 * k], u.values[3 * k + 1], u.values[3 * k + 2]};
            EXPECT_NEAR(norm(momentum) / 125, 0.0, 1e-12);
            EXPECT_THROW(read_fields_dataset(file, "T_tr"), std::runtime_error); // not asked for
        }
        for (const auto& e : fs::directory_iterator(d))
            EXPECT_EQ(test::read_file(e.path()),
                      test::read_file(fields_replica_dir(dir / "b", replica) / e.path().filename()))
                << e.path();
    }
    // Another run into the same directory needs --force, which removes the earlier fields first.
    const test::CommandResult again = test::run_roughgas(run + q(dir / "a"), dir);
    EXPECT_EQ(again.status, 2);
    EXPECT_NE(again.err.find("fields exists (use --force to overwrite)"), std::string::npos) << again.err;
    fs::remove_all(dir / "a" / "moments.csv");
    const fs::path every3 = dir.write("every3.toml", replaced(c, "every = 2", "every = 3"));
    ASSERT_EQ(test::run_roughgas("run " + q(every3) + " --quiet --force --out " + q(dir / "a"), dir).status, 0);
    EXPECT_TRUE(fs::exists(fields_replica_dir(dir / "a", 0) / "row_000003.h5"));
    EXPECT_FALSE(fs::exists(fields_replica_dir(dir / "a", 0) / "row_000002.h5"));
}

// roughgas check of a cooling box states the shear mode's linear stability (observables/shear_mode.hpp):
// for the case's rough grains (alpha = 0.8, beta = 0.4) and for smooth ones (beta = -1) the
// Navier-Stokes critical length, 14.83 and 18.8 mean free paths, against the box's longest side,
// longer (60 of them) or shorter (17.8), and the heat mode's (observables/longitudinal_modes.hpp);
// for a mixture, that there is no such statement.
TEST(BoxCli, CheckStatesTheShearModesStability) {
    const test::ScratchDir dir;
    const std::string c = std::string(ROUGHGAS_SOURCE_DIR) + "/cases/box_shear_mode.toml";
    const test::CommandResult rough = test::run_roughgas("check '" + c + "'", dir);
    ASSERT_EQ(rough.status, 0) << rough.err;
    EXPECT_NE(rough.out.find("rough grains, alpha = 0.8, beta = 0.4, in their cooling state theta = 1): critical "
                             "length 14.83 mean free paths; the box's longest side, 59.98 of them, is longer"),
              std::string::npos)
        << rough.out;
    const fs::path mix = dir.write(
        "mix.toml", replaced(test::read_file(c), "[[species]]\nname = \"grain\"\nmass = 1.0\nradius = 0.5\n",
                             "[[species]]\nname = \"a\"\nmass = 1.0\nradius = 0.5\nfraction = 0.5\n\n[[species]]\nname = \"b\"\nfraction = 0.5\n"
                             "mass = 2.0\nradius = 0.5\n"));
    const test::CommandResult mixture = test::run_roughgas("check " + q(mix), dir);
    ASSERT_EQ(mixture.status, 0) << mixture.err;
    EXPECT_NE(mixture.out.find("given for grains of one species with constant alpha and beta only"), std::string::npos)
        << mixture.out;
    const test::CommandResult unstable = test::run_roughgas("check '" + c + "' --set collision.beta=-1", dir);
    EXPECT_NE(unstable.out.find("critical length 18.8 mean free paths; the box's longest side, 59.98 of them, is "
                                "longer: linearly unstable: its longest transverse wave grows"),
              std::string::npos)
        << unstable.out;
    // Smooth grains: the heat mode too (observables/longitudinal_modes.hpp), at alpha = 0.8.
    const LongitudinalModeTheory heat = smooth_longitudinal_modes(0.8);
    EXPECT_NE(unstable.out.find(fmt::format("heat mode (density clusters): critical length {:.4g} mean free paths, "
                                            "the box is longer: the heat mode of its longest wave grows",
                                            heat.critical_length)),
              std::string::npos)
        << unstable.out;
    const LongitudinalModeTheory rough_heat = rough_longitudinal_modes(0.8, 0.4, 0.4);
    EXPECT_NE(rough.out.find(fmt::format("heat mode (density clusters): critical length {:.4g} mean free paths, "
                                         "the box is longer: the heat mode of its longest wave grows",
                                         rough_heat.critical_length)),
              std::string::npos)
        << rough.out;
    const test::CommandResult stable = test::run_roughgas(
        "check '" + c + "' --set collision.beta=-1 --set 'domain.size=[200.0,11.25,11.25]' --set 'domain.cells=[60,3,3]'",
        dir);
    EXPECT_EQ(stable.status, 0) << stable.err;
    EXPECT_NE(stable.out.find("17.77 of them, is shorter: linearly stable: its longest transverse wave decays"),
              std::string::npos)
        << stable.out;
    // The Enskog equation at phi = 0.2: Garzo & Dufty's critical length (in the dilute gas's mean free
    // paths) for smooth grains, none for rough ones, and no dilute heat mode.
    const std::string dense = " --set run.equation=enskog --set run.density=0.3819718634 --set domain.allow_coarse=true";
    const test::CommandResult enskog = test::run_roughgas("check '" + c + "' --set collision.beta=-1" + dense, dir);
    ASSERT_EQ(enskog.status, 0) << enskog.err;
    const ShearModeTheory e = enskog_shear_mode(0.8, 0.2, carnahan_starling_chi(0.2));
    EXPECT_NE(enskog.out.find(fmt::format("Enskog equation at phi = 0.2, chi = 1.758, smooth grains, alpha = 0.8): "
                                          "critical length {:.4g} dilute mean free paths",
                                          e.critical_length)),
              std::string::npos)
        << enskog.out;
    EXPECT_NE(enskog.out.find("heat mode (density clusters): its critical length is given for the Boltzmann equation "
                              "only"),
              std::string::npos)
        << enskog.out;
    const test::CommandResult enskog_rough = test::run_roughgas("check '" + c + "'" + dense, dir);
    EXPECT_NE(enskog_rough.out.find("the finite-phi critical length is given for smooth grains only (beta = 0.4 here)"),
              std::string::npos)
        << enskog_rough.out;
}

// Elastic smooth grains, 20000 of them to 20 collisions per particle with rows at linear spacing, in
// the box of box_case with `boundary` (its wall tables to be added).
std::string elastic_walled_box(const std::string& boundary) {
    return replaced(replaced(replaced(box_case(20000, 1, 20.0), "alpha = 0.9\nbeta = 0.4", "alpha = 1.0\nbeta = -1.0"),
                             "cells = [5, 5, 5]", "cells = [5, 5, 5]\nboundary = " + boundary),
                    "output_spacing = \"log\"", "output_spacing = \"linear\"");
}

// Walls along x and y, each axis its own: x closed by specular walls of its own ([wall_lower_x],
// [wall_upper_x]), y by the shared [wall_lower], [wall_upper], diffuse at 1.5 and 0.5 and sliding
// along x (allowed: they close y only). The specular walls exchange no energy and no tangential
// momentum (exactly 0 in every row), the hot wall gives heat and the cold one takes it (means over
// the rows beyond 5 standard errors), the header names each axis's walls, and a table for the
// periodic z is reported as unused.
TEST(BoxCli, EachAxisCanHaveWallsOfItsOwn) {
    const test::ScratchDir dir;
    const std::string text =
        elastic_walled_box("[\"walls\", \"walls\", \"periodic\"]") +
        "\n[wall_lower]\ntemperature = 1.5\nvelocity = [0.2, 0.0, 0.0]\n\n[wall_upper]\ntemperature = 0.5\n"
        "velocity = [-0.2, 0.0, 0.0]\n\n[wall_lower_x]\nkind = \"specular\"\n\n[wall_upper_x]\nkind = \"specular\"\n\n"
        "[wall_lower_z]\nkind = \"specular\"\n";
    const fs::path f = dir.write("own.toml", text);
    const CaseConfig c = load_case(f.string());
    ASSERT_TRUE(c.axis_wall_lower[0] && c.axis_wall_upper[0] && c.axis_wall_lower[2] && !c.axis_wall_lower[1]);
    EXPECT_EQ(parse_case(emit_case(c), "emitted.toml"), c) << "the echo in the CSV headers and checkpoints reads back";
    const test::CommandResult r = test::run_roughgas("run " + q(f) + " --out " + q(dir / "out"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("[wall_lower_z] is not used: axis z of domain.boundary is not \"walls\""), std::string::npos)
        << r.err;
    EXPECT_NE(test::read_file(dir / "out" / "moments.csv")
                  .find("walls along x (lower: specular, upper: specular) and y (lower: diffuse, upper: diffuse)"),
              std::string::npos);
    const auto csv = test::read_csv(dir / "out" / "walls.csv");
    const std::size_t rows = csv.at("t").size();
    ASSERT_GT(rows, 10u);
    for (std::size_t k = 1; k < rows; ++k) {
        for (const char* wall : {"x_lower", "x_upper"}) {
            EXPECT_GT(csv.at(std::string(wall) + ".hits")[k], 0) << wall << " row " << k;
            for (const char* column : {".q_x", ".P_yx", ".P_zx"})
                EXPECT_EQ(csv.at(wall + std::string(column))[k], 0.0) << wall << column << " row " << k;
        }
    }
    for (const char* column : {"y_lower.q_y", "y_upper.q_y"}) {
        const std::vector<double>& x = csv.at(column);
        double mean = 0, ss = 0;
        const double K = static_cast<double>(rows - 1);
        for (std::size_t k = 1; k < rows; ++k)
            mean += x[k] / K;
        for (std::size_t k = 1; k < rows; ++k)
            ss += (x[k] - mean) * (x[k] - mean);
        EXPECT_GT(mean, 5 * std::sqrt(ss / (K * (K - 1)))) << column << ": heat flows from the hot wall to the cold";
    }
}

// Elastic smooth grains between two diffuse walls at their temperature (normal to y): walls.csv has
// a row per moments.csv row, the same bytes for one and two threads; averaged over the rows after
// the first, each wall's pressure P_yy is n T_w and its hit rate n sqrt(T_w/(2 pi m)) (5 standard
// errors of the row-to-row scatter), the header names the walls.
TEST(BoxCli, WallsFileHasTheWallsPressureAndHitRate) {
    const test::ScratchDir dir;
    const std::string text =
        elastic_walled_box("[\"periodic\", \"walls\", \"periodic\"]") +
        "\n[wall_lower]\ntemperature = 1.0\n\n[wall_upper]\ntemperature = 1.0\n";
    const fs::path f = dir.write("walls.toml", text);
    const std::string run = "run " + q(f) + " --quiet --out ";
    ASSERT_EQ(test::run_roughgas(run + q(dir / "t1") + " --threads 1", dir).status, 0);
    const test::CommandResult r2 = test::run_roughgas(run + q(dir / "t2") + " --threads 2", dir);
    ASSERT_EQ(r2.status, 0) << r2.err;
    const std::string walls = test::read_file(dir / "t1" / "walls.csv");
    EXPECT_EQ(test::read_file(dir / "t2" / "walls.csv"), walls);
    EXPECT_NE(test::read_file(dir / "t1" / "moments.csv").find("walls along y"), std::string::npos);
    const auto csv = test::read_csv(dir / "t1" / "walls.csv");
    ASSERT_EQ(csv.at("t"), test::read_csv(dir / "t1" / "moments.csv").at("t"));
    const double n = 0.02;
    for (const char* wall : {"y_lower", "y_upper"}) {
        for (const auto& [column, expected] :
             {std::pair{std::string(wall) + ".P_yy", n}, std::pair{std::string(wall) + ".hits", n / std::sqrt(2 * std::numbers::pi)}}) {
            const std::vector<double>& x = csv.at(column);
            ASSERT_TRUE(std::isnan(x[0])) << column << " at t = 0: no interval yet";
            double mean = 0, ss = 0;
            const double K = static_cast<double>(x.size() - 1);
            for (std::size_t k = 1; k < x.size(); ++k)
                mean += x[k] / K;
            for (std::size_t k = 1; k < x.size(); ++k)
                ss += (x[k] - mean) * (x[k] - mean);
            EXPECT_NEAR(mean, expected, 5 * std::sqrt(ss / (K * (K - 1)))) << column;
        }
    }
}

// The box of 4.4 mean free paths against the homogeneous gas (the same case without [domain]) on
// the way to 40 collisions per particle, for restitution of four kinds: constant alpha and beta
// (the box's constant loop); Coulomb friction (Walton's beta(g_t/g_n)); the viscoelastic eps^N(g_N)
// of ice from its table, rough with a constant beta; and the contact model's eps^N and eps^T of ice
// from both tables (brilliantov; cases/hcs_brilliantov.toml, its tables integrated to 1e-6 and kept
// in a file for the second run). The last three go through the per-pair policies' loop; the ice in
// boxes of 4.4 mean free paths and cells of 0.89. At the box's rows nearest 5, 10, 20 and 40
// collisions per particle, theta, a20, a02 and a11 agree with the homogeneous gas's, taken between
// its rows at the box row's collisions (linear), within 4 combined standard errors (8 replicas of
// 5000 grains each) plus 1e-3, above the error of the interpolation (both runs aim their rows at the
// same collision counts, so the box row lies within a step, a quarter collision per particle, of a
// homogeneous row, over which theta changes by at most 0.005 here, and linearly to 1e-4).
TEST(BoxCli, SmallBoxCoolsAsTheHomogeneousGas) {
    const std::string constant = box_case(5000, 8, 40.0);
    const std::string coulomb = replaced(constant, "model = \"constant\"\nalpha = 0.9\nbeta = 0.4",
                                         "model = \"coulomb\"\nalpha = 0.9\nbeta0 = 0.4\nfriction = 0.15");
    const auto shipped = [](const char* name, const std::vector<std::pair<std::string, std::string>>& edits) {
        std::string c = test::read_file(fs::path(ROUGHGAS_SOURCE_DIR) / "cases" / name);
        for (const auto& [from, to] : edits) {
            if (c.find(from) == std::string::npos) // the shipped case as it is would run for hours
                throw std::runtime_error(std::string(name) + " has no '" + from + "'");
            c = replaced(c, from, to);
        }
        // lambda = 1/(sqrt(2) pi n sigma^2) = 0.5627 m at n = 1000 m^-3, sigma = 0.02 m.
        return c + "\n[domain]\nsize = [2.5, 2.5, 2.5]\ncells = [5, 5, 5]\n";
    };
    const std::string ice = shipped("hcs_viscoelastic_ice.toml", {{"particles = 50000", "particles = 5000"},
                                                                  {"replicas = 1", "replicas = 8"},
                                                                  {"end = 1000.0", "end = 40.0"},
                                                                  {"beta = -1.0 ", "beta = 0.4 "}});
    const test::ScratchDir tables;
    const std::string brilliantov =
        shipped("hcs_brilliantov.toml", {{"particles = 50000", "particles = 5000"},
                                         {"replicas = 1", "replicas = 8"},
                                         {"end = 60.0", "end = 40.0"},
                                         {"tolerance = 1e-12", "tolerance = 1e-6"},
                                         {"cache_file = \"\"", "cache_file = " + q(tables.path() / "ice.tables")}});
    for (const auto& [name, c] : {std::pair{"constant", constant}, std::pair{"coulomb", coulomb},
                                  std::pair{"viscoelastic", ice}, std::pair{"brilliantov", brilliantov}}) {
        const test::ScratchDir dir;
        const fs::path box = dir.write("box.toml", c);
        const fs::path hom = dir.write("hom.toml", c.substr(0, c.find("[domain]")));
        ASSERT_EQ(test::run_roughgas("run " + q(hom) + " --quiet --out " + q(dir / "hom"), dir).status, 0) << name;
        const test::CommandResult rb = test::run_roughgas("run " + q(box) + " --quiet --out " + q(dir / "box"), dir);
        ASSERT_EQ(rb.status, 0) << name << rb.err;
        const auto b = test::read_csv(dir / "box" / "moments.csv");
        const auto h = test::read_csv(dir / "hom" / "moments.csv");
        const std::vector<double>&sb = b.at("coll_per_particle"), &sh = h.at("coll_per_particle");
        EXPECT_NEAR(sb.back(), 40.0, 0.25) << name;
        for (const double target : {5.0, 10.0, 20.0, 40.0}) {
            std::size_t r = 0; // the box's row nearest the target
            for (std::size_t k = 1; k < sb.size(); ++k)
                if (std::abs(sb[k] - target) < std::abs(sb[r] - target))
                    r = k;
            std::size_t k = 1; // the homogeneous rows k - 1, k around the box row
            while (k + 1 < sh.size() && sh[k] < sb[r])
                ++k;
            const double w = std::clamp((sb[r] - sh[k - 1]) / (sh[k] - sh[k - 1]), 0.0, 1.0);
            for (const char* col : {"theta", "a20", "a02", "a11"}) {
                const std::vector<double>&x = b.at(col), &y = h.at(col);
                const std::vector<double>&xe = b.at(std::string(col) + "_err"), &ye = h.at(std::string(col) + "_err");
                const double expected = (1 - w) * y[k - 1] + w * y[k];
                const double se = std::hypot(xe[r], std::max(ye[k - 1], ye[k]));
                EXPECT_NEAR(x[r], expected, 4 * se + 1e-3) << name << " " << col << " at " << sb[r];
            }
        }
    }
}

// run.save_state and initial.from: a homogeneous cooling run leaves its replicas' grains in
// DIR/state; a box started from them has, at t = 0, replica 0's last temperatures and cumulants (the
// same grains: equal to round-off), at uniform positions; a box started from a box of the same size
// takes the positions too (the box's last row again). Refused before any work (exit 2, nothing
// written): a directory without state files, other species or grain counts, a density wave on
// positions taken over, the Maxwell kernel, an output directory holding a state without --force,
// and the state's own directory as the output directory even with --force. (A homogeneous run from
// a saved state: tests/io/initial_state_cli_test.cpp.)
TEST(BoxCli, StartsFromTheSavedStateOfAnEarlierRun) {
    const test::ScratchDir dir;
    const std::string c = box_case(3000, 1, 10.0);
    const std::string saving = replaced(c, "seed = 4", "seed = 4\nsave_state = true");
    const fs::path hom = dir.write("hom.toml", saving.substr(0, saving.find("[domain]")));
    ASSERT_EQ(test::run_roughgas("run " + q(hom) + " --quiet --out " + q(dir / "hom"), dir).status, 0);
    ASSERT_TRUE(fs::exists(dir / "hom" / "state" / "replica_0.bin"));
    const std::string from_hom = c + "\n[initial]\nfrom = " + q(dir / "hom") + "\n";
    const fs::path box = dir.write("box.toml", replaced(from_hom, "seed = 4", "seed = 4\nsave_state = true"));
    const test::CommandResult r = test::run_roughgas("run " + q(box) + " --out " + q(dir / "box"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("at uniform random positions"), std::string::npos) << r.err;
    const auto h = test::read_csv(dir / "hom" / "moments.csv");
    const auto b = test::read_csv(dir / "box" / "moments.csv");
    for (const char* col : {"T_tr", "T_rot", "theta", "a20", "a02", "a11"})
        EXPECT_NEAR(b.at(col).front() / h.at(col).back(), 1.0, 1e-9) << col;
    EXPECT_LT(b.at("T_tr").back(), 0.5 * b.at("T_tr").front()); // and it cools on

    const fs::path again = dir.write("again.toml", c + "\n[initial]\nfrom = " + q(dir / "box") + "\n");
    const test::CommandResult r2 = test::run_roughgas("run " + q(again) + " --out " + q(dir / "again"), dir);
    ASSERT_EQ(r2.status, 0) << r2.err;
    EXPECT_NE(r2.err.find("with their positions"), std::string::npos) << r2.err;
    const auto a = test::read_csv(dir / "again" / "moments.csv");
    for (const char* col : {"T_tr", "theta", "a20"})
        EXPECT_NEAR(a.at(col).front() / b.at(col).back(), 1.0, 1e-9) << col;

    const struct {
        std::string text, key, says;
    } bad[] = {
        {c + "\n[initial]\nfrom = " + q(dir / "nowhere") + "\n", "initial.from", "no "},
        {replaced(from_hom, "particles = 3000", "particles = 3001"), "initial.from", "3000 grains"},
        {c + "\n[initial]\nmode = \"density\"\nfrom = " + q(dir / "box") + "\n", "initial.mode",
         "needs fresh positions"},
        {replaced(from_hom, "seed = 4", "seed = 4\nkernel = \"maxwell\""), "initial.from",
         "run.kernel = \"maxwell\""},
    };
    for (const auto& x : bad) {
        const fs::path f = dir.write("bad.toml", x.text);
        const test::CommandResult e = test::run_roughgas("run " + q(f) + " --out " + q(dir / "out"), dir);
        EXPECT_EQ(e.status, 2) << x.key << "\n" << e.err;
        EXPECT_NE(e.err.find(x.key), std::string::npos) << e.err;
        EXPECT_NE(e.err.find(x.says), std::string::npos) << e.err;
        EXPECT_FALSE(fs::exists(dir / "out"));
        const test::CommandResult k = test::run_roughgas("check " + q(f), dir); // `check` refuses it too
        EXPECT_EQ(k.status, 2) << x.key << "\n" << k.err;
        EXPECT_NE(k.err.find(x.says), std::string::npos) << k.err;
    }
    const test::CommandResult e = test::run_roughgas("run " + q(box) + " --out " + q(dir / "box"), dir);
    EXPECT_EQ(e.status, 2);
    EXPECT_NE(e.err.find("state exists (use --force"), std::string::npos) << e.err;
    // A run may not replace the state it starts from, even with --force.
    const test::CommandResult o = test::run_roughgas("run " + q(again) + " --force --out " + q(dir / "box"), dir);
    EXPECT_EQ(o.status, 2);
    EXPECT_NE(o.err.find("is the output directory"), std::string::npos) << o.err;
    EXPECT_TRUE(fs::exists(dir / "box" / "state" / "replica_0.bin"));
}

// A cooling run from a saved state reaches T_tr/m = 1e-300 sooner than one from the species'
// temperatures: it is refused from the state's own temperatures (replica 0's), before any work. A box
// at alpha = 0.5 saved after 100 collisions per particle has about 100 fewer left than a fresh start
// (within the Maxwellian cooling rate's few per cent of its 30 e-foldings: 10 collisions); a run.end
// between the two reaches is refused from the state, accepted from a fresh start.
TEST(BoxCli, ACoolingRunFromASavedStateIsRefusedPastTheStatesReach) {
    const test::ScratchDir dir;
    const std::string c = replaced(box_case(3000, 1, 100.0), "alpha = 0.9", "alpha = 0.5");
    const fs::path aged = dir.write("aged.toml", replaced(c, "seed = 4", "seed = 4\nsave_state = true"));
    ASSERT_EQ(test::run_roughgas("run " + q(aged) + " --quiet --out " + q(dir / "aged"), dir).status, 0);
    const fs::path fresh = dir.write("fresh.toml", c);
    const fs::path from = dir.write("from.toml", c + "\n[initial]\nfrom = " + q(dir / "aged") + "\n");
    const auto reach_of = [&](const fs::path& f) {
        const test::CommandResult r = test::run_roughgas("check " + q(f) + " --set run.end=1e6", dir);
        EXPECT_EQ(r.status, 2) << r.err;
        EXPECT_NE(r.err.find("run.end = 1000000"), std::string::npos) << r.err;
        const std::size_t at = r.err.find("(run.end < ");
        return at == std::string::npos ? 0.0 : std::stod(r.err.substr(at + 11));
    };
    const double fresh_reach = reach_of(fresh), state_reach = reach_of(from);
    EXPECT_NEAR(fresh_reach - state_reach, 100.0, 10.0) << fresh_reach << " " << state_reach;
    const std::string between = " --set run.end=" + std::to_string(state_reach + 20);
    EXPECT_EQ(test::run_roughgas("check " + q(fresh) + between, dir).status, 0);
    const test::CommandResult refused =
        test::run_roughgas("run " + q(from) + between + " --out " + q(dir / "out"), dir);
    EXPECT_EQ(refused.status, 2) << refused.err;
    EXPECT_NE(refused.err.find("the state of initial.from"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find("reaches T_tr/m = 1e-300 (velocities squared underflow)"), std::string::npos)
        << refused.err;
    EXPECT_FALSE(fs::exists(dir / "out"));
    EXPECT_EQ(test::run_roughgas("check " + q(from) + " --set run.end=" + std::to_string(state_reach - 20), dir)
                  .status,
              0);
}

} // namespace
} // namespace roughgas
