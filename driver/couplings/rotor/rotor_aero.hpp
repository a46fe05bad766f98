#pragma once
// Aerodynamics of the rigid rotor on the floating multibody: the inflow from the wind module at
// the blade nodes, the blade-element momentum loads of the aero module, summed to a force at the
// rotor apex and a moment about it for the multibody. Node geometry follows the chain exactly:
// the blade table is placed once in the hub frame (aero::place_rigid_rotor with a hub at rest),
// then moved with the hub's pose, velocity and angular velocity at every evaluation.
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "fowtsim/aero/aero.hpp"
#include "fowtsim/aero/rigid_rotor.hpp"
#include "fowtsim/aero/tower_drag.hpp"
#include "fowtsim/core/channels.hpp"
#include "fowtsim/multibody/kinematics.hpp"
#include "fowtsim/multibody/loads.hpp"
#include "fowtsim/multibody/model.hpp"
#include "fowtsim/multibody/params.hpp"
#include "fowtsim/wind/wind_field.hpp"

namespace fowtsim::driver {

class RotorAero {
 public:
  // What changes during a run (a part of the scene state): the last evaluation (the channels read
  // it; its node results warm-start the next solve and hold held inductions), the unsteady states
  // and the rotor resultant; and workspace every evaluation writes before reading.
  struct Data {
    aero::Aero::Input input;            // the last evaluation's input
    aero::Aero::Output output;          // its output
    aero::Aero::State unsteady;         // unsteady airfoil / dynamic inflow states (empty when off)
    Vec3 force_N = Vec3::Zero();        // rotor force at the apex, g [N]
    Vec3 moment_N_m = Vec3::Zero();     // rotor moment about the apex, g [N·m]
    aero::Aero::Input local;            // workspace: the rigid rotor placed at the origin with h = identity
    multibody::ChainKinematics chain;   // workspace: advance_states' end configuration
    std::vector<Vec3> points, inflow;   // workspace: node positions and their wind
    std::vector<Vec3> arms;             // workspace: Rayleigh–Ritz blades, each node's aerodynamic centre from its station, g
  };

  // What the constructor sets up of the wind: all of it for a run, or for a deck check (a sweep
  // checks every case deck before anything runs) all but a turbulent field, whose parameters are
  // validated but whose generation (seconds per ten-minute field) is left to the run.
  enum class WindSetUp { run, check };

  // The rotor of `params` in the wind of `wind` (a turbulent field is generated here, a TurbSim
  // file read); the rotor geometry (precone, hub radius) comes from the structure. Set up with
  // WindSetUp::check, a rotor in turbulent wind has no field: only params() and wind_params() serve.
  // With `run_until_s`, a generated field holds only the samples a run to that time reaches; with
  // `turbulence_cache`, it is read from that folder when another run stored it there, else generated
  // and stored (turbulence_cache.hpp).
  RotorAero(aero::Params params, const wind::WindParams& wind, const multibody::Params& structure,
            WindSetUp setup = WindSetUp::run, std::optional<double> run_until_s = std::nullopt,
            const std::optional<std::filesystem::path>& turbulence_cache = std::nullopt);
  Data make_data() const;

  // Loads at time t on the rotor in the chain configuration `chain`, blade pitch `pitch_rad` (one
  // per blade): force at the apex and moment about it, inertial frame [N, N·m], into d.force_N,
  // d.moment_N_m.
  void evaluate(double t, const multibody::ChainKinematics& chain, double rotor_speed_rad_s, std::span<const double> pitch_rad, Data& d,
                aero::Induction induction = aero::Induction::solve) const;
  // Rayleigh–Ritz blades (the model's stations are the aero nodes' spans, then the tip): every node
  // on its deflected station — position, airfoil frame turned by the section's elastic rotation,
  // the station's velocity — at each blade's pitch (state.blade_pitch_rad), evaluated; d.force_N and
  // d.moment_N_m get the rotor resultant, and `out` (if given) the node loads lumped to the stations
  // (trapezoid weights of the per-span loads, which the aero module integrates piecewise linearly,
  // so the lumped forces sum to its resultant exactly), moments about the stations.
  void evaluate_rayleigh_ritz(double t, const multibody::Model& model, const multibody::State& state,
                              const multibody::ChainKinematics& chain, Data& d, multibody::AppliedLoads* out,
                              aero::Induction induction = aero::Induction::solve) const;
  // Flexible blades: the caller places every node (position, airfoil frame, structural velocity,
  // all in g; BladeAeroMap::place) in d.input, then evaluate_placed() computes the loads per node
  // into d.output and the rotor resultant about the apex.
  void evaluate_placed(double t, const Vec3& apex_m, const Mat3& t_gh, double rotor_speed_rad_s,
                       std::span<const double> pitch_rad, const Vec3& tower_base_m, const Vec3& tower_axis,
                       aero::Induction induction, Data& d) const;

  // Workspace of tower_drag(), sized by make_tower_workspace(): written before it is read.
  struct TowerWorkspace {
    std::vector<Vec3> position, velocity, inflow, force;  // per tower station, g
  };
  TowerWorkspace make_tower_workspace() const;
  bool tower_drag_on() const { return params_.tower_drag; }
  // Aerodynamic drag on the tower (aero.tower_drag, AeroDyn TwrAero; aero/tower_drag.hpp) at time t
  // for the multibody state `state` (chain: its kinematics): the stations at their elevations along
  // the tower axis from tower_axis_at_sea_level, placed on the deflected tower and moving with it
  // (multibody::tower_point: a flexible tower's vibration is damped by the drag), in the wind of the
  // field (the mean profile below a turbulence grid); appended to out.tower_loads as the consistent
  // nodal loads at the stations' heights above the tower base.
  void tower_drag(double t, const multibody::Model& model, const multibody::State& state,
                  const multibody::ChainKinematics& chain, TowerWorkspace& w, multibody::AppliedLoads& out) const;

  // Unsteady airfoil aerodynamics and dynamic inflow (aero.unsteady_airfoil, aero.dynamic_inflow):
  // their states are read by every evaluation and advanced only here. Nothing happens when the
  // deck asks for neither.
  bool unsteady() const { return aero::has_unsteady_models(params_); }
  // Rigid or Rayleigh–Ritz blades, once per large step: the rotor evaluated at the step's end (t_end, the multibody
  // state after the step) with the states of its start, then the states advanced to t_end. The
  // end evaluation holds the induction of the last Runge–Kutta stage (also at t_end, on the
  // predicted state): its quasi-steady BEM solve is the filters' input, and no second solve is
  // needed. The first call starts the states there (the first step is quasi-steady).
  void advance_states(const multibody::Model& model, const multibody::State& end, double t_end, Data& d) const;
  // Flexible blades, at every small step: after evaluate_placed() at t, advances the states from
  // their time to t with that evaluation and evaluates again (held induction) so the output and
  // loads carry the new states; at a time not after the states' (the start's static passes) it
  // (re)starts them from that evaluation.
  void advance_states_placed(double t, Data& d) const;
  // The wind field (for the rotor-plane probe and checks that the rotor stays inside the grid).
  const wind::WindField& wind() const { return *wind_; }
  const wind::WindParams& wind_params() const { return wind_params_; }
  const aero::Params& params() const { return params_; }
  // Hub-height wind speed at the probe (for the controller's record 27 and the channels).
  Vec3 probe_wind(double t) const { return wind_->velocity(wind_->params().probe_point_m, t); }

  std::vector<ChannelInfo> channels() const;  // aero channels, then Wind1VelX/Y/Z
  void channel_values(double t, const Data& d, std::span<double> out) const;

 private:
  aero::Params params_;
  wind::WindParams wind_params_;
  std::shared_ptr<const wind::WindField> wind_;  // null only for a turbulent wind set up for a check
  aero::RigidRotor hub_frame_rotor_;  // the rotor placed at the origin with h = identity
  std::vector<double> span_weight_m_;  // trapezoid weight of each blade node along the span [m]
  std::vector<Mat3> airfoil_in_blade_;  // each node's airfoil frame in the unpitched blade frame, R_y(curve) R_z(−twist)
  std::size_t aero_channel_count_ = 0;
};

// Field list of the rotor's data (core/fields.hpp).
template <class Archive>
void fields(Archive& a, RotorAero::Data& d) {
  a.io(d.input, d.output, d.unsteady, d.force_N, d.moment_N_m);
  a.scratch(d.local, d.chain, d.points, d.inflow, d.arms);
}

}  // namespace fowtsim::driver
