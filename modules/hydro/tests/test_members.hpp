#pragma once
// Small member decks shared by the hydro tests.
#include <Eigen/Geometry>

#include "fowtsim/hydro/hydro.hpp"

namespace fowtsim::hydro::test {

// One vertical cylinder of diameter D from z = −draft up to z = top (top > 0 pierces the surface),
// centred on the reference point; axial coefficients left at their defaults (C_p,ax = 1).
inline Params vertical_cylinder(double diameter, double draft, double top, double cd, double ca, int strips) {
  Params p;
  MemberParams m;
  m.end_a_body_m = Vec3(0.0, 0.0, -draft);
  m.end_b_body_m = Vec3(0.0, 0.0, top);
  m.diameter_a_m = m.diameter_b_m = diameter;
  m.cd = cd;
  m.ca = ca;
  m.strips = strips;
  p.members.push_back(m);
  validate(p);
  return p;
}

// Input at the platform pose with kinematics at the strip points filled by `fill(points, input)`.
template <class Fill>
Hydro::Input input_at(const Params& params, const FrameMotion& pose, Fill fill) {
  Hydro::Input in = make_input(params);
  in.platform = pose;
  Points points(3, node_count(params));
  strip_points(params, pose, in.surface_elevation_m, points);
  fill(points, in);
  return in;
}

}  // namespace fowtsim::hydro::test
