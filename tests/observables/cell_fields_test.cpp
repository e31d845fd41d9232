// The fields of a box's cells (observables/cell_fields.hpp): the cells of a slab add up to the
// slab's profile (grains, flow, temperatures, mean spin, kinetic pressure tensor and heat flux,
// through the exact identities of moments about two means), the cells run x fastest, and an
// empty cell has n = 0 and NaN fields.
#include "roughgas/observables/cell_fields.hpp"
#include "roughgas/observables/profiles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>

namespace roughgas {
namespace {

std::vector<SpeciesBlock> one_species(std::size_t n, double m) {
    std::vector<SpeciesBlock> b(1);
    b[0].grain.mass = m;
    b[0].grain.radius = 0.5;
    b[0].grain.inertia = 0.4;
    b[0].count = n;
    return b;
}

const std::vector<FieldQuantity> all = {FieldQuantity::n,     FieldQuantity::u,     FieldQuantity::T_tr,
                                        FieldQuantity::T_rot, FieldQuantity::theta, FieldQuantity::omega,
                                        FieldQuantity::P,     FieldQuantity::q};

// Component c of a quantity's value in cell (i, j, l).
double at(const CellFields& f, FieldQuantity q, int i, int j, int l, int c = 0) {
    for (std::size_t k = 0; k < f.quantities.size(); ++k)
        if (f.quantities[k] == q) {
            const auto cell = static_cast<std::size_t>(i + f.cells[0] * (j + f.cells[1] * l));
            return f.values[k][cell * static_cast<std::size_t>(field_components(q)) + static_cast<std::size_t>(c)];
        }
    ADD_FAILURE() << "no such quantity";
    return 0;
}
Vec3 vec(const CellFields& f, FieldQuantity q, int i, int j, int l) {
    return {at(f, q, i, j, l, 0), at(f, q, i, j, l, 1), at(f, q, i, j, l, 2)};
}

TEST(CellFields, CellsOfASlabAddUpToItsProfile) {
    // Walls along y, gravity, a drift and a half flight that carries grains across cells and walls.
    const std::array<int, 3> cells{4, 3, 5};
    const std::array<double, 3> box{8.0, 6.0, 5.0};
    const double m = 1.7;
    const std::vector<SpeciesBlock> species = one_species(1500, m);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> normal(0, 1);
    std::vector<Vec3> x, v, w;
    for (std::size_t i = 0; i < 1500; ++i) {
        x.push_back({u(rng) * box[0], u(rng) * box[1], u(rng) * box[2]});
        v.push_back({normal(rng) + 0.4 * std::sin(x.back().z), normal(rng), normal(rng) - 0.2 * x.back().x});
        w.push_back({normal(rng), normal(rng) + 0.3, normal(rng)});
    }
    ProfileGeometry p;
    p.axis = 1;
    p.bins = cells[1];
    p.length = box[1];
    p.box = box;
    p.periodic = false;
    p.weight = 3.0;
    p.bin_volume = box[0] * box[1] * box[2] / cells[1];
    p.half_flight = 0.3;
    p.gravity = {0.1, -0.5, 0.2};
    const std::vector<double> profile =
        compute_profiles(p, x, v, w, species, std::vector<Virial>(static_cast<std::size_t>(cells[1])), 1.0);
    const CellFields f = compute_cell_fields(p, cells, {false, true, false}, all, x, v, w, species);
    ASSERT_EQ(f.values.size(), all.size());
    const double V_c = box[0] * box[1] * box[2] / (cells[0] * cells[1] * cells[2]);
    for (int j = 0; j < cells[1]; ++j) {
        const double* slab = profile.data() + static_cast<std::size_t>(j) * profile_field_count;
        const auto field = [&](const std::string& name) {
            for (std::size_t k = 0; k < profile_field_count; ++k)
                if (name == profile_fields[k])
                    return slab[k];
            ADD_FAILURE() << name;
            return 0.0;
        };
        const Vec3 U{field("u_x"), field("u_y"), field("u_z")};
        // Sums over the slab's cells, each cell's moments moved from its flow u_c to the slab's U
        // (d = u_c - U; c the velocities about u_c, sum m c = 0 in a cell):
        //   sum m |c + d|^2 = sum m c^2 + M_c d^2,   sum m (c + d)(c + d) = sum m c c + M_c d d,
        //   sum (m |c + d|^2 / 2 + e_rot)(c + d) = q_c V_c / F + (E_c + E_rot,c) d + (sum m c c) . d + M_c d^2 d / 2.
        double N = 0, kinetic = 0, rot = 0;
        Vec3 flow{}, spin{}, heat{};
        double P[3][3] = {};
        for (int l = 0; l < cells[2]; ++l)
            for (int i = 0; i < cells[0]; ++i) {
                const double N_c = at(f, FieldQuantity::n, i, j, l) * V_c / p.weight;
                if (N_c == 0)
                    continue;
                const Vec3 d = vec(f, FieldQuantity::u, i, j, l) - U;
                const double T_c = at(f, FieldQuantity::T_tr, i, j, l), Tr_c = at(f, FieldQuantity::T_rot, i, j, l);
                EXPECT_NEAR(at(f, FieldQuantity::theta, i, j, l), Tr_c / T_c, 1e-15 * Tr_c / T_c);
                N += N_c;
                flow += N_c * vec(f, FieldQuantity::u, i, j, l);
                spin += N_c * vec(f, FieldQuantity::omega, i, j, l);
                kinetic += 3 * N_c * T_c + m * N_c * norm2(d);
                rot += 3 * N_c * Tr_c;
                // Tensor6 order xx, xy, xz, yy, yz, zz; sum m c c = P_c V_c / F.
                const int index[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
                double S[3][3];
                const double dd[3] = {d.x, d.y, d.z};
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b) {
                        S[a][b] = at(f, FieldQuantity::P, i, j, l, index[a][b]) * V_c / p.weight;
                        P[a][b] += S[a][b] + m * N_c * dd[a] * dd[b];
                    }
                const Vec3 Sd{S[0][0] * d.x + S[0][1] * d.y + S[0][2] * d.z, S[1][0] * d.x + S[1][1] * d.y + S[1][2] * d.z,
                              S[2][0] * d.x + S[2][1] * d.y + S[2][2] * d.z};
                heat += vec(f, FieldQuantity::q, i, j, l) * (V_c / p.weight) + (1.5 * N_c * (T_c + Tr_c)) * d + Sd +
                        (0.5 * m * N_c * norm2(d)) * d;
            }
        const double tol = 1e-12;
        EXPECT_NEAR(N * p.weight / p.bin_volume, field("n"), tol * field("n"));
        for (const auto& [sum, name] : {std::pair{flow.x, "u_x"}, {flow.y, "u_y"}, {flow.z, "u_z"}, {spin.x, "omega_x"},
                                         {spin.y, "omega_y"}, {spin.z, "omega_z"}})
            EXPECT_NEAR(sum / N, field(name), tol) << name;
        EXPECT_NEAR(kinetic / (3 * N), field("T_tr"), tol * field("T_tr"));
        EXPECT_NEAR(rot / (3 * N), field("T_rot"), tol * field("T_rot"));
        const double F_V = p.weight / p.bin_volume;
        const char* names[3][3] = {{"P_xx", "P_xy", "P_xz"}, {"P_xy", "P_yy", "P_yz"}, {"P_xz", "P_yz", "P_zz"}};
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                EXPECT_NEAR(F_V * P[a][b], field(names[a][b]), tol * field("P_xx")) << names[a][b];
        for (const auto& [sum, name] : {std::pair{heat.x, "q_x"}, {heat.y, "q_y"}, {heat.z, "q_z"}})
            EXPECT_NEAR(F_V * sum, field(name), tol * std::abs(field("P_xx"))) << name;
    }
}

// A row that writes fields takes its profiles from the cells' sums: the same profiles to round-off,
// the same cell fields exactly, along a walled and a periodic axis, with and without spins in the
// heat flux, with empty cells in between; refused where the profile bins are not layers of cells
// or walls stand across another axis.
TEST(CellFields, ProfilesFromTheCellsAgreeWithTheirOwnPass) {
    const std::array<int, 3> cells{5, 3, 4};
    const std::array<double, 3> box{10.0, 6.0, 4.0};
    const std::size_t n = 400; // about 7 grains per cell: some cells are empty
    const std::vector<SpeciesBlock> species = one_species(n, 1.3);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> normal(0, 1);
    std::vector<Vec3> x, v, w;
    for (std::size_t i = 0; i < n; ++i) {
        x.push_back({u(rng) * box[0], u(rng) * box[1], u(rng) * box[2]});
        // A flow ten times the thermal speed across the box: the identities must not lose it.
        v.push_back({normal(rng) + 10 * std::sin(x.back().y), normal(rng) - 3 * x.back().x, normal(rng)});
        w.push_back({normal(rng), normal(rng) + 0.3, normal(rng)});
    }
    CellFieldsScratch scratch;
    for (const int axis : {0, 1})
        for (const bool rotation : {true, false}) {
            ProfileGeometry p;
            p.axis = axis;
            p.bins = cells[static_cast<std::size_t>(axis)];
            p.length = box[static_cast<std::size_t>(axis)];
            p.box = box;
            p.periodic = axis == 0;
            p.rotation = rotation;
            p.weight = 2.0;
            p.bin_volume = box[0] * box[1] * box[2] / p.bins;
            p.half_flight = 0.2;
            p.gravity = {0.0, -0.4, 0.1};
            const std::array<bool, 3> walled{false, axis == 1, false};
            std::vector<Virial> virial(static_cast<std::size_t>(p.bins));
            for (std::size_t b = 0; b < virial.size(); ++b)
                virial[b][0] = static_cast<double>(b) + 1;
            const std::vector<double> own = compute_profiles(p, x, v, w, species, virial, 0.5);
            CellFields fused;
            const std::vector<double> from_cells = compute_cell_fields_and_profiles(
                p, cells, walled, all, x, v, w, species, virial, 0.5, fused, scratch); // reused from the last pass
            const CellFields alone = compute_cell_fields(p, cells, walled, all, x, v, w, species);
            ASSERT_EQ(fused.values.size(), alone.values.size());
            for (std::size_t k = 0; k < alone.values.size(); ++k) { // bit for bit, NaN included
                ASSERT_EQ(fused.values[k].size(), alone.values[k].size());
                EXPECT_EQ(std::memcmp(fused.values[k].data(), alone.values[k].data(),
                                      alone.values[k].size() * sizeof(double)),
                          0);
            }
            ASSERT_EQ(from_cells.size(), own.size());
            for (std::size_t b = 0; b < static_cast<std::size_t>(p.bins); ++b) {
                const double* o = own.data() + b * profile_field_count;
                const double* c = from_cells.data() + b * profile_field_count;
                // The shifts between cell and layer flows reach ten thermal speeds: round-off grows with
                // their square, 1e-13 relative; a wrong identity errs by order one.
                const double pressure = o[7] + o[8] + o[9]; // P_xx + P_yy + P_zz
                for (std::size_t k = 0; k < profile_field_count; ++k) {
                    const std::string name = profile_fields[k];
                    const double tol = name.starts_with("P_")   ? 1e-11 * pressure
                                       : name.starts_with("q_") ? 1e-10 * pressure
                                                                : 1e-12 * std::max(1.0, std::abs(o[k]));
                    EXPECT_NEAR(c[k], o[k], tol) << "axis " << axis << " rotation " << rotation << " bin " << b << " "
                                                 << name;
                }
            }
        }
    ProfileGeometry p;
    p.axis = 2;
    p.bins = 3; // not a layer of cells
    p.length = box[2];
    p.box = box;
    CellFields out;
    EXPECT_THROW(compute_cell_fields_and_profiles(p, cells, {false, false, false}, all, x, v, w, species,
                                                  std::vector<Virial>(3), 0.5, out, scratch),
                 std::invalid_argument);
    p.bins = cells[2];
    EXPECT_THROW(compute_cell_fields_and_profiles(p, cells, {false, true, false}, all, x, v, w, species, // walls
                                                  std::vector<Virial>(4), 0.5, out, scratch),            // along y
                 std::invalid_argument);
}

TEST(CellFields, CellsRunXFastestAndEmptyCellsHaveNoFields) {
    const std::vector<SpeciesBlock> species = one_species(1, 2.0);
    const std::array<int, 3> cells{3, 4, 2};
    FlightSampling s;
    s.box = {3.0, 8.0, 4.0};
    s.weight = 5.0;
    const std::vector<Vec3> x = {{2.5, 5.5, 3.1}}, v = {{1, -2, 0.5}}, w = {{0, 0, 3}}; // cell (2, 2, 1)
    const CellFields f = compute_cell_fields(s, cells, {false, false, false}, all, x, v, w, species);
    for (int l = 0; l < 2; ++l)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 3; ++i) {
                const bool here = i == 2 && j == 2 && l == 1;
                EXPECT_EQ(at(f, FieldQuantity::n, i, j, l), here ? 5.0 / 4.0 : 0.0);
                EXPECT_EQ(std::isnan(at(f, FieldQuantity::u, i, j, l, 1)), !here);
                EXPECT_EQ(std::isnan(at(f, FieldQuantity::P, i, j, l, 5)), !here);
            }
    EXPECT_EQ(at(f, FieldQuantity::u, 2, 2, 1, 1), -2.0);
    EXPECT_EQ(at(f, FieldQuantity::omega, 2, 2, 1, 2), 3.0);
    EXPECT_EQ(at(f, FieldQuantity::T_tr, 2, 2, 1), 0.0); // one grain: no spread about its own velocity
    // Only the quantities asked for, in that order.
    const CellFields g = compute_cell_fields(s, cells, {false, false, false}, {FieldQuantity::P, FieldQuantity::n},
                                             x, v, w, species);
    ASSERT_EQ(g.values.size(), 2u);
    EXPECT_EQ(g.values[0].size(), 6u * 24u);
    EXPECT_EQ(g.values[1].size(), 24u);
}

TEST(CellFields, AScratchKeptFromSnapshotToSnapshotLeavesNothingBehind) {
    // A full box, then one grain in it: every other cell must come out empty again, and the grain's
    // own cell must hold it alone, bit for bit as from fresh arrays.
    const std::array<int, 3> cells{3, 4, 2};
    FlightSampling s;
    s.box = {3.0, 8.0, 4.0};
    s.weight = 5.0;
    s.rotation = true;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> normal(0, 1);
    std::vector<Vec3> x, v, w;
    for (int i = 0; i < 400; ++i) {
        x.push_back({u(rng) * s.box[0], u(rng) * s.box[1], u(rng) * s.box[2]});
        v.push_back({normal(rng), normal(rng), normal(rng)});
        w.push_back({normal(rng), normal(rng), normal(rng)});
    }
    CellFieldsScratch scratch;
    CellFields full, single;
    compute_cell_fields(s, cells, {false, false, false}, all, x, v, w, one_species(400, 2.0), full, scratch);
    EXPECT_EQ(at(full, FieldQuantity::n, 0, 0, 0) > 0, true);
    const std::vector<Vec3> x1 = {{2.5, 5.5, 3.1}}, v1 = {{1, -2, 0.5}}, w1 = {{0, 0, 3}}; // cell (2, 2, 1)
    compute_cell_fields(s, cells, {false, false, false}, all, x1, v1, w1, one_species(1, 2.0), single, scratch);
    const CellFields fresh = compute_cell_fields(s, cells, {false, false, false}, all, x1, v1, w1, one_species(1, 2.0));
    ASSERT_EQ(single.values.size(), fresh.values.size());
    for (std::size_t k = 0; k < fresh.values.size(); ++k) { // bit for bit, NaN included
        ASSERT_EQ(single.values[k].size(), fresh.values[k].size());
        EXPECT_EQ(std::memcmp(single.values[k].data(), fresh.values[k].data(), fresh.values[k].size() * sizeof(double)),
                  0)
            << "quantity " << k;
    }
    EXPECT_EQ(at(single, FieldQuantity::n, 0, 0, 0), 0.0);
    EXPECT_EQ(at(single, FieldQuantity::T_tr, 2, 2, 1), 0.0);
}

} // namespace
} // namespace roughgas
