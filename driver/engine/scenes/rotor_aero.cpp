#include "scenes/rotor_aero.hpp"

#include <numbers>

#include "decks/aero_deck.hpp"
#include "decks/wind_deck.hpp"
#include "fowtsim/io/turbsim_bts.hpp"
#include "fowtsim/wind/turbulence_generator.hpp"

namespace fowtsim::driver {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

std::shared_ptr<const wind::WindField> make_wind(const wind::WindParams& p) {
  if (p.model == wind::WindModel::turbulent) {
    // The rotor's aerodynamics read only the grid (the blades stay above it), so the scene skips
    // the tower column `fowtsim turbulence` writes for OpenFAST (it triples the generation time;
    // the grid is the same either way).
    wind::WindParams grid_only = p;
    grid_only.turbulence.tower_points = false;
    return std::make_shared<wind::WindField>(p, std::make_shared<wind::FullField>(wind::generate_turbulence(grid_only).field));
  }
  if (p.model != wind::WindModel::bts) return std::make_shared<wind::WindField>(p);
  auto f = std::make_shared<wind::FullField>();
  static_cast<WindGrid&>(*f) = io::read_turbsim_bts(p.file);  // the file's grid; its description is dropped
  return std::make_shared<wind::WindField>(p, f);
}

}  // namespace

RotorAero::RotorAero(const io::ValidatedDeck& deck, const multibody::Params& structure)
    : params_(aero_params(deck)), wind_(make_wind(wind_params(deck.section("wind")))) {
  // ElastoDyn signs in the structure (PreCone < 0 cones upwind), the aero convention + upwind.
  hub_frame_rotor_.precone_rad = -structure.rotor.precone_deg * kDegree;
  hub_frame_rotor_.hub_radius_m = structure.rotor.hub_radius_m;
  local_ = aero::make_input(params_);
  input_ = aero::make_input(params_);
  output_ = aero::make_output(params_);
  state_ = aero::Aero::make_state(params_);
  points_.resize(static_cast<std::size_t>(aero::node_count(params_)));
  inflow_.resize(points_.size());
  aero_channel_count_ = aero::Aero::channels(params_).size();
}

void RotorAero::evaluate(double t, const multibody::ChainKinematics& chain, double rotor_speed_rad_s, double pitch_rad,
                         aero::Induction induction) {
  aero::place_rigid_rotor(params_, hub_frame_rotor_, 0.0, 0.0, pitch_rad, local_);
  const Mat3& t_gh = chain.rotor.orientation;
  const Vec3& apex = chain.apex.position_m;
  const Vec3& omega = chain.rotor.angular_velocity_rad_s;
  input_.hub_position_m = apex;
  input_.hub_orientation = t_gh;
  input_.rotor_speed_rad_s = rotor_speed_rad_s;
  input_.blade_pitch_rad.setConstant(pitch_rad);
  input_.time_s = t;
  input_.tower_base_position_m = multibody::tower_axis_at_sea_level(chain);
  input_.tower_axis = chain.base.orientation.col(2);
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const auto c = static_cast<Eigen::Index>(k);
    const Vec3 r = t_gh * local_.node_position_m.col(c);
    input_.node_position_m.col(c) = apex + r;
    input_.node_orientation[k] = t_gh * local_.node_orientation[k];
    input_.node_velocity_m_s.col(c) = chain.apex.velocity_m_s + omega.cross(r);
    // The unsteady airfoil model's ω: the rotation of the section about its span axis z_a from the
    // platform and nacelle motion (the non-rotating shaft's angular velocity). The spin's own
    // component along a coned blade's axis (Ω sin precone, steady) is left out, so a rotor in
    // steady wind keeps the quasi-steady loads of the static polars.
    input_.node_pitch_rate_rad_s(c) = chain.shaft.angular_velocity_rad_s.dot(input_.node_orientation[k].col(2));
    points_[k] = apex + r;
  }
  wind_->velocities(points_, t, inflow_);
  for (std::size_t k = 0; k < points_.size(); ++k) input_.inflow_velocity_m_s.col(static_cast<Eigen::Index>(k)) = inflow_[k];
  aero::evaluate(params_, input_, state_, output_, induction);

  // The aero module's rotor resultant (exact integration of the linear load distribution, the
  // same numbers as the RtAero* channels), in h about the apex → g.
  force_ = t_gh * output_.rotor.force_hub_N;
  moment_ = t_gh * output_.rotor.moment_hub_N_m;
}

void RotorAero::evaluate_placed(double t, const Vec3& apex_m, const Mat3& t_gh, double rotor_speed_rad_s,
                                std::span<const double> pitch_rad, const Vec3& tower_base_m, const Vec3& tower_axis,
                                aero::Induction induction) {
  input_.hub_position_m = apex_m;
  input_.hub_orientation = t_gh;
  input_.rotor_speed_rad_s = rotor_speed_rad_s;
  for (Eigen::Index b = 0; b < input_.blade_pitch_rad.size(); ++b) input_.blade_pitch_rad[b] = pitch_rad[static_cast<std::size_t>(b)];
  input_.time_s = t;
  input_.tower_base_position_m = tower_base_m;
  input_.tower_axis = tower_axis;
  for (std::size_t k = 0; k < points_.size(); ++k) points_[k] = input_.node_position_m.col(static_cast<Eigen::Index>(k));
  wind_->velocities(points_, t, inflow_);
  for (std::size_t k = 0; k < points_.size(); ++k) input_.inflow_velocity_m_s.col(static_cast<Eigen::Index>(k)) = inflow_[k];
  aero::evaluate(params_, input_, state_, output_, induction);
  force_ = t_gh * output_.rotor.force_hub_N;
  moment_ = t_gh * output_.rotor.moment_hub_N_m;
}

void RotorAero::advance_states(const multibody::Model& model, const multibody::State& end, double t_end, double pitch_rad) {
  if (!unsteady()) return;
  multibody::chain_kinematics(model, end, chain_);
  evaluate(t_end, chain_, end.rotor_speed_rad_s, pitch_rad, state_.started ? aero::Induction::held : aero::Induction::solve);
  if (!state_.started) {
    aero::start_states(params_, input_, output_, t_end, state_);
    return;
  }
  aero::advance_states(params_, input_, output_, t_end - state_.time_s, state_);
}

void RotorAero::advance_states_placed(double t) {
  if (!unsteady()) return;
  if (!state_.started || !(t > state_.time_s)) {
    aero::start_states(params_, input_, output_, t, state_);
  } else {
    aero::advance_states(params_, input_, output_, t - state_.time_s, state_);
  }
  aero::evaluate(params_, input_, state_, output_, aero::Induction::held);
  force_ = input_.hub_orientation * output_.rotor.force_hub_N;
  moment_ = input_.hub_orientation * output_.rotor.moment_hub_N_m;
}

template <class Archive>
void RotorAero::checkpoint(Archive& a) {
  a.io(input_.hub_position_m);
  a.io(input_.hub_orientation);
  a.io(input_.rotor_speed_rad_s);
  a.io(input_.blade_pitch_rad);
  a.io(input_.node_position_m);
  a.io(input_.node_orientation);
  a.io(input_.node_velocity_m_s);
  a.io(input_.inflow_velocity_m_s);
  a.io(input_.tower_base_position_m);
  a.io(input_.tower_axis);
  a.io(input_.time_s);
  a.io(output_.force_N_m);
  a.io(output_.moment_N_m_m);
  a.io(output_.disturbed_inflow_m_s);
  a.io(output_.nodes);
  aero::RotorResult& rr = output_.rotor;
  a.io(rr.force_hub_N);
  a.io(rr.moment_hub_N_m);
  for (double* x : {&rr.power_W, &rr.mean_axial_inflow_m_s, &rr.skew_rad, &rr.radius_m, &rr.area_m2, &rr.tip_speed_ratio,
                    &rr.cp, &rr.ct, &rr.cq})
    a.io(*x);
  a.io(output_.unconverged_nodes);
  a.io(force_);
  a.io(moment_);
  a.io(state_.started);
  a.io(state_.time_s);
  a.io(state_.tau1_s);
  a.io(state_.nodes);
}
template void RotorAero::checkpoint(CheckpointWriter&);
template void RotorAero::checkpoint(CheckpointReader&);

std::vector<ChannelInfo> RotorAero::channels() const {
  std::vector<ChannelInfo> all = aero::Aero::channels(params_);
  for (const ChannelInfo& c : wind::Wind::channels({wind_})) all.push_back(c);
  return all;
}

void RotorAero::channel_values(double t, std::span<double> out) const {
  const std::size_t n = aero_channel_count_;
  aero::channel_values(params_, input_, output_, out.subspan(0, n));
  const Vec3 v = probe_wind(t);
  for (int k = 0; k < 3; ++k) out[n + static_cast<std::size_t>(k)] = v[k];
}

}  // namespace fowtsim::driver
