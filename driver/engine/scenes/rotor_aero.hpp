#pragma once
// Aerodynamics of the rigid rotor on the floating multibody: the inflow from the wind module at
// the blade nodes, the blade-element momentum loads of the aero module, summed to a force at the
// rotor apex and a moment about it for the multibody. Node geometry follows the chain exactly:
// the blade table is placed once in the hub frame (aero::place_rigid_rotor with a hub at rest),
// then moved with the hub's pose, velocity and angular velocity at every evaluation.
#include <memory>
#include <span>
#include <vector>

#include "fowtsim/aero/aero.hpp"
#include "fowtsim/aero/rigid_rotor.hpp"
#include "fowtsim/core/channels.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/multibody/kinematics.hpp"
#include "fowtsim/multibody/model.hpp"
#include "fowtsim/multibody/params.hpp"
#include "fowtsim/wind/wind_field.hpp"
#include "run/checkpoint.hpp"

namespace fowtsim::driver {

class RotorAero {
 public:
  // Reads the deck's `aero`, `airfoils` and `wind` sections; the rotor geometry (precone, hub
  // radius) comes from the structure.
  RotorAero(const io::ValidatedDeck& deck, const multibody::Params& structure);

  // Loads at time t on the rotor in the chain configuration `chain`, blade pitch `pitch_rad`:
  // force at the apex and moment about it, inertial frame [N, N·m].
  void evaluate(double t, const multibody::ChainKinematics& chain, double rotor_speed_rad_s, double pitch_rad,
                aero::Induction induction = aero::Induction::solve);
  // Flexible blades: the caller places every node (position, airfoil frame, structural velocity,
  // all in g; BladeAeroMap::place) in placed_input(), then evaluate_placed() computes the loads
  // per node into output() and the rotor resultant about the apex.
  aero::Aero::Input& placed_input() { return input_; }
  void evaluate_placed(double t, const Vec3& apex_m, const Mat3& t_gh, double rotor_speed_rad_s,
                       std::span<const double> pitch_rad, const Vec3& tower_base_m, const Vec3& tower_axis,
                       aero::Induction induction);
  const aero::Aero::Output& output() const { return output_; }

  // Unsteady airfoil aerodynamics and dynamic inflow (aero.unsteady_airfoil, aero.dynamic_inflow):
  // their states are read by every evaluation and advanced only here. Nothing happens when the
  // deck asks for neither.
  bool unsteady() const { return aero::has_unsteady_models(params_); }
  // Rigid blades, once per large step: the rotor evaluated at the step's end (t_end, the multibody
  // state after the step) with the states of its start, then the states advanced to t_end. The
  // end evaluation holds the induction of the last Runge–Kutta stage (also at t_end, on the
  // predicted state): its quasi-steady BEM solve is the filters' input, and no second solve is
  // needed. The first call starts the states there (the first step is quasi-steady).
  void advance_states(const multibody::Model& model, const multibody::State& end, double t_end, double pitch_rad);
  // Flexible blades, at every small step: after evaluate_placed() at t, advances the states from
  // their time to t with that evaluation and evaluates again (held induction) so the output and
  // loads carry the new states; at a time not after the states' (the start's static passes) it
  // (re)starts them from that evaluation.
  void advance_states_placed(double t);
  // The wind field (for the rotor-plane probe and checks that the rotor stays inside the grid).
  const wind::WindField& wind() const { return *wind_; }
  const aero::Params& params() const { return params_; }
  const Vec3& force_N() const { return force_; }
  const Vec3& moment_N_m() const { return moment_; }
  // Hub-height wind speed at the probe (for the controller's record 27 and the channels).
  Vec3 probe_wind(double t) const { return wind_->velocity(wind_->params().probe_point_m, t); }

  // What an evaluation leaves for the next one: each node's BEM root, the warm start of its next
  // solve (and, with held inductions, its induced velocities). An output row evaluates between
  // steps and restores it, so results do not depend on decimation. No allocation once sized.
  void save_memory(std::vector<aero::NodeResult>& memory) const { memory = output_.nodes; }
  void restore_memory(const std::vector<aero::NodeResult>& memory) { output_.nodes = memory; }
  // Writes or reads the last evaluation's input and output whole (the channels and the warm
  // starts) and the unsteady states, for checkpoints.
  template <class Archive>
  void checkpoint(Archive& archive);

  std::vector<ChannelInfo> channels() const;  // aero channels, then Wind1VelX/Y/Z
  void channel_values(double t, std::span<double> out) const;

 private:
  aero::Params params_;
  std::shared_ptr<const wind::WindField> wind_;
  aero::RigidRotor hub_frame_rotor_;  // the rotor placed at the origin with h = identity
  aero::Aero::Input local_, input_;
  aero::Aero::Output output_;
  aero::Aero::State state_;
  multibody::ChainKinematics chain_;  // advance_states' end configuration
  std::vector<Vec3> points_, inflow_;
  std::size_t aero_channel_count_ = 0;
  Vec3 force_ = Vec3::Zero(), moment_ = Vec3::Zero();
};

}  // namespace fowtsim::driver
