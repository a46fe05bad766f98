#pragma once
// A member at its instantaneous position: the body-frame end points of MemberParams carried into
// the inertial frame g by the platform pose (r_ref, T_gb), and the part of its axis below a
// horizontal surface.
#include "fowtsim/core/types.hpp"
#include "fowtsim/hydro/params.hpp"

namespace fowtsim::hydro {

struct MemberGeometry {
  Vec3 end_a_m = Vec3::Zero();  // end A in g [m]
  Vec3 axis = Vec3::UnitZ();    // unit vector A → B in g [-]
  double length_m = 0.0;        // |B − A| [m]
  double radius_a_m = 0.0;      // radius at A [m]
  double radius_b_m = 0.0;      // radius at B [m]

  Vec3 point_at(double s_m) const { return end_a_m + s_m * axis; }  // axis point at arclength s [m]
  double radius_at(double s_m) const {                              // linear taper [m]
    return radius_a_m + (radius_b_m - radius_a_m) * (s_m / length_m);
  }
  double radius_slope() const { return (radius_b_m - radius_a_m) / length_m; }  // dR/ds [-]
};

// r_g = r_ref + T_gb r_b for both ends.
MemberGeometry place_member(const MemberParams& member, const Vec3& reference_position_m,
                            const Mat3& orientation_gb);

// Arclength interval [begin, end] ⊂ [0, L] of the axis with z ≤ surface_z; begin ≥ end when the
// axis is entirely above it. A horizontal axis lying exactly on the surface counts as submerged.
struct AxisInterval {
  double begin_m = 0.0;
  double end_m = 0.0;
  double length_m() const { return end_m > begin_m ? end_m - begin_m : 0.0; }
};
AxisInterval submerged_axis_interval(const MemberGeometry& member, double surface_z_m);

// Point where the axis meets z = 0 (clamped to the member; its middle when the axis is
// horizontal): where the driver samples the wave elevation for SurfaceModel::wave_elevation.
Vec3 waterline_point(const MemberGeometry& member);

}  // namespace fowtsim::hydro
