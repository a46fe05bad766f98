#include "fowtsim/hydro/member_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace fowtsim::hydro {

MemberGeometry place_member(const MemberParams& member, const Vec3& reference_position_m,
                            const Mat3& orientation_gb) {
  MemberGeometry g;
  g.end_a_m = reference_position_m + orientation_gb * member.end_a_body_m;
  const Vec3 along = orientation_gb * (member.end_b_body_m - member.end_a_body_m);
  g.length_m = along.norm();
  g.axis = along / g.length_m;
  g.radius_a_m = 0.5 * member.diameter_a_m;
  g.radius_b_m = 0.5 * member.diameter_b_m;
  return g;
}

AxisInterval submerged_axis_interval(const MemberGeometry& member, double surface_z_m) {
  // z(s) = z_A + s e_z is linear: z ≤ h on one side of its root.
  const double za = member.end_a_m.z() - surface_z_m;
  const double ez = member.axis.z();
  const double L = member.length_m;
  if (ez == 0.0) return za <= 0.0 ? AxisInterval{0.0, L} : AxisInterval{0.0, 0.0};
  const double root = -za / ez;
  if (ez > 0.0) return {0.0, std::clamp(root, 0.0, L)};  // rising from A: wet below the root
  return {std::clamp(root, 0.0, L), L};                    // falling from A: wet beyond the root
}

Vec3 waterline_point(const MemberGeometry& member) {
  const double ez = member.axis.z();
  if (std::abs(ez) < 1e-12) return member.point_at(0.5 * member.length_m);
  return member.point_at(std::clamp(-member.end_a_m.z() / ez, 0.0, member.length_m));
}

}  // namespace fowtsim::hydro
