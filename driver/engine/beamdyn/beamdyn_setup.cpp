#include "beamdyn/beamdyn_setup.hpp"

#include <cmath>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation_vector.hpp"

namespace fowtsim::driver {
namespace {

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void unsupported(const std::filesystem::path& file, const std::string& key, const std::string& what) {
  throw InputError({"beamdyn", std::nullopt, key, ""}, fmt::format("{}: {}: {}", file.string(), key, what));
}

// BeamDyn's key-point fit: p(ξ) = v_first (1−ξ)/2 + v_last (1+ξ)/2 + (1−ξ²) Σ_k b_k ξ^k with
// ξ = 2(z − z_first)/(z_last − z_first) − 1, total degree `degree`, b by least squares over the
// key points (the end points are met exactly).
class EndpointPolynomial {
 public:
  EndpointPolynomial(const std::vector<double>& xi, const std::vector<double>& v, int degree)
      : first_(v.front()), last_(v.back()) {
    const int inner = std::max(degree - 1, 0);
    if (inner == 0) return;
    MatX a(xi.size(), inner);
    VecX rhs(xi.size());
    for (std::size_t i = 0; i < xi.size(); ++i) {
      rhs[i] = v[i] - ends(xi[i]);
      for (int k = 0; k < inner; ++k) a(i, k) = (1.0 - xi[i] * xi[i]) * std::pow(xi[i], k);
    }
    b_ = a.colPivHouseholderQr().solve(rhs);
  }
  double operator()(double xi) const {
    double sum = ends(xi);
    for (int k = 0; k < b_.size(); ++k) sum += (1.0 - xi * xi) * std::pow(xi, k) * b_[k];
    return sum;
  }

 private:
  double ends(double xi) const { return 0.5 * (first_ * (1.0 - xi) + last_ * (1.0 + xi)); }
  double first_, last_;
  VecX b_;
};

beam::ReferenceLine beamdyn_line(const io::BeamDynPrimary& p) {
  if (p.member_total != 1)
    unsupported(p.file, "member_total", fmt::format("only one member is supported, got {}", p.member_total));
  std::vector<Vec3> points;
  std::vector<double> twist;
  for (const io::BeamDynKeyPoint& k : p.key_points) {
    points.push_back(k.position_m);
    twist.push_back(k.initial_twist_deg);
  }
  try {
    return beamdyn_reference_line(points, twist, std::min(p.order_elem, static_cast<int>(points.size()) - 1));
  } catch (const InputError& e) {
    unsupported(p.file, "kp_zr", e.message());
  }
}

// Root-frame orientation at time t: R(t) = exp(ω̃ (t − t0)) R0.
Mat3 root_orientation(const BeamDynSetup& s, double t) {
  return rotation_matrix(s.angular_velocity_rad_s * (t - s.t_initial_s)) * s.root_orientation0;
}

}  // namespace

beam::ReferenceLine beamdyn_reference_line(const std::vector<Vec3>& kp, const std::vector<double>& twist_deg,
                                           int degree) {
  const double z0 = kp.front().z(), z1 = kp.back().z();
  if (kp.size() < 2 || kp.size() != twist_deg.size() || !(z1 > z0))
    throw InputError({"beam", std::nullopt, "kp_zr", ""},
                     "key points: need ≥ 2 with z increasing root to tip and one twist each");
  std::vector<double> xi, x, y, twist;
  for (std::size_t i = 0; i < kp.size(); ++i) {
    xi.push_back(2.0 * (kp[i].z() - z0) / (z1 - z0) - 1.0);
    x.push_back(kp[i].x());
    y.push_back(kp[i].y());
    twist.push_back(-twist_deg[i] * kPi / 180.0);  // BeamDyn turns the section by −twist
  }
  const EndpointPolynomial px(xi, x, degree), py(xi, y, degree), pt(xi, twist, degree);
  auto xi_of = [=](double z) { return 2.0 * (z - z0) / (z1 - z0) - 1.0; };
  return beam::ReferenceLine::parametric(
      [=](double z) { return Vec3(px(xi_of(z)), py(xi_of(z)), z); },
      [=](double z) { return pt(xi_of(z)); }, z0, z1);
}

beam::BeamDefinition beamdyn_definition(const io::BeamDynPrimary& primary, const io::BeamDynBlade& blade) {
  beam::BeamDefinition d{beamdyn_line(primary), {}};
  for (const io::BeamDynStation& st : blade.stations) d.stations.push_back({st.eta, st.stiffness, st.mass});
  if (blade.damp_type == 2) unsupported(blade.file, "damp_type", "modal damping (2) is not supported; use 0 or 1");
  if (blade.damp_type == 1) d.stiffness_damping = blade.mu;
  // The beam module's checks now, naming the blade file and its station (BeamDyn numbers from 1),
  // not later when the beam is discretised.
  try {
    beam::validate(d);
  } catch (const InputError& e) {
    const std::string& variable = e.context().variable;
    const std::string station =
        variable.starts_with("stations[") ? fmt::format(" station {}:", std::stoi(variable.substr(9)) + 1) : std::string();
    throw InputError(e.context(), fmt::format("{}:{} {}", blade.file.string(), station, e.message()));
  }
  return d;
}

BeamDynSetup beamdyn_setup(const io::BeamDynCase& bd) {
  BeamDynSetup s{.definition = beamdyn_definition(bd.primary, bd.blade)};
  s.root_orientation0 = bd.driver.glb_dcm.transpose();
  s.root_position_m = bd.driver.glb_pos_m;
  s.angular_velocity_rad_s = bd.driver.root_angular_velocity_rad_s;
  s.gravity_m_s2 = bd.driver.gravity_m_s2;
  s.distributed_load = bd.driver.distributed_load;
  s.tip_load = bd.driver.tip_load;
  s.point_loads = bd.driver.point_loads;
  s.dynamic = bd.driver.dynamic_solve;
  s.quasi_static_init = bd.primary.quasi_static_init.value_or(false);
  s.t_initial_s = bd.driver.t_initial_s;
  s.t_final_s = bd.driver.t_final_s;
  s.dt_s = bd.primary.dt_beam_s.value_or(bd.driver.dt_s);
  s.spectral_radius = bd.primary.rhoinf;
  s.out_list = bd.primary.out_list;
  if (s.dynamic && !(s.dt_s > 0.0)) unsupported(bd.driver.file, "dt", "the time step must be positive");
  if (s.dynamic && !(s.t_final_s > s.t_initial_s))
    unsupported(bd.driver.file, "t_final", fmt::format("must exceed t_initial = {}", s.t_initial_s));
  return s;
}

void beamdyn_input(const BeamDynSetup& s, const beam::BeamModel& model, const beam::BeamState& state,
                   double t, beam::BeamInput& in) {
  const Mat3 rt = root_orientation(s, t).transpose();  // global → root frame
  in.frame.angular_velocity_rad_s = rt * s.angular_velocity_rad_s;
  // The root turns about the global origin: a_root = ω × (ω × x_root(t)).
  const Vec3 x_root = rotation_matrix(s.angular_velocity_rad_s * (t - s.t_initial_s)) * s.root_position_m;
  in.frame.acceleration_m_s2 = rt * s.angular_velocity_rad_s.cross(s.angular_velocity_rad_s.cross(x_root));
  in.frame.gravity_m_s2 = rt * s.gravity_m_s2;
  Vec6 per_length;
  per_length << rt * s.distributed_load.head<3>(), rt * s.distributed_load.tail<3>();
  in.node_loads.resize(model.node_count());
  for (int n = 0; n < model.node_count(); ++n) in.node_loads[n] = per_length * model.nodes[n].segment_length_m;
  in.tip_load << rt * s.tip_load.head<3>(), rt * s.tip_load.tail<3>();
  if (s.tip_motion) {
    in.tip_displacement_m = rt * s.tip_motion->displacement(t - s.t_initial_s);
    in.tip_velocity_m_s = rt * s.tip_motion->velocity(t - s.t_initial_s);
  }
  for (const io::BeamDynPointLoad& p : s.point_loads) {
    const double arc = p.eta * model.length_m;
    const int n = std::clamp(static_cast<int>(arc / model.nodes[0].segment_length_m), 0, model.node_count() - 1);
    const beam::LinePoint at = s.definition.line.at(arc);
    const Vec3 arm = state.orientation[n] * (model.nodes[n].orientation.transpose() * (at.position_m - model.nodes[n].position_m)) -
                     state.orientation[n] * model.nodes[n].load_arm_m;
    const Vec3 f = rt * p.load.head<3>();
    in.node_loads[n].head<3>() += f;
    in.node_loads[n].tail<3>() += rt * p.load.tail<3>() + arm.cross(f);
  }
}

}  // namespace fowtsim::driver
