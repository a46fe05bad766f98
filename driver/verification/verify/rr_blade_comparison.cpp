#include "verify/rr_blade_comparison.hpp"

#include <numbers>

#include "beamdyn/beamdyn_setup.hpp"
#include "fowtsim/beam/modal.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/flexbody/blade_deck.hpp"
#include "fowtsim/io/beamdyn_input.hpp"

namespace fowtsim::driver {
namespace {

std::vector<double> mbbt_frequencies_hz(const beam::BeamModel& model, double omega, double hub_radius) {
  beam::BeamInput input;
  input.frame.angular_velocity_rad_s = Vec3(omega, 0, 0);
  input.frame.acceleration_m_s2 = Vec3(0, 0, -omega * omega * hub_radius);  // Ω × (Ω × HubRad e_z)
  beam::BeamState state = beam::make_state(model);
  if (omega > 0) beam::solve_static(model, input, state);
  return beam::natural_frequencies_hz(model, input, state, 3);
}

}  // namespace

RrBladeComparison rr_blade_comparison(const std::filesystem::path& blade_deck, const std::filesystem::path& beamdyn_driver) {
  const flexbody::ElastoDynBlade b = flexbody::read_elastodyn_blade(blade_deck);
  const flexbody::RrBladeMatrices rr = flexbody::rr_blade_matrices(b, flexbody::sample_blade(b));
  RrBladeComparison c;
  c.omega_rad_s = 12.1 * 2 * std::numbers::pi / 60;
  // ElastoDyn's own rule: BldNodes = 17 equal elements of the NREL 5MW deck, one midpoint each.
  c.elastodyn_rule =
      flexbody::mass_properties(flexbody::sample_blade(b, {flexbody::BladeRule::Kind::ElastoDynNodes, {}, 17, {}}));
  c.rr_rest_hz = flexbody::natural_frequencies_hz(rr);
  c.rr_spinning_hz = flexbody::natural_frequencies_hz(rr, c.omega_rad_s);
  const beam::BeamModel model = beam::discretise(driver::beamdyn_setup(io::read_beamdyn_driver(beamdyn_driver)).definition, 48);
  c.mbbt_rest_hz = mbbt_frequencies_hz(model, 0.0, b.hub_radius);
  c.mbbt_spinning_hz = mbbt_frequencies_hz(model, c.omega_rad_s, b.hub_radius);
  return c;
}

}  // namespace fowtsim::driver
