#include "morison.hpp"

#include <cmath>

#include <Eigen/Geometry>
#include <numbers>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"

namespace fowtsim::hydro::detail {
namespace {

constexpr double kPi = std::numbers::pi;

void check_node(const Hydro::Input& in, int node) {
  const bool ok = in.fluid_velocity_m_s.col(node).allFinite() &&
                  in.fluid_acceleration_m_s2.col(node).allFinite() &&
                  std::isfinite(in.dynamic_pressure_Pa[node]);
  if (!ok) {
    throw NumericalError({"hydro", in.time_s, fmt::format("fluid kinematics at strip node {}", node),
                          "check the wave kinematics handed to hydro (waves module, its time step)"},
                         "non-finite fluid velocity, acceleration or dynamic pressure");
  }
}

// Adds the force f at r (relative to r_ref) and the added mass m P at r to the totals:
// [F; M] = −[[mP, −mP r̃], [r̃ mP, −r̃ mP r̃]] [a_ref; α] (README "Added mass").
void add_point(const Vec3& r, const Vec3& f, double m, const Mat3& P, Vec6& load, Mat6& added) {
  load.head<3>() += f;
  load.tail<3>() += r.cross(f);
  const Mat3 rx = skew(r);
  const Mat3 mP = m * P;
  added.topLeftCorner<3, 3>() += mP;
  added.topRightCorner<3, 3>() -= mP * rx;
  added.bottomLeftCorner<3, 3>() += rx * mP;
  added.bottomRightCorner<3, 3>() -= rx * mP * rx;
}

}  // namespace

void add_member_morison(const Params& params, const MemberParams& member,
                        const MemberGeometry& g, const AxisInterval& wet, double surface_z,
                        const Hydro::Input& in, int offset, const PlatformMotion& motion,
                        Vec6& load, Mat6& added_mass) {
  const double rho = params.water_density_kg_m3;
  const Vec3& e = g.axis;
  const Mat3 transverse = Mat3::Identity() - e * e.transpose();
  const Mat3 axial = e * e.transpose();
  const Vec3& omega = motion.angular_velocity;
  // With potential flow the members carry viscous drag only (params.hpp, PotentialFlowParams).
  const bool inertia = !params.potential_flow;

  // Strips: midpoint rule over the submerged part of the axis (second order in ds, tests).
  const int n = member.strips;
  const double ds = wet.length_m() / n;
  if (ds > 0.0) {
    const double slope = g.radius_slope();
    for (int i = 0; i < n; ++i) {
      const int node = offset + i;
      check_node(in, node);
      const double s = wet.begin_m + (i + 0.5) * ds;
      const Vec3 p = g.point_at(s);
      const Vec3 r = p - motion.reference_m;
      const double R = g.radius_at(s);
      const double area = kPi * R * R;
      const Vec3 u = in.fluid_velocity_m_s.col(node) + current_velocity(params.current, p.z());
      const Vec3 body_velocity = motion.velocity_m_s + omega.cross(r);
      const Vec3 u_rel_n = transverse * (u - body_velocity);
      // Quadratic drag on the normal relative velocity (seed 004, Morison drag term).
      Vec3 f = 0.5 * rho * member.cd * 2.0 * R * u_rel_n.norm() * ds * u_rel_n;
      if (!inertia) {
        add_point(r, f, 0.0, transverse, load, added_mass);
        continue;
      }
      // Froude–Krylov + diffraction inertia on the normal fluid acceleration (seed 004: ρ A C_m u̇).
      f += rho * (1.0 + member.ca) * area * ds * (transverse * in.fluid_acceleration_m_s2.col(node));
      // Axial Froude–Krylov on the sloping wall of a taper: −∮ p n dS over the slice = p dA/ds ds e.
      f += in.dynamic_pressure_Pa[node] * 2.0 * kPi * R * slope * ds * e;
      // Structure acceleration −ρ C_a A a_body,⊥: the part linear in [a_ref; α] goes to added_mass,
      // the centripetal part ω × (ω × r), known from the state, stays in the force.
      const double m = rho * member.ca * area * ds;
      f -= m * (transverse * omega.cross(omega.cross(r)));
      add_point(r, f, m, transverse, load, added_mass);
    }
  }

  // End effects at A (outward normal −e) and B (+e), each while below the surface.
  const struct {
    double s, sign, ca, cd, cp;
  } ends[2] = {{0.0, -1.0, member.axial_ca_a, member.axial_cd_a, member.axial_cp_a},
               {g.length_m, 1.0, member.axial_ca_b, member.axial_cd_b, member.axial_cp_b}};
  for (int k = 0; k < 2; ++k) {
    const Vec3 p = g.point_at(ends[k].s);
    if (p.z() > surface_z) continue;
    const int node = offset + n + k;
    check_node(in, node);
    const Vec3 r = p - motion.reference_m;
    const double R = g.radius_at(ends[k].s);
    const double area = kPi * R * R;
    const double reference_volume = 2.0 / 3.0 * kPi * R * R * R;  // half sphere on the end plate
    const Vec3 u = in.fluid_velocity_m_s.col(node) + current_velocity(params.current, p.z());
    const double u_axial = e.dot(u - motion.velocity_m_s - omega.cross(r));
    Vec3 f = 0.5 * rho * ends[k].cd * area * std::abs(u_axial) * u_axial * e;
    if (!inertia) {
      add_point(r, f, 0.0, axial, load, added_mass);
      continue;
    }
    f -= ends[k].cp * in.dynamic_pressure_Pa[node] * area * ends[k].sign * e;
    f += rho * ends[k].ca * reference_volume * e.dot(in.fluid_acceleration_m_s2.col(node)) * e;
    const double m = rho * ends[k].ca * reference_volume;
    f -= m * e.dot(omega.cross(omega.cross(r))) * e;
    add_point(r, f, m, axial, load, added_mass);
  }
}

}  // namespace fowtsim::hydro::detail
