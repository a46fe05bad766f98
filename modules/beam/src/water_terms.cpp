#include "water_terms.hpp"

#include <cmath>
#include <numbers>

namespace fowtsim::beam {

void add_water_node_terms(const BeamModel& model, const BeamInput& input, const BeamState& state, int i, bool inertia,
                          Mat6& mass, Mat6& damping, Vec6& rhs) {
  const SurroundingWater& water = *model.water;
  if (state.position_m[i].z() > water.surface_z_m) return;  // a dry volume
  const double ds = model.nodes[i].segment_length_m;
  const double d = water.outer_diameter_m;
  const double displaced = 0.25 * std::numbers::pi * d * d * ds * water.density_kg_m3;  // ρ_w A_e Δs [kg]
  rhs.head<3>() -= displaced * input.frame.gravity_m_s2;  // Archimedes

  const Vec3 t = state.orientation[i].col(2);
  const Mat3 normal = Mat3::Identity() - t * t.transpose();  // P = I − t tᵀ
  // Drag F(u̇) = k |v_n| v_n, v_n = P (U_c − u̇), linearised about u̇_0 (the base velocity):
  // F ≈ F_0 + J (u̇ − u̇_0), J = −k (|v_n| I + v_n v_nᵀ/|v_n|) P. J goes to the damping as −J and
  // F_0 − J u̇_0 to the load; a static solve (no velocity) keeps F_0, the drag of the current.
  const double k = 0.5 * water.density_kg_m3 * water.drag_coefficient * d * ds;
  const Vec3 u0 = state.velocity[i].head<3>();
  const Vec3 flow = input.water_velocity_m_s.empty() ? water.current_m_s : Vec3(water.current_m_s + input.water_velocity_m_s[i]);
  const Vec3 vn = normal * (flow - u0);
  const double speed = vn.norm();
  rhs.head<3>() += k * speed * vn;
  // The accelerating sea (Morison's inertia term): Froude–Krylov ρ A_e Δs a_w and the added mass's
  // share C_a ρ A_e Δs a_w, normal to the axis; a load, so it acts in a static solve too.
  if (!input.water_acceleration_m_s2.empty())
    rhs.head<3>() += (1.0 + water.added_mass_coefficient) * displaced * (normal * input.water_acceleration_m_s2[i]);
  if (!inertia) return;
  mass.block<3, 3>(0, 0) += water.added_mass_coefficient * displaced * normal;
  if (speed == 0.0) return;
  const Mat3 tangent = k * (speed * Mat3::Identity() + vn * vn.transpose() / speed) * normal;  // −J
  damping.block<3, 3>(0, 0) += tangent;
  rhs.head<3>() += tangent * u0;
}

}  // namespace fowtsim::beam
