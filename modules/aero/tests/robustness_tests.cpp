// The induction solver and the rotor evaluation never fail and never return NaN, whatever the
// inflow: reverse flow, parked, feathered, spinning backwards, wind from any direction.
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/aero/aero.hpp"
#include "fowtsim/aero/rigid_rotor.hpp"
#include "fowtsim/core/error.hpp"
#include "nrel5mw_deck.hpp"

using namespace fowtsim;
using namespace fowtsim::aero;

namespace {
constexpr double kDegree = std::numbers::pi / 180.0;

bool finite(const SectionSolution& s) {
  return std::isfinite(s.phi_rad) && std::isfinite(s.alpha_rad) && std::isfinite(s.axial_induction) &&
         std::isfinite(s.tangential_induction) && std::isfinite(s.relative_speed_m_s) &&
         std::isfinite(s.cn) && std::isfinite(s.ct) && std::isfinite(s.coefficients.cm);
}
}  // namespace

// Intent: every section of every airfoil over the full circle of inflow directions (V_x, V_y),
// pitch from −20° to 90° and every combination of options gets a finite solution and a root
// (status never no_root): Ning's brackets plus the circle scan find one.
TEST_CASE("section solver: finite and rooted over all inflow angles, pitches and options", "[unit][aero]") {
  Params p = aero::testing::load_nrel5mw_deck();
  long sections = 0, rooted = 0, special = 0, max_calls = 0;
  for (int options = 0; options < 8; ++options) {
    p.tangential_induction = options & 1;
    p.drag_in_axial_induction = p.drag_in_tangential_induction = options & 2;
    p.high_induction_correction = (options & 4) ? HighInductionCorrection::none : HighInductionCorrection::buhl;
    for (std::size_t k = 1; k + 1 < p.blade.size(); ++k) {
      for (int angle = -180; angle < 180; angle += 5) {
        for (double pitch_deg : {-20.0, 0.0, 15.0, 45.0, 90.0}) {
          for (double speed : {1.0, 30.0, 90.0}) {
            SectionInflow s;
            s.axial_velocity_m_s = speed * std::sin(angle * kDegree);
            s.tangential_velocity_m_s = speed * std::cos(angle * kDegree);
            s.local_radius_m = 1.5 + p.blade[k].span_m;
            s.hub_radius_m = 1.5;
            s.tip_radius_m = 63.0;
            s.chord_m = p.blade[k].chord_m;
            s.theta_rad = p.blade[k].twist_rad + pitch_deg * kDegree;
            s.number_of_blades = 3;
            const SectionSolution sol = solve_section(s, p.airfoils[p.blade[k].airfoil], p);
            ++sections;
            CHECK(finite(sol));
            CHECK(sol.status != InductionStatus::no_root);
            if (sol.status == InductionStatus::converged) ++rooted;
            else ++special;
            max_calls = std::max<long>(max_calls, sol.residual_evaluations);
          }
        }
      }
    }
  }
  std::printf("\nsection grid: %ld sections, %ld converged roots, %ld special cases (V_x or V_y = 0), "
              "at most %ld residual calls\n", sections, rooted, special, max_calls);
}

// Intent: whole-rotor evaluations over wind direction (yaw 0…360°, up- and down-flow),
// tip-speed ratio (parked, normal, overspeed, reversed) and pitch (incl. 90° feather) are finite
// and report no unconverged node; towers on.
TEST_CASE("rotor evaluation: finite over wind direction, TSR and pitch", "[unit][aero]") {
  Params p = aero::testing::load_nrel5mw_deck();
  p.tower_potential = TowerPotential::bak;
  p.tower_shadow = TowerShadow::powles;
  Aero::Input in = make_input(p);
  Aero::Output out = make_output(p);
  const RigidRotor rotor{Vec3(-5.0, 0.0, 90.0), 0.0, 5.0 * kDegree, 2.5 * kDegree, 1.5};
  long evaluations = 0;
  for (int yaw = 0; yaw < 360; yaw += 30) {
    for (double flow_up_deg : {-60.0, 0.0, 30.0}) {
      const Vec3 wind = 12.0 * Vec3(std::cos(flow_up_deg * kDegree) * std::cos(yaw * kDegree),
                                    std::cos(flow_up_deg * kDegree) * std::sin(yaw * kDegree),
                                    std::sin(flow_up_deg * kDegree));
      in.inflow_velocity_m_s.colwise() = wind;
      for (double tsr : {-4.0, 0.0, 2.0, 7.5, 15.0}) {
        for (double pitch_deg : {-10.0, 0.0, 30.0, 90.0}) {
          for (double azimuth_deg : {0.0, 50.0}) {
            place_rigid_rotor(p, rotor, azimuth_deg * kDegree, tsr * 12.0 / 63.0, pitch_deg * kDegree, in);
            evaluate(p, in, Aero::State{}, out);
            ++evaluations;
            CHECK(out.unconverged_nodes == 0);
            CHECK(out.force_N_m.allFinite());
            CHECK(out.moment_N_m_m.allFinite());
            CHECK(std::isfinite(out.rotor.cp));
          }
        }
      }
    }
  }
  CHECK(evaluations == 12 * 3 * 5 * 4 * 2);
}

// Intent: still air gives zero loads; a NaN input is reported as NumericalError, never passed on.
TEST_CASE("still air and non-finite inputs", "[unit][aero]") {
  const Params p = aero::testing::load_nrel5mw_deck();
  Aero::Input in = make_input(p);
  Aero::Output out = make_output(p);
  place_rigid_rotor(p, RigidRotor{Vec3(0, 0, 90), 0, 0, 0, 1.5}, 0.0, 0.0, 0.0, in);
  evaluate(p, in, Aero::State{}, out);
  CHECK(out.force_N_m.norm() == 0.0);
  CHECK(out.rotor.cp == 0.0);
  in.inflow_velocity_m_s(0, 7) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(evaluate(p, in, Aero::State{}, out), NumericalError);
  Aero::Input wrong = make_input(p);
  wrong.node_orientation.pop_back();
  CHECK_THROWS_AS(evaluate(p, wrong, Aero::State{}, out), InputError);
}

// Intent: channel names are unique OpenFAST-style names and values fill the declared list.
TEST_CASE("aero channels", "[unit][aero]") {
  const Params p = aero::testing::load_nrel5mw_deck();
  ChannelRegistry registry;
  for (const ChannelInfo& c : Aero::channels(p)) registry.add(c);  // throws on a duplicate
  REQUIRE(registry.find("RtAeroCp").has_value());
  REQUIRE(registry.find("B3N3AxInd").has_value());
  Aero::Input in = make_input(p);
  Aero::Output out = make_output(p);
  in.inflow_velocity_m_s.colwise() = Vec3(11.0, 0.0, 0.0);
  place_rigid_rotor(p, RigidRotor{Vec3(0, 0, 90), 0, 0, 0, 1.5}, 0.0, 1.2, 0.0, in);
  evaluate(p, in, Aero::State{}, out);
  std::vector<double> values(registry.size());
  channel_values(p, in, out, values);
  CHECK(values[*registry.find("RtAeroPwr")] == out.rotor.power_W);
  CHECK(values[*registry.find("RtSpeed")] == Approx(1.2 * 30.0 / std::numbers::pi).epsilon(1e-15));
  CHECK(values[*registry.find("B1N2Alpha")] == Approx(out.nodes[8].section.alpha_rad * 180.0 / std::numbers::pi).epsilon(1e-15));
}
