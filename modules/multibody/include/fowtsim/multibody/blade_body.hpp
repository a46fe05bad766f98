#pragma once
// The Rayleigh–Ritz blades as flexible bodies of the chain (flexible_body.hpp, model.hpp
// RayleighRitzBlades): blade b turns with the hub from its root point, in its pitched root frame
// f_b, and bends with ElastoDyn's flap 1, flap 2 and edge 1 shapes. Its stations (the aerodynamic
// nodes and the tip) are where loads act and deflections are read. Everything in g.
#include "fowtsim/core/types.hpp"
#include "fowtsim/multibody/flexible_body.hpp"

namespace fowtsim::multibody {

// Blade b as a flexible body: O = its root, turning with the hub, frame f_b, modes from
// kBlade + b·kMaxBladeModes.
FlexibleBodyMotion blade_motion(const Model& model, const State& state, const ChainKinematics& chain, int blade);

// Station s of blade b, deflected: position, velocity, Jacobian and bias acceleration (g).
PointKinematics blade_station_point(const Model& model, const State& state, const ChainKinematics& chain, int blade,
                                    int station);

// Its position and velocity only (g).
PointMotion blade_station_motion(const Model& model, const State& state, const ChainKinematics& chain, int blade,
                                 int station);

// The section's small elastic rotation at station s of blade b, per unit of each mode: the slope
// turns the section about y_f by φ'_flap and about x_f by −φ'_edge (as the tower's top, in f) [1/m].
Vec3 blade_rotation_shape(const BladeStation& station, int mode);

// The deflected section frame at station s of blade b: T_g,f R_x(θ_x) R_y(θ_y) with
// (θ_x, θ_y) = Σ_j q_j (rotation shape)_j (g ← section).
Mat3 blade_section_orientation(const Model& model, const State& state, const ChainKinematics& chain, int blade,
                               int station);

// The elastic deflection Σ_j q_j φ_j at station s of blade b, in f [m].
Vec3 blade_deflection(const Model& model, const State& state, int blade, int station);

}  // namespace fowtsim::multibody
