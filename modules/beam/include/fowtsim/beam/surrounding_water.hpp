#pragma once
// Water (a uniform current, and the input's waves) around a submerged line: buoyancy and Morison's
// equation on the relative velocity (Morison et al. 1950), the loads of seed 000 §3.5.3's riser.
// Data of the discretised model (BeamModel::water); src/water_terms.hpp has the per-volume terms.
//
// Per finite volume of length Δs whose node lies below the still-water level (a volume is wet or
// dry as its node is; the line is meant to be fully submerged, as the seed's riser):
//   - buoyancy −ρ_w A_e Δs g, a dead load with g the gravity of the beam's input (Archimedes on the
//     outer section A_e = π D²/4). The external pressure's face term p_e A_e (a tension along the
//     axis) is not added: with buoyancy as a body force the lateral equations are exact and the
//     sections' axial resultant is the effective tension plus p_i A_i (Sparks, Fundamentals of
//     Marine Riser Mechanics, ch. 3); the axial strain it leaves out is p_e A_e/(EA), 7e-5 for the
//     seed's riser at 300 m.
//   - added mass C_a ρ_w A_e Δs (I − t tᵀ) on the volume's translation, C_a = C_m − 1; in waves
//     (BeamInput::water_acceleration_m_s2, a_w per node) the load C_m ρ_w A_e Δs (I − t tᵀ) a_w,
//     Froude–Krylov plus the added mass's share;
//   - drag ½ ρ_w C_d D Δs |v_n| v_n on the velocity of the water relative to the line, normal to
//     its axis t: v_n = (I − t tᵀ)(U_c + v_w − u̇), v_w the waves' particle velocity
//     (BeamInput::water_velocity_m_s). It enters each step linearised about the velocity at
//     the step's start (a damping tangent and a load), so the step stays one linear solve.
// The water's motion is given in the beam's frame f: use it with a frame that does not rotate or
// accelerate (the pipe scene checks this; the floating turbine's riser is resolved in g).
#include "fowtsim/core/types.hpp"

namespace fowtsim::beam {

struct SurroundingWater {
  double density_kg_m3 = 1025.0;        // ρ_w [kg/m³]
  double outer_diameter_m = 0.0;        // D: hydrodynamic diameter [m]
  double added_mass_coefficient = 0.0;  // C_a = C_m − 1 [-]
  double drag_coefficient = 0.0;        // C_d, normal flow [-]
  double surface_z_m = 0.0;             // still-water level, f's z [m]: volumes with the node above are dry
  Vec3 current_m_s = Vec3::Zero();      // uniform current, in f [m/s]
};

}  // namespace fowtsim::beam
