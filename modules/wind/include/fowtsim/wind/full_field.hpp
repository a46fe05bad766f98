#pragma once
// A full-field (grid) wind: velocities on a y–z grid at equally spaced times, advected downwind
// by Taylor's frozen-turbulence hypothesis — the data of a TurbSim .bts file or of our generator.
// The data is core's WindGrid, which fowtsim::io reads from .bts files (this module does not use io).
//
// InflowWind's conventions, which we follow (sources: OpenFAST InflowWind_IO.f90, IfW_TurbSim_Init,
// OpenFAST v3.5+/v5; InflowWind User's Guide, Platt, Jonkman & Jonkman 2016, "Taylor's frozen
// turbulence hypothesis ... using the mean wind speed as the advection speed"):
//   * a point at wind-frame x is evaluated at the shifted time t' = t + (X0 − x) / U_hub, where
//     U_hub is the file's hub mean speed; X0 = 0 for a periodic file (format id 8, "start at the
//     hub") and X0 = half the grid width for a non-periodic file (id 7, "start half the grid
//     width ahead of the turbine");
//   * a periodic file wraps with period nt·dt; a non-periodic file covers t' in [0, (nt−1)·dt];
//   * grid node (iy, iz) sits at y = −W/2 + iy·dy, z = z_bottom + iz·dz; bilinear in y–z, linear in
//     time; velocities are stored whole (mean included), not added after interpolation;
//   * tower points (at y = 0, z = z_bottom − k·dz, k = 0..n_tower−1; point 0 repeats the bottom
//     grid row at y = 0, checked on TurbSim's file) are used only below the grid (InflowWind:
//     InterpTower = false for TurbSim files): linear in z between them and linear to zero at the
//     ground z = 0, y ignored. This below-grid rule is ours, modelled on InflowWind's extrapolation
//     figure (docs FFWindExtrap--Tower.png), and not verified against InflowWind output.
// Measured: at the OC3 run's probe (0, 0, 90) m this reproduces OpenFAST v5's Wind1VelX/Y/Z to
// 8.4e-7 m/s over 0–60 s (tests/bts_reference_tests.cpp).
#include <cstddef>
#include <vector>

#include "fowtsim/core/types.hpp"
#include "fowtsim/core/wind_grid.hpp"

namespace fowtsim::wind {

// The grid (core/wind_grid.hpp) with the geometry InflowWind derives from it.
struct FullField : WindGrid {
  double half_width_m() const { return 0.5 * (ny - 1) * dy_m; }
  double top_m() const { return z_bottom_m + (nz - 1) * dz_m; }
  // Covered time: nt·dt periodic, (nt−1)·dt otherwise [s].
  double total_time_s() const { return periodic ? nt * dt_s : (nt - 1) * dt_s; }
  // X0 of the Taylor shift [m] (see above).
  double initial_x_m() const { return periodic ? 0.0 : half_width_m(); }
};

// Throws InputError (module "wind.full_field") if sizes, spacings or array lengths are inconsistent.
void validate(const FullField& field);

// Velocity [m/s] in the wind frame at wind-frame point p [m] and time t [s]. No allocation.
// Throws NumericalError (with t) outside the grid (and tower) or outside the covered time of a
// non-periodic field: InflowWind stops there too ("FF wind array boundaries violated").
Vec3 full_field_velocity(const FullField& field, const Vec3& p_wind_m, double time_s);

// True if full_field_velocity has data at p (wind-box coordinates): inside the grid's width and
// height, or below it down to z = 0 when the field has tower points.
bool covers(const FullField& field, const Vec3& p_wind_m);

}  // namespace fowtsim::wind
