#include "fowtsim/mooring/presets.hpp"

#include <cmath>
#include <numbers>

namespace fowtsim::mooring {

MooringParams oc3_hywind_mooring() {
  MooringParams p;
  p.model = LineModel::catenary;
  p.depth_m = 320.0;                         // MAP summary: water depth
  p.water_density_kg_m3 = 1025.0;            // .fst WtrDens
  p.gravity_m_s2 = 9.80665;                  // .fst Gravity (MAP's summary prints it rounded to 9.81)
  p.delta_yaw_stiffness_N_m_rad = 9.834e7;   // TP-47266 additional yaw spring (HydroDyn AddCLin(6,6) in the deck)
  for (const double heading_deg : {0.0, 120.0, 240.0}) {  // MAP "repeat 240 120"
    const double c = std::cos(heading_deg * std::numbers::pi / 180.0), s = std::sin(heading_deg * std::numbers::pi / 180.0);
    LineParams l;
    l.anchor_m = Vec3(853.87 * c, 853.87 * s, -320.0);  // MAP node 1
    l.fairlead_body_m = Vec3(5.2 * c, 5.2 * s, -70.0);  // MAP node 2
    l.unstretched_length_m = 902.2;
    l.mass_per_length_kg_m = 77.7066;
    l.diameter_m = 0.09;
    l.ea_N = 384.243e6;
    l.seabed_friction = 0.001;  // MAP line dictionary CB
    p.lines.push_back(l);
  }
  return p;
}

MooringParams seed_taut_mooring(double fairlead_z_m, double fairlead_radius_m, double pretension_N) {
  MooringParams p;
  p.model = LineModel::taut;
  p.depth_m = 320.0;
  p.delta_yaw_stiffness_N_m_rad = 98'340'000.0;
  constexpr double anchor_radius_m = 804.7, ea_N = 384'243'000.0;
  for (const double heading_deg : {0.0, 90.0, 180.0, 270.0}) {
    const double c = std::cos(heading_deg * std::numbers::pi / 180.0), s = std::sin(heading_deg * std::numbers::pi / 180.0);
    LineParams l;
    l.anchor_m = Vec3(anchor_radius_m * c, anchor_radius_m * s, -320.0);
    l.fairlead_body_m = Vec3(fairlead_radius_m * c, fairlead_radius_m * s, fairlead_z_m);
    l.ea_N = ea_N;
    l.unstretched_length_m = unstretched_length_for_pretension((l.fairlead_body_m - l.anchor_m).norm(), pretension_N, ea_N);
    p.lines.push_back(l);
  }
  return p;
}

}  // namespace fowtsim::mooring
