#pragma once
// Aerodynamic drag on the tower (AeroDyn's TwrAero): each tower station (Params::tower) carries a
// load per unit length
//     f = ½ ρ C_d D |v⊥| v⊥,   v⊥ = (u − ẋ) − ((u − ẋ)·k) k,
// with u the undisturbed wind at the station, ẋ the station's velocity, k the unit tower axis, D
// and C_d the station's diameter and drag coefficient — the steady drag of a circular cylinder in
// the flow normal to its axis (Morison's drag term without the inertia term: air is light). The
// load is taken linear between stations and integrated exactly (the trapezoid rule), as the
// blades' loads are (aero.hpp); it is zero below the first and above the last station.
#include <span>

#include "fowtsim/aero/params.hpp"
#include "fowtsim/core/types.hpp"

namespace fowtsim::aero {

struct TowerDragLoad {
  Vec3 force_N = Vec3::Zero();      // resultant, g [N]
  Vec3 moment_N_m = Vec3::Zero();   // about the point asked for, g [N·m]
};

// Positions of the tower stations: tower_base_m + elevation · tower_axis (both in g), into `out`
// (one per station).
void tower_station_positions(const Params& params, const Vec3& tower_base_m, const Vec3& tower_axis,
                             std::span<Vec3> out);

// The drag resultant on the tower with stations at `position_m` moving at `velocity_m_s` in the
// wind `inflow_m_s` (one each per station, g), moment about `about_m`. Allocates nothing.
TowerDragLoad tower_drag(const Params& params, const Vec3& tower_axis, std::span<const Vec3> position_m,
                         std::span<const Vec3> velocity_m_s, std::span<const Vec3> inflow_m_s, const Vec3& about_m);

// The same drag as consistent nodal loads, one per station into `force_N` (g [N]), for stations
// moving at `velocity_m_s` in the wind `inflow_m_s` (wherever the caller places them): for f linear
// between stations a and b, h = z_b − z_a apart, F_a += h (2 f_a + f_b)/6 and F_b += h (f_a + 2 f_b)/6,
// the loads of a linear finite element. Their sum and, for stations on a straight line, their first
// moment Σ (x_i − c) × F_i equal tower_drag()'s exact integrals; applied at the stations of a bending
// tower they also give its modes the work of the distributed drag. Allocates nothing.
void tower_drag_nodal(const Params& params, const Vec3& tower_axis, std::span<const Vec3> velocity_m_s, std::span<const Vec3> inflow_m_s, std::span<Vec3> force_N);

}  // namespace fowtsim::aero
