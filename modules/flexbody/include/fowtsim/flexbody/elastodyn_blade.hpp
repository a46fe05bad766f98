#pragma once
// A blade as ElastoDyn describes it (its individual blade input file, plus HubRad and TipRad of the
// main file): distributed properties at stations along the flexible span, linear in between, and
// three mode-shape polynomials — two flapwise, one edgewise — each bending about one principal
// axis of the (structurally twisted) section. inputs/nrel5mw/blade_elastodyn.yaml holds the NREL
// 5MW blade; blade_deck.hpp reads it.
#include <array>
#include <vector>

namespace fowtsim::flexbody {

struct ElastoDynBlade {
  double hub_radius = 0.0;  // HubRad: rotor apex to blade root along the blade axis [m]
  double tip_radius = 0.0;  // TipRad: rotor apex to blade tip [m]

  // Stations, root to tip (BlFract 0 … 1).
  std::vector<double> span_fraction;   // BlFract: distance from the root / flexible length [-]
  std::vector<double> twist_deg;       // StrcTwst: structural twist [deg] (ElastoDyn's sign, rr_blade.hpp)
  std::vector<double> mass_density;    // BMassDen [kg/m], before mass_factor
  std::vector<double> flap_stiffness;  // FlpStff: EI about the principal flap axis [N m^2], before factor
  std::vector<double> edge_stiffness;  // EdgStff: EI about the principal edge axis [N m^2], before factor

  // φ = Σ_{j=2..6} c_j (r/L)^j, r from the root: coefficients c2..c6 (BldFl1Sh, BldFl2Sh, BldEdgSh).
  std::array<double, 5> flap1_shape{}, flap2_shape{}, edge1_shape{};

  std::array<double, 2> flap_damping_percent{};  // BldFlDmp(1..2): % of critical [%]
  double edge_damping_percent = 0.0;             // BldEdDmp(1) [%]
  std::array<double, 2> flap_stiffness_tuners{1.0, 1.0};  // FlStTunr(1..2): flap modal stiffness factors [-]
  double mass_factor = 1.0;            // AdjBlMs: multiplies BMassDen [-]
  double flap_stiffness_factor = 1.0;  // AdjFlSt: multiplies FlpStff [-]
  double edge_stiffness_factor = 1.0;  // AdjEdSt: multiplies EdgStff [-]

  double length() const { return tip_radius - hub_radius; }  // flexible length L [m]
};

// Throws InputError naming the field unless: 0 <= hub_radius < tip_radius; >= 2 stations, all
// columns the same length, BlFract from 0 to 1 strictly increasing; mass >= 0, stiffnesses > 0;
// factors and tuners > 0; damping >= 0. (The shape coefficients are checked where they are used:
// polynomial_shape, Σ c_j = 1 within 0.001.)
void validate(const ElastoDynBlade& blade);

}  // namespace fowtsim::flexbody
