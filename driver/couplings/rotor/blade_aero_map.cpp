#include "rotor/blade_aero_map.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "fowtsim/aero/rigid_rotor.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation_vector.hpp"
#include "rotor/flexible_rotor.hpp"

namespace fowtsim::driver {

BladeAeroMap::BladeAeroMap(const aero::Params& aero_params, const beam::BeamModel& blade, double precone_rad,
                           double hub_radius_m)
    : blade_(blade) {
  const int n = blade.node_count();
  station_s_.push_back(0.0);
  for (const beam::NodeModel& node : blade.nodes) station_s_.push_back(node.s_m);
  station_s_.push_back(blade.length_m);
  node_deformation_.resize(static_cast<std::size_t>(n));

  // The undeformed aero nodes of blade 1 in f from the rigid-rotor placement (hub at the origin,
  // h = identity, ψ = 0, zero pitch): position and airfoil frame in h, taken into the coned root
  // frame r = f at zero pitch (T_hr = R_y(−precone), root at hub_radius along z_r).
  aero::Aero::Input rigid = aero::make_input(aero_params);
  aero::place_rigid_rotor(aero_params, aero::RigidRotor{.precone_rad = precone_rad, .hub_radius_m = hub_radius_m},
                          0.0, 0.0, 0.0, rigid);
  const Mat3 t_hr = rotation_matrix(Vec3(0.0, -precone_rad, 0.0));
  const Vec3 root_h = t_hr * Vec3(0.0, 0.0, hub_radius_m);
  const int count = aero::nodes_per_blade(aero_params);
  for (int k = 0; k < count; ++k) {
    AeroNode a;
    a.span_m = aero_params.blade[k].span_m;
    a.at = along(a.span_m);
    const Vec3 p_f = t_hr.transpose() * (Vec3(rigid.node_position_m.col(k)) - root_h);
    const int lo = a.at.lower;
    const Vec3 x_lo = lo < 0 ? blade.root_position_m : blade.nodes[lo].position_m;
    const Vec3 x_hi = lo + 1 >= n ? blade.tip_position_m : blade.nodes[lo + 1].position_m;
    a.offset_m = p_f - (x_lo + a.at.fraction * (x_hi - x_lo));
    a.airfoil_f = t_hr.transpose() * rigid.node_orientation[k];
    aero_nodes_.push_back(a);
  }
  force_f_.resize(3, count);
  moment_f_.resize(3, count);

  // Breakpoints: segment boundaries and aero nodes, inside the aero span.
  const double s_first = aero_nodes_.front().span_m, s_last = std::min(aero_nodes_.back().span_m, blade.length_m);
  std::vector<double> breaks;
  for (const AeroNode& a : aero_nodes_)
    if (a.span_m <= s_last) breaks.push_back(a.span_m);
  for (const beam::NodeModel& node : blade.nodes) {
    const double lo = node.s_m - 0.5 * node.segment_length_m;
    if (lo > s_first && lo < s_last) breaks.push_back(lo);
  }
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  const double g = 0.5 / std::sqrt(3.0);
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = breaks[i], b = breaks[i + 1], mid = 0.5 * (a + b);
    int segment = 0;
    while (segment + 1 < n && blade.nodes[segment + 1].s_m - 0.5 * blade.nodes[segment + 1].segment_length_m <= mid) ++segment;
    int interval = 0;
    while (interval + 2 < count && aero_nodes_[interval + 1].span_m <= mid) ++interval;
    for (const double x : {mid - g * (b - a), mid + g * (b - a)}) {
      QuadraturePoint q;
      q.segment = segment;
      q.weight_m = 0.5 * (b - a);
      q.aero_lower = interval;
      q.aero_fraction = (x - aero_nodes_[interval].span_m) / (aero_nodes_[interval + 1].span_m - aero_nodes_[interval].span_m);
      q.at = along(x);
      quadrature_.push_back(q);
    }
  }
}

BladeAeroMap::Along BladeAeroMap::along(double s) const {
  s = std::clamp(s, 0.0, station_s_.back());
  std::size_t i = 0;
  while (i + 2 < station_s_.size() && station_s_[i + 1] <= s) ++i;
  const double span = station_s_[i + 1] - station_s_[i];
  return {static_cast<int>(i) - 1, span > 0.0 ? (s - station_s_[i]) / span : 0.0};
}

Vec3 BladeAeroMap::position(const beam::BeamState& state, const Along& a) const {
  const int n = blade_.node_count();
  auto at = [&](int i) -> Vec3 {
    if (i < 0) return blade_.root_position_m;
    if (i >= n) return state.position_m[n - 1] + state.orientation[n - 1] * blade_.tip_arm_m;
    return state.position_m[i];
  };
  return at(a.lower) + a.fraction * (at(a.lower + 1) - at(a.lower));
}

Vec3 BladeAeroMap::velocity(const beam::BeamState& state, const Along& a) const {
  const int n = blade_.node_count();
  auto at = [&](int i) -> Vec3 {
    if (i < 0) return Vec3::Zero();
    if (i >= n) {
      const Vec6& v = state.velocity[n - 1];
      return v.head<3>() + v.tail<3>().cross(state.orientation[n - 1] * blade_.tip_arm_m);
    }
    return state.velocity[i].head<3>();
  };
  return at(a.lower) + a.fraction * (at(a.lower + 1) - at(a.lower));
}

// The sections' angular velocity relative to f, linear between the beam nodes (the tip arm is
// rigid: the last node's).
Vec3 BladeAeroMap::angular_velocity(const beam::BeamState& state, const Along& a) const {
  const int n = blade_.node_count();
  auto at = [&](int i) -> Vec3 { return i < 0 ? Vec3(Vec3::Zero()) : Vec3(state.velocity[std::min(i, n - 1)].tail<3>()); };
  return at(a.lower) + a.fraction * (at(a.lower + 1) - at(a.lower));
}

void BladeAeroMap::node_deformations(const beam::BeamState& state) const {
  for (int n = 0; n < blade_.node_count(); ++n)
    node_deformation_[n] = state.orientation[n] * blade_.nodes[n].orientation.transpose();
}

Mat3 BladeAeroMap::deformation(const Along& a) const {
  const int n = blade_.node_count();
  // The clamped root does not deform; the tip moves rigidly with the last node.
  auto at = [&](int i) -> Mat3 { return i < 0 ? Mat3::Identity() : node_deformation_[std::min(i, n - 1)]; };
  if (a.fraction == 0.0) return at(a.lower);
  // The linear blend of the two rotations, orthonormalised (Gram–Schmidt on its first two
  // columns): the geodesic to O(θ²) of the small relative rotation θ between neighbouring
  // stations (below 1e-4 rad of error for 0.01 rad between them), exact when they are equal,
  // and without the trigonometry of log and exp or a quaternion per node at every step.
  const Mat3 blend = (1.0 - a.fraction) * at(a.lower) + a.fraction * at(a.lower + 1);
  Mat3 r;
  r.col(0) = blend.col(0).normalized();
  r.col(1) = (blend.col(1) - r.col(0).dot(blend.col(1)) * r.col(0)).normalized();
  r.col(2) = r.col(0).cross(r.col(1));
  return r;
}

void BladeAeroMap::place(int b, const BladeFrame& frame, const beam::BeamState& state, aero::Aero::Input& input) const {
  const int count = nodes_per_blade();
  const Mat3& t_gf = frame.orientation;
  node_deformations(state);
  for (int k = 0; k < count; ++k) {
    const AeroNode& a = aero_nodes_[k];
    const auto c = static_cast<Eigen::Index>(b * count + k);
    const Mat3 d = deformation(a.at);
    const Vec3 p_f = position(state, a.at) + d * a.offset_m;
    const Vec3 r = t_gf * p_f;
    input.node_position_m.col(c) = frame.root_m + r;
    input.node_orientation[static_cast<std::size_t>(c)] = t_gf * d * a.airfoil_f;
    input.node_velocity_m_s.col(c) =
        frame.root_velocity_m_s + frame.angular_velocity_rad_s.cross(r) + t_gf * velocity(state, a.at);
    // The section's rotation rate about its span axis (pitch, platform, bending and torsion
    // rates; the caller removes the rotor spin's part): the unsteady airfoil model's ω.
    input.node_pitch_rate_rad_s(c) = (frame.angular_velocity_rad_s + t_gf * angular_velocity(state, a.at))
                                         .dot(input.node_orientation[static_cast<std::size_t>(c)].col(2));
  }
}

void BladeAeroMap::distribute(int b, const BladeFrame& frame, const beam::BeamState& state,
                              const aero::Aero::Output& output, std::vector<Vec6>& node_loads) const {
  const int count = nodes_per_blade();
  const Mat3 t_fg = frame.orientation.transpose();
  node_deformations(state);
  // The aero loads per unit span into f once per aero node, not at every quadrature point.
  for (int k = 0; k < count; ++k) {
    const auto c = static_cast<Eigen::Index>(b * count + k);
    force_f_.col(k) = t_fg * output.force_N_m.col(c);
    moment_f_.col(k) = t_fg * output.moment_N_m_m.col(c);
  }
  for (Vec6& l : node_loads) l.setZero();
  for (const QuadraturePoint& q : quadrature_) {
    const int k = q.aero_lower;
    const double x = q.aero_fraction;
    const Vec3 f = (1.0 - x) * force_f_.col(k) + x * force_f_.col(k + 1);
    const Vec3 m = (1.0 - x) * moment_f_.col(k) + x * moment_f_.col(k + 1);
    const AeroNode& lo = aero_nodes_[k];
    const AeroNode& hi = aero_nodes_[k + 1];
    const int n = q.segment;
    const Vec3 arm = position(state, q.at) + node_deformation_[n] * ((1.0 - x) * lo.offset_m + x * hi.offset_m) - state.position_m[n];
    node_loads[n].head<3>() += q.weight_m * f;
    node_loads[n].tail<3>() += q.weight_m * (m + arm.cross(f));
  }
  // The beam applies a segment's force at its load arm and adds that arm's moment itself.
  for (int n = 0; n < blade_.node_count(); ++n) {
    const Vec3 arm = state.orientation[n] * blade_.nodes[n].load_arm_m;
    node_loads[n].tail<3>() -= arm.cross(Vec3(node_loads[n].head<3>()));
  }
}

}  // namespace fowtsim::driver
