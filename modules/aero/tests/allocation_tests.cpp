// A rotor evaluation must not touch the heap once Input and Output are built (module contract:
// functions called every step do not allocate). Global operator new counts in this executable.
#include <catch2/catch.hpp>

#include "fowtsim/testing/allocation_counter.hpp"

#include "fowtsim/aero/aero.hpp"
#include "fowtsim/aero/rigid_rotor.hpp"
#include "nrel5mw_deck.hpp"

using fowtsim::testing::allocations;
using fowtsim::testing::counting;
using namespace fowtsim;
using namespace fowtsim::aero;

TEST_CASE("a rotor aero evaluation allocates nothing", "[unit][aero]") {
  Params params = aero::testing::load_nrel5mw_deck();
  params.tower_potential = TowerPotential::bak;
  params.tower_shadow = TowerShadow::powles;
  Aero::Input in = make_input(params);
  Aero::Output out = make_output(params);
  in.inflow_velocity_m_s.colwise() = Vec3(11.0, 1.0, 0.5);
  std::vector<double> values(Aero::channels(params).size());
  const RigidRotor rotor{Vec3(-5.0, 0.0, 90.0), 0.0, 0.0873, 0.0436, 1.5};
  allocations = 0;
  counting = true;
  for (int k = 0; k < 20; ++k) {
    place_rigid_rotor(params, rotor, 0.3 * k, 1.24, 0.0, in);
    evaluate(params, in, Aero::State{}, out);
    channel_values(params, in, out, values);
  }
  counting = false;
  CHECK(allocations == 0);
}

TEST_CASE("a rotor aero evaluation and state advance with UA and DBEMT allocate nothing", "[unit][aero]") {
  Params params = aero::testing::load_nrel5mw_deck();
  params.unsteady_airfoil = UnsteadyAirfoilModel::hgm;
  params.dynamic_inflow = DynamicInflowModel::oye;
  Aero::Input in = make_input(params);
  Aero::Output out = make_output(params);
  Aero::State state = Aero::make_state(params);
  in.inflow_velocity_m_s.colwise() = Vec3(11.0, 1.0, 0.5);
  const RigidRotor rotor{Vec3(-5.0, 0.0, 90.0), 0.0, 0.0873, 0.0436, 1.5};
  place_rigid_rotor(params, rotor, 0.0, 1.24, 0.0, in);
  evaluate(params, in, state, out);
  start_states(params, in, out, 0.0, state);
  allocations = 0;
  counting = true;
  for (int k = 1; k <= 20; ++k) {
    place_rigid_rotor(params, rotor, 0.3 * k, 1.24, 0.0, in);
    evaluate(params, in, state, out);
    advance_states(params, in, out, 0.25, state);
    evaluate(params, in, state, out, Induction::held);
  }
  counting = false;
  CHECK(allocations == 0);
}
