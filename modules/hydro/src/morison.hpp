#pragma once
// Morison strip theory over one member (internal to the hydro module; README "Morison").
#include "fowtsim/core/types.hpp"
#include "fowtsim/hydro/hydro.hpp"
#include "fowtsim/hydro/member_geometry.hpp"

namespace fowtsim::hydro::detail {

// Rigid-body motion of the platform in g, shared by every member.
struct PlatformMotion {
  Vec3 reference_m;        // r_ref [m]
  Vec3 velocity_m_s;       // ṙ_ref [m/s]
  Vec3 angular_velocity;   // ω in g [rad/s]
};

// Adds the member's Morison load about r_ref (strips over `wet`, end effects of the ends below
// surface_z) to `load` and its structure-acceleration part to `added_mass`. Reads the kinematics
// of nodes [offset, offset + strips + 2) of `input`.
void add_member_morison(const Params& params, const MemberParams& member,
                        const MemberGeometry& geometry, const AxisInterval& wet, double surface_z_m,
                        const Hydro::Input& input, int offset, const PlatformMotion& motion,
                        Vec6& load, Mat6& added_mass);

}  // namespace fowtsim::hydro::detail
