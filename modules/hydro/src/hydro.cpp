#include "fowtsim/hydro/hydro.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/hydro/hydrostatics.hpp"
#include "fowtsim/hydro/member_geometry.hpp"
#include "morison.hpp"

namespace fowtsim::hydro {
namespace {

[[noreturn]] void misuse(const std::string& variable, const std::string& message) {
  throw InputError({"hydro", std::nullopt, variable, "size Input with make_input(params)"}, message);
}

void check_sizes(const Params& params, const Hydro::Input& in) {
  const Eigen::Index n = node_count(params);
  if (in.fluid_velocity_m_s.cols() != n || in.fluid_acceleration_m_s2.cols() != n ||
      in.dynamic_pressure_Pa.size() != n) {
    misuse("fluid kinematics",
           fmt::format("input.fluid_*.cols() = {}/{}/{} differs from node_count(params) = {}",
                       in.fluid_velocity_m_s.cols(), in.fluid_acceleration_m_s2.cols(),
                       in.dynamic_pressure_Pa.size(), n));
  }
  if (params.surface == SurfaceModel::wave_elevation &&
      in.surface_elevation_m.size() != static_cast<Eigen::Index>(params.members.size())) {
    misuse("surface_elevation_m", fmt::format("input.surface_elevation_m.size() = {} differs from "
                                              "params.members.size() = {}",
                                              in.surface_elevation_m.size(), params.members.size()));
  }
}

// The platform pose must be finite and T_gb a rotation; a drifted or NaN pose would otherwise
// turn into silently wrong buoyancy.
void check_pose(const FrameMotion& pose, double time_s) {
  const auto fail = [&](const char* variable, const char* message) {
    throw NumericalError({"hydro", time_s, variable,
                          "check the platform state handed to hydro (multibody step size)"},
                         message);
  };
  if (!pose.position_m.allFinite() || !pose.orientation.allFinite()) {
    fail("platform pose", "non-finite platform position or orientation");
  }
  if (!pose.velocity_m_s.allFinite() || !pose.angular_velocity_rad_s.allFinite()) {
    fail("platform velocity", "non-finite platform velocity or angular velocity");
  }
  if ((pose.orientation.transpose() * pose.orientation - Mat3::Identity()).cwiseAbs().maxCoeff() > 1e-6) {
    fail("platform orientation", "orientation is not a rotation matrix (|T^T T - I| > 1e-6)");
  }
}

double member_surface(const Params& params, const Eigen::Ref<const VecX>& elevation, int m) {
  return params.surface == SurfaceModel::wave_elevation ? elevation[m] : 0.0;
}

Vec6 added_linear_load(const Params& params, const FrameMotion& pose, const Vec3& omega_g) {
  Vec6 q, qdot;
  q << pose.position_m, matrix_to_euler123(pose.orientation);
  qdot << pose.velocity_m_s, omega_g;
  const Vec6 quadratic = qdot.cwiseAbs().cwiseProduct(qdot);
  return params.added_force - params.added_stiffness * q - params.added_damping * qdot -
         params.added_quadratic_damping * quadratic;
}

}  // namespace

Vec3 current_velocity(const CurrentParams& c, double z) {
  double speed = 0.0;
  switch (c.profile) {
    case CurrentParams::Profile::none: return Vec3::Zero();
    case CurrentParams::Profile::uniform: speed = c.surface_speed_m_s; break;
    case CurrentParams::Profile::power_law: {
      // Above z = 0 (wave-elevation strips) the surface value holds; below −d there is none.
      const double depth_fraction = (std::min(z, 0.0) + c.reference_depth_m) / c.reference_depth_m;
      speed = depth_fraction <= 0.0 ? 0.0 : c.surface_speed_m_s * std::pow(depth_fraction, c.power_law_exponent);
      break;
    }
  }
  return speed * Vec3(std::cos(c.heading_rad), std::sin(c.heading_rad), 0.0);
}

Hydro::Input make_input(const Params& params) {
  Hydro::Input in;
  const Eigen::Index n = node_count(params);
  in.fluid_velocity_m_s = Points::Zero(3, n);
  in.fluid_acceleration_m_s2 = Points::Zero(3, n);
  in.dynamic_pressure_Pa = VecX::Zero(n);
  in.surface_elevation_m = VecX::Zero(static_cast<Eigen::Index>(params.members.size()));
  return in;
}

void strip_points(const Params& params, const FrameMotion& platform,
                  const Eigen::Ref<const VecX>& surface_elevation_m, Eigen::Ref<Points> out) {
  if (params.surface == SurfaceModel::wave_elevation &&
      surface_elevation_m.size() != static_cast<Eigen::Index>(params.members.size())) {
    misuse("surface_elevation_m", fmt::format("surface_elevation_m.size() = {} differs from "
                                              "params.members.size() = {}",
                                              surface_elevation_m.size(), params.members.size()));
  }
  if (out.cols() != node_count(params)) {
    misuse("strip points", fmt::format("out.cols() = {} differs from node_count(params) = {}",
                                       out.cols(), node_count(params)));
  }
  int offset = 0;
  for (int m = 0; m < static_cast<int>(params.members.size()); ++m) {
    const MemberParams& member = params.members[m];
    const MemberGeometry g = place_member(member, platform.position_m, platform.orientation);
    const AxisInterval wet = submerged_axis_interval(g, member_surface(params, surface_elevation_m, m));
    const double ds = wet.length_m() / member.strips;
    for (int i = 0; i < member.strips; ++i) out.col(offset + i) = g.point_at(wet.begin_m + (i + 0.5) * ds);
    out.col(offset + member.strips) = g.end_a_m;
    out.col(offset + member.strips + 1) = g.point_at(g.length_m);
    offset += member.strips + 2;
  }
}

void waterline_points(const Params& params, const FrameMotion& platform, Eigen::Ref<Points> out) {
  if (out.cols() != static_cast<Eigen::Index>(params.members.size())) {
    misuse("waterline points", fmt::format("out.cols() = {} differs from params.members.size() = {}",
                                           out.cols(), params.members.size()));
  }
  for (int m = 0; m < static_cast<int>(params.members.size()); ++m) {
    out.col(m) = waterline_point(place_member(params.members[m], platform.position_m, platform.orientation));
  }
}

Vec6 generalised_velocity(const FrameMotion& platform) {
  Vec6 v;
  v << platform.velocity_m_s, platform.orientation * platform.angular_velocity_rad_s;
  return v;
}

Hydro::State Hydro::make_state(const Params& params, const Input& in) {
  State s;
  if (params.potential_flow)
    s.radiation = make_radiation_state(params.potential_flow->radiation, in.time_s, generalised_velocity(in.platform));
  return s;
}

Hydro::State Hydro::make_state(const Params& params) { return make_state(params, make_input(params)); }

void Hydro::advance(const Params& params, const Input& in, double t, double dt, State& state) {
  if (!params.potential_flow) return;
  check_pose(in.platform, t + dt);
  advance_radiation(params.potential_flow->radiation, t + dt, generalised_velocity(in.platform), state.radiation);
}

// Linear hydrostatics (HydroDyn with WAMIT): ρ g V0 up at the reference point, − C_hst q with
// q = [r_ref; Euler 1-2-3 angles], the same small-angle coordinates as the added linear terms.
static Vec6 linear_hydrostatic_load(const Params& params, const FrameMotion& pose) {
  Vec6 q;
  q << pose.position_m, matrix_to_euler123(pose.orientation);
  Vec6 f = -params.hydrostatic_stiffness * q;
  f[2] += params.water_density_kg_m3 * params.gravity_m_s2 * params.displaced_volume_m3;
  return f;
}

Hydro::Output Hydro::outputs(const Params& params, const Input& in, const State& state) {
  check_sizes(params, in);
  check_pose(in.platform, in.time_s);
  Output out;
  const double rho_g = params.water_density_kg_m3 * params.gravity_m_s2;
  const detail::PlatformMotion motion{in.platform.position_m, in.platform.velocity_m_s,
                                      in.platform.orientation * in.platform.angular_velocity_rad_s};
  const bool nonlinear_hydrostatics = params.hydrostatics == Hydrostatics::nonlinear;
  SubmergedVolume displaced;
  int offset = 0;
  for (int m = 0; m < static_cast<int>(params.members.size()); ++m) {
    const MemberParams& member = params.members[m];
    const MemberGeometry g = place_member(member, motion.reference_m, in.platform.orientation);
    if (nonlinear_hydrostatics) {
      const SubmergedVolume v = submerged_volume(g, 0.0, params.hydrostatic_quadrature_points);
      displaced.volume_m3 += v.volume_m3;
      displaced.first_moment_m4 += v.first_moment_m4;
    }
    const double surface_z = member_surface(params, in.surface_elevation_m, m);
    if (!std::isfinite(surface_z)) {
      throw NumericalError({"hydro", in.time_s, fmt::format("surface_elevation_m[{}]", m),
                            "check the wave elevation handed to hydro"}, "non-finite wave elevation");
    }
    detail::add_member_morison(params, member, g, submerged_axis_interval(g, surface_z), surface_z, in,
                               offset, motion, out.morison, out.added_mass);
    offset += member.strips + 2;
  }
  if (nonlinear_hydrostatics) {
    // Buoyancy ρ g V k at the centre of buoyancy; its moment about r_ref is (r_B − r_ref) × F.
    out.submerged_volume_m3 = displaced.volume_m3;
    out.buoyancy.head<3>() = Vec3(0.0, 0.0, rho_g * displaced.volume_m3);
    out.buoyancy.tail<3>() = (displaced.first_moment_m4 - displaced.volume_m3 * motion.reference_m).cross(
        Vec3(0.0, 0.0, rho_g));
    out.centre_of_buoyancy_m = displaced.volume_m3 > 0.0 ? Vec3(displaced.first_moment_m4 / displaced.volume_m3)
                                                         : motion.reference_m;
  } else {
    out.submerged_volume_m3 = params.displaced_volume_m3;
    out.centre_of_buoyancy_m = motion.reference_m;
    out.buoyancy = linear_hydrostatic_load(params, in.platform);
  }
  out.added_linear = added_linear_load(params, in.platform, motion.angular_velocity);
  if (params.potential_flow) {
    const PotentialFlowParams& pf = *params.potential_flow;
    out.added_mass += pf.radiation.added_mass_infinite_frequency;
    out.radiation = radiation_load(pf.radiation, state.radiation, in.time_s, generalised_velocity(in.platform));
    if (pf.excitation) out.excitation = in.wave_excitation;
  }
  out.total = out.buoyancy + out.morison + out.added_linear + out.radiation + out.excitation;
  if (!out.total.allFinite() || !out.added_mass.allFinite()) {
    throw NumericalError({"hydro", in.time_s, "hydro load", "check the platform state and wave inputs"},
                         "non-finite hydrodynamic load or added mass");
  }
  return out;
}

std::vector<ChannelInfo> Hydro::channels(const Params& params) {
  std::vector<ChannelInfo> all;
  const char* axes[3] = {"x", "y", "z"};
  const struct {
    const char* prefix;
    const char* what;
  } parts[6] = {{"Hydro", "total hydrodynamic + hydrostatic load (buoyancy, Morison, added linear, potential flow, the "
                           "added-mass reaction −A a)"},
                {"B1HDS", "hydrostatic load (buoyancy, nonlinear or linear)"},
                {"HydroMor", "Morison load (strips and end effects, without the added-mass reaction)"},
                {"HydroAdd", "additional linear load (AddF0, AddCLin, AddBLin, AddBQuad)"},
                {"B1Rdt", "potential-flow radiation load: memory −∫K q̇ and the reaction −A(∞) a"},
                {"B1Wvs", "potential-flow first-order wave excitation"}};
  for (const auto& part : std::span(parts, params.potential_flow ? 6 : 4)) {
    for (const char* a : axes) {
      all.push_back({fmt::format("{}F{}i", part.prefix, a), "N",
                     fmt::format("{}: force along inertial {}", part.what, a), "hydro"});
    }
    for (const char* a : axes) {
      all.push_back({fmt::format("{}M{}i", part.prefix, a), "N-m",
                     fmt::format("{}: moment about inertial {} at the platform reference point", part.what, a),
                     "hydro"});
    }
  }
  return all;
}

void channel_values(const Params& params, const Hydro::Output& o, const Vec6& platform_acceleration,
                    std::span<double> values) {
  const Vec6 total = o.total - o.added_mass * platform_acceleration;
  const Vec6 radiation =
      params.potential_flow ? Vec6(o.radiation - params.potential_flow->radiation.added_mass_infinite_frequency * platform_acceleration)
                            : o.radiation;
  const Vec6* parts[6] = {&total, &o.buoyancy, &o.morison, &o.added_linear, &radiation, &o.excitation};
  const int count = params.potential_flow ? 6 : 4;
  if (values.size() != static_cast<std::size_t>(6 * count))
    misuse("channel values", fmt::format("{} values for {} channels", values.size(), 6 * count));
  for (int p = 0; p < count; ++p) {
    for (int i = 0; i < 6; ++i) values[static_cast<std::size_t>(6 * p + i)] = (*parts[p])[i];
  }
}

}  // namespace fowtsim::hydro
