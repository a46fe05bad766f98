#pragma once
// Parameters of a mooring system: the lines as physical objects, independent of the model that
// solves them (taut spring, quasi-static catenary, later a lumped-mass dynamic model). Each
// member maps one to one onto a key of the deck section
//
//   mooring:
//     model: catenary | taut
//     depth_m: 320
//     water_density_kg_m3: 1025
//     gravity_m_s2: 9.80665
//     delta_yaw_stiffness_N_m_rad: 9.834e7     # optional, default 0
//     solver: {tolerance: 1e-10, max_newton_iterations: 50, max_bisection_iterations: 200}  # optional
//     lines:
//       - {anchor_m: [853.87, 0, -320], fairlead_body_m: [5.2, 0, -70], unstretched_length_m: 902.2,
//          mass_per_length_kg_m: 77.7066, diameter_m: 0.09, ea_N: 384.243e6, seabed_friction: 0.001}
#include <cstddef>
#include <string_view>
#include <vector>

#include "fowtsim/core/types.hpp"
#include "fowtsim/mooring/catenary.hpp"

namespace fowtsim::mooring {

// Capacity of the fixed-size per-line arrays in State and Output (no heap use per step).
inline constexpr std::size_t kMaxLines = 32;

enum class LineModel {
  catenary,  // quasi-static elastic catenary with seabed contact and friction (MAP/FAST)
  taut,      // massless linear spring along the chord, no compression (seed 000 §4.4, §4.5.1)
};

// "catenary" or "taut" → LineModel; throws InputError naming the key `mooring.model` otherwise.
LineModel line_model_from_name(std::string_view name);
const char* line_model_name(LineModel model);

struct LineParams {
  Vec3 anchor_m = Vec3::Zero();         // anchor position, inertial frame g (DESIGN.md §3) [m]
  Vec3 fairlead_body_m = Vec3::Zero();  // fairlead relative to the platform reference point, body frame b [m]
  double unstretched_length_m = 0.0;    // L [m], > 0
  double mass_per_length_kg_m = 0.0;    // mass per unstretched length in air [kg/m]; > 0 for catenary, unused by taut
  double diameter_m = 0.0;              // volume-equivalent diameter for buoyancy [m], ≥ 0; unused by taut
  double ea_N = 0.0;                    // axial stiffness EA, tension per unit strain [N], > 0
  double seabed_friction = 0.0;         // seabed friction coefficient C_B [-], ≥ 0; catenary only
};

struct MooringParams {
  LineModel model = LineModel::catenary;  // how every line is solved
  double depth_m = 0.0;                   // water depth [m], > 0 for catenary: seabed at z = −depth_m
  double water_density_kg_m3 = 1025.0;    // ρ [kg/m³], for the line's buoyancy
  double gravity_m_s2 = 9.80665;          // g [m/s²]
  // Equivalent of OC3-Hywind's delta connection (crowfoot), which three single lines cannot
  // represent: a linear yaw spring on the platform, M_z = −k ψ with ψ the platform yaw (Euler
  // 1-2-3 θ₃), as in Jonkman NREL/TP-500-47266 §"mooring" and the OC3 OpenFAST deck (there in
  // HydroDyn's AddCLin). Put it here or in hydro, never in both. [N·m/rad], ≥ 0.
  double delta_yaw_stiffness_N_m_rad = 0.0;
  CatenarySolverOptions solver;           // iteration tolerance and caps (catenary only)
  std::vector<LineParams> lines;          // 1 … kMaxLines lines
};

// Collects every problem (line index, key, value found, what was expected) and throws one
// InputError listing them all; returns normally when the parameters are usable.
void validate(const MooringParams& params);

// Apparent weight in water per unit unstretched length: (m − ρ π d²/4) g [N/m].
double apparent_weight_N_m(const MooringParams& params, const LineParams& line);

// The 2-D catenary description of line `index` (contact possible when its anchor is on the seabed).
CatenaryLine catenary_line(const MooringParams& params, std::size_t index);

// Unstretched length that gives a taut spring the tension `pretension_N` when stretched to the
// chord `chord_m`: L = chord / (1 + T/EA). For decks that state a pretension (the seed gives
// none; see README).
double unstretched_length_for_pretension(double chord_m, double pretension_N, double ea_N);

}  // namespace fowtsim::mooring
