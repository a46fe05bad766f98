#include "rotor/rotor_aero.hpp"

#include <algorithm>
#include <numbers>

#include "fowtsim/io/turbsim_bts.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/multibody/blade_body.hpp"
#include "fowtsim/multibody/tower_body.hpp"
#include "fowtsim/wind/turbulence_generator.hpp"
#include "rotor/turbulence_cache.hpp"

namespace fowtsim::driver {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

std::shared_ptr<const wind::WindField> make_wind(const wind::WindParams& p, RotorAero::WindSetUp setup, std::optional<double> run_until_s,
                                                 const std::optional<std::filesystem::path>& turbulence_cache) {
  if (p.model == wind::WindModel::turbulent) {
    if (setup == RotorAero::WindSetUp::check) {
      wind::validate(p);  // what generate_turbulence checks of its input
      return nullptr;
    }
    // The scene skips the tower column `fowtsim turbulence` writes for OpenFAST (it triples the
    // generation time; the grid is the same either way): the blades stay above the grid's bottom,
    // and the tower drag takes the mean profile below it (README "Tower drag": the column moved
    // the OC3 load case's means by ≤ 0.01 %).
    wind::WindParams grid_only = p;
    grid_only.turbulence.tower_points = false;
    // A point x downwind of the hub reads the periodic box at t − x/U (InflowWind's Taylor shift):
    // blades, tower and platform stay within the grid's width of the hub up- and downwind, as the
    // sweep's lead time assumes (sweep/case_expansion.cpp).
    std::optional<wind::HeldTimes> held;
    if (run_until_s && p.speed_m_s > 0.0) {
      const double reach_s = p.turbulence.width_m / p.speed_m_s;
      held = wind::HeldTimes{*run_until_s + reach_s, reach_s};
    }
    if (turbulence_cache) return std::make_shared<wind::WindField>(p, std::make_shared<wind::FullField>(cached_turbulence(*turbulence_cache, grid_only, held)));
    return std::make_shared<wind::WindField>(p, std::make_shared<wind::FullField>(wind::generate_turbulence(grid_only, held).field));
  }
  if (p.model != wind::WindModel::bts) return std::make_shared<wind::WindField>(p);
  auto f = std::make_shared<wind::FullField>();
  static_cast<WindGrid&>(*f) = io::read_turbsim_bts(p.file);  // the file's grid; its description is dropped
  return std::make_shared<wind::WindField>(p, f);
}

}  // namespace

RotorAero::RotorAero(aero::Params params, const wind::WindParams& wind, const multibody::Params& structure, WindSetUp setup,
                     std::optional<double> run_until_s, const std::optional<std::filesystem::path>& turbulence_cache)
    : params_(std::move(params)), wind_params_(wind), wind_(make_wind(wind, setup, run_until_s, turbulence_cache)) {
  // ElastoDyn signs in the structure (PreCone < 0 cones upwind), the aero convention + upwind.
  hub_frame_rotor_.precone_rad = -structure.rotor.precone_deg * kDegree;
  hub_frame_rotor_.hub_radius_m = structure.rotor.hub_radius_m;
  aero_channel_count_ = aero::Aero::channels(params_).size();
  const std::vector<aero::BladeNodeParams>& nodes = params_.blade;
  span_weight_m_.assign(nodes.size(), 0.0);
  for (const aero::BladeNodeParams& node : nodes)
    airfoil_in_blade_.push_back(rotation_y(node.curve_angle_rad) * rotation_z(-node.twist_rad));
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
    const double half = 0.5 * (nodes[k + 1].span_m - nodes[k].span_m);
    span_weight_m_[k] += half;
    span_weight_m_[k + 1] += half;
  }
}

RotorAero::Data RotorAero::make_data() const {
  Data d;
  d.local = aero::make_input(params_);
  d.input = aero::make_input(params_);
  d.output = aero::make_output(params_);
  d.unsteady = aero::Aero::make_state(params_);
  d.points.resize(static_cast<std::size_t>(aero::node_count(params_)));
  d.inflow.resize(d.points.size());
  d.arms.resize(d.points.size());
  return d;
}

RotorAero::TowerWorkspace RotorAero::make_tower_workspace() const {
  const std::size_t n = params_.tower_drag ? params_.tower.size() : 0;
  return {std::vector<Vec3>(n), std::vector<Vec3>(n), std::vector<Vec3>(n), std::vector<Vec3>(n)};
}

void RotorAero::tower_drag(double t, const multibody::Model& model, const multibody::State& state,
                           const multibody::ChainKinematics& chain, TowerWorkspace& w, multibody::AppliedLoads& out) const {
  if (!params_.tower_drag) return;
  // The stations' elevations count from the tower axis's still-water crossing (the aero deck's tower
  // reference point), as the rigid tower's always did; as heights above the tower base they shift
  // with heave and tilt. The normal to the flow is taken to the base body's axis (a bent tower's
  // local tilt, ~1e-2 rad, changes the normal flow by its cosine: ~1e-4).
  const Vec3 axis = chain.base.orientation.col(2);
  const double base_elevation = (chain.tower_base.position_m - multibody::tower_axis_at_sea_level(chain)).dot(axis);
  const std::size_t n = w.position.size();
  for (std::size_t i = 0; i < n; ++i) {
    const multibody::PointKinematics p =
        multibody::tower_point(model, state, chain, params_.tower[i].elevation_m - base_elevation);
    w.position[i] = p.position_m;
    w.velocity[i] = p.velocity_m_s;
  }
  wind_->velocities_profile_below(w.position, t, w.inflow);  // the tower's foot lies below the grid
  aero::tower_drag_nodal(params_, axis, w.velocity, w.inflow, w.force);
  for (std::size_t i = 0; i < n; ++i)
    out.tower_loads[static_cast<std::size_t>(out.tower_load_count++)] = {params_.tower[i].elevation_m - base_elevation, w.force[i]};
}

void RotorAero::evaluate(double t, const multibody::ChainKinematics& chain, double rotor_speed_rad_s,
                         std::span<const double> pitch_rad, Data& d, aero::Induction induction) const {
  // A collective pitch goes into the placement as before; blades at different pitches (a pitch
  // fault) are placed unpitched and each node turned by its blade's pitch about the span axis z,
  // which commutes with the twist's turn: R_z(−twist) R_z(−pitch) = R_z(−(twist + pitch)).
  const int nn = aero::nodes_per_blade(params_);
  const double first = pitch_rad.empty() ? 0.0 : pitch_rad[0];
  const bool collective = std::all_of(pitch_rad.begin(), pitch_rad.end(), [&](double p) { return p == first; });
  aero::place_rigid_rotor(params_, hub_frame_rotor_, 0.0, 0.0, collective ? first : 0.0, d.local);
  if (!collective)
    for (std::size_t k = 0; k < d.points.size(); ++k) {
      const double p = pitch_rad[k / static_cast<std::size_t>(nn)];
      d.local.node_orientation[k] = d.local.node_orientation[k] * rotation_z(-p);
    }
  const Mat3& t_gh = chain.rotor.orientation;
  const Vec3& apex = chain.apex.position_m;
  const Vec3& omega = chain.rotor.angular_velocity_rad_s;
  aero::Aero::Input& in = d.input;
  in.hub_position_m = apex;
  in.hub_orientation = t_gh;
  in.rotor_speed_rad_s = rotor_speed_rad_s;
  for (Eigen::Index b = 0; b < in.blade_pitch_rad.size(); ++b) in.blade_pitch_rad[b] = pitch_rad[static_cast<std::size_t>(b)];
  in.time_s = t;
  in.tower_base_position_m = multibody::tower_axis_at_sea_level(chain);
  in.tower_axis = chain.base.orientation.col(2);
  for (std::size_t k = 0; k < d.points.size(); ++k) {
    const auto c = static_cast<Eigen::Index>(k);
    const Vec3 r = t_gh * d.local.node_position_m.col(c);
    in.node_position_m.col(c) = apex + r;
    in.node_orientation[k] = t_gh * d.local.node_orientation[k];
    in.node_velocity_m_s.col(c) = chain.apex.velocity_m_s + omega.cross(r);
    // The unsteady airfoil model's ω: the rotation of the section about its span axis z_a from the
    // platform and nacelle motion (the non-rotating shaft's angular velocity). The spin's own
    // component along a coned blade's axis (Ω sin precone, steady) is left out, so a rotor in
    // steady wind keeps the quasi-steady loads of the static polars.
    in.node_pitch_rate_rad_s(c) = chain.shaft.angular_velocity_rad_s.dot(in.node_orientation[k].col(2));
    d.points[k] = apex + r;
  }
  wind_->velocities(d.points, t, d.inflow);
  for (std::size_t k = 0; k < d.points.size(); ++k) in.inflow_velocity_m_s.col(static_cast<Eigen::Index>(k)) = d.inflow[k];
  aero::evaluate(params_, in, d.unsteady, d.output, induction);

  // The aero module's rotor resultant (exact integration of the linear load distribution, the
  // same numbers as the RtAero* channels), in h about the apex → g.
  d.force_N = t_gh * d.output.rotor.force_hub_N;
  d.moment_N_m = t_gh * d.output.rotor.moment_hub_N_m;
}

void RotorAero::evaluate_rayleigh_ritz(double t, const multibody::Model& model, const multibody::State& state,
                                       const multibody::ChainKinematics& chain, Data& d, multibody::AppliedLoads* out,
                                       aero::Induction induction) const {
  const Mat3& t_gh = chain.rotor.orientation;
  const Vec3& omega = chain.rotor.angular_velocity_rad_s;
  aero::Aero::Input& in = d.input;
  const int nb = params_.number_of_blades, nn = aero::nodes_per_blade(params_);
  for (int b = 0; b < nb; ++b) {
    const Mat3& t_gc = chain.blade_root_orientation[b];  // coned, unpitched: the rigid rotor's blade frame
    const Mat3& t_gf = chain.blade_frame_orientation[b];
    const double pitch = state.blade_pitch_rad[b];
    in.blade_pitch_rad[b] = pitch;
    const Mat3 pitched = rotation_z(-pitch);  // about the span axis, so it commutes with the twist
    for (int k = 0; k < nn; ++k) {
      const aero::BladeNodeParams& node = params_.blade[static_cast<std::size_t>(k)];
      const auto c = static_cast<Eigen::Index>(b * nn + k);
      const multibody::PointMotion p = multibody::blade_station_motion(model, state, chain, b, k);
      // The elastic rotation of the section, in g: the deflected section frame relative to f.
      const Mat3 turn = multibody::blade_section_orientation(model, state, chain, b, k) * t_gf.transpose();
      const Vec3 offset = turn * (t_gc * Vec3(node.curve_ac_m, node.sweep_ac_m, 0.0));  // aerodynamic centre from the pitch axis
      in.node_position_m.col(c) = p.position_m + offset;
      d.arms[static_cast<std::size_t>(c)] = offset;
      in.node_orientation[static_cast<std::size_t>(c)] = turn * t_gc * airfoil_in_blade_[static_cast<std::size_t>(k)] * pitched;
      in.node_velocity_m_s.col(c) = p.velocity_m_s + omega.cross(offset);
      // As the rigid rotor: the platform's and nacelle's rotation about the span axis (unsteady airfoils).
      in.node_pitch_rate_rad_s(c) = chain.shaft.angular_velocity_rad_s.dot(in.node_orientation[static_cast<std::size_t>(c)].col(2));
    }
  }
  evaluate_placed(t, chain.apex.position_m, t_gh, state.rotor_speed_rad_s, {state.blade_pitch_rad.data(), static_cast<std::size_t>(nb)},
                  multibody::tower_axis_at_sea_level(chain), chain.base.orientation.col(2), induction, d);
  if (!out) return;
  out->blade_station_load_count = nn;
  for (int b = 0; b < nb; ++b)
    for (int k = 0; k < nn; ++k) {
      const auto c = static_cast<Eigen::Index>(b * nn + k);
      const double w = span_weight_m_[static_cast<std::size_t>(k)];
      const Vec3 force = w * d.output.force_N_m.col(c);
      out->blade_station_loads[b][k] = {force, w * d.output.moment_N_m_m.col(c) + d.arms[static_cast<std::size_t>(c)].cross(force)};
    }
}

void RotorAero::evaluate_placed(double t, const Vec3& apex_m, const Mat3& t_gh, double rotor_speed_rad_s,
                                std::span<const double> pitch_rad, const Vec3& tower_base_m, const Vec3& tower_axis,
                                aero::Induction induction, Data& d) const {
  aero::Aero::Input& in = d.input;
  in.hub_position_m = apex_m;
  in.hub_orientation = t_gh;
  in.rotor_speed_rad_s = rotor_speed_rad_s;
  for (Eigen::Index b = 0; b < in.blade_pitch_rad.size(); ++b) in.blade_pitch_rad[b] = pitch_rad[static_cast<std::size_t>(b)];
  in.time_s = t;
  in.tower_base_position_m = tower_base_m;
  in.tower_axis = tower_axis;
  for (std::size_t k = 0; k < d.points.size(); ++k) d.points[k] = in.node_position_m.col(static_cast<Eigen::Index>(k));
  wind_->velocities(d.points, t, d.inflow);
  for (std::size_t k = 0; k < d.points.size(); ++k) in.inflow_velocity_m_s.col(static_cast<Eigen::Index>(k)) = d.inflow[k];
  aero::evaluate(params_, in, d.unsteady, d.output, induction);
  d.force_N = t_gh * d.output.rotor.force_hub_N;
  d.moment_N_m = t_gh * d.output.rotor.moment_hub_N_m;
}

void RotorAero::advance_states(const multibody::Model& model, const multibody::State& end, double t_end, Data& d) const {
  if (!unsteady()) return;
  multibody::chain_kinematics(model, end, d.chain);
  const aero::Induction induction = d.unsteady.started ? aero::Induction::held : aero::Induction::solve;
  if (model.rr_blades.mode_count > 0) evaluate_rayleigh_ritz(t_end, model, end, d.chain, d, nullptr, induction);
  else evaluate(t_end, d.chain, end.rotor_speed_rad_s, {end.blade_pitch_rad.data(), static_cast<std::size_t>(params_.number_of_blades)}, d, induction);
  if (!d.unsteady.started) {
    aero::start_states(params_, d.input, d.output, t_end, d.unsteady);
    return;
  }
  aero::advance_states(params_, d.input, d.output, t_end - d.unsteady.time_s, d.unsteady);
}

void RotorAero::advance_states_placed(double t, Data& d) const {
  if (!unsteady()) return;
  if (!d.unsteady.started || !(t > d.unsteady.time_s)) {
    aero::start_states(params_, d.input, d.output, t, d.unsteady);
  } else {
    aero::advance_states(params_, d.input, d.output, t - d.unsteady.time_s, d.unsteady);
  }
  aero::evaluate(params_, d.input, d.unsteady, d.output, aero::Induction::held);
  d.force_N = d.input.hub_orientation * d.output.rotor.force_hub_N;
  d.moment_N_m = d.input.hub_orientation * d.output.rotor.moment_hub_N_m;
}

std::vector<ChannelInfo> RotorAero::channels() const {
  std::vector<ChannelInfo> all = aero::Aero::channels(params_);
  for (const ChannelInfo& c : wind::Wind::channels({wind_})) all.push_back(c);
  return all;
}

void RotorAero::channel_values(double t, const Data& d, std::span<double> out) const {
  const std::size_t n = aero_channel_count_;
  aero::channel_values(params_, d.input, d.output, out.subspan(0, n));
  const Vec3 v = probe_wind(t);
  for (int k = 0; k < 3; ++k) out[n + static_cast<std::size_t>(k)] = v[k];
}

}  // namespace fowtsim::driver
