#pragma once
// The translational temperature about the local flow of a box run, from its collision cells' sums.
//
// moments.csv's T_tr is (1/3) <m |v - u|^2> about the box's mean velocity u: a wave, a shear flow
// or the vortices of a cooling box add their flow energy to it. T_th takes each grain's velocity
// about its own cell's flow U_c = (sum_j m_j v_j)/M_c instead, M_c the cell's mass:
//   T_th = sum_c sum_{j in c} m_j |v_j - U_c|^2 / (3 sum_c (N_c - 1)),   cells with N_c >= 1.
// The N_c - 1 and not N_c: for independent grains at temperature T, E sum_j m_j |v_j - U_c|^2 =
// 3 N_c T - M_c E|U_c - u_c|^2 = 3 (N_c - 1) T (the cell's mean carries one grain's worth of
// the thermal motion, variance T/M_c per component), so T_th is unbiased at any number of grains
// per cell, where dividing by N_c would read a cell of N_c grains 1/N_c cold. Exactly, with C the
// cells holding a grain and u the box's mean velocity (T_tr over N grains),
//   3 N T_tr = 3 (N - C) T_th + sum_c M_c |U_c - u|^2,
// so T_tr - T_th is the cells' flow share, sum_c M_c |U_c - u|^2 / (3 N), less the thermal noise
// their means carry, C T_th / N (tests/observables/thermal_temperature_test.cpp checks both).
// A flow varying within a cell stays in T_th (a shear rate a across cells of edge h along the
// gradient adds m a^2 h^2/36): it is the flow the cells do not resolve.
#include <cstddef>
#include <span>

namespace roughgas {

// `cell_sums`: per (cell, species), cells slowest, `fields` numbers each: the count of the grains,
// the sums of v_x, v_y, v_z and of |v|^2 (SpatialEngine::cell_sums()); `masses`: per species.
// NaN when no cell holds two grains.
double thermal_temperature(std::span<const double> cell_sums, std::size_t fields, std::span<const double> masses);

} // namespace roughgas
