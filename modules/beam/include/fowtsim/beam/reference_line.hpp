#pragma once
// The reference line of an undeformed beam (seed 000 §2.2.1: curvilinear coordinate s along the
// elastic axis, local frame l at each point): position and local frame as functions of
// arclength, in the floating frame f.
//
// Convention (BeamDyn's, so that BeamDyn sectional matrices apply unchanged): local axis 3 is the
// tangent of the reference line, axes 1 and 2 span the cross-section. The seed writes the same
// theory with axis 1 (a) tangent; only the labels differ.
#include <functional>
#include <vector>

#include "fowtsim/core/types.hpp"

namespace fowtsim::beam {

struct LinePoint {
  Vec3 position_m = Vec3::Zero();  // R_f^{WP0}: point on the reference line, in f [m]
  Mat3 frame = Mat3::Identity();   // T_fl: columns are the local axes 1, 2, 3 resolved in f [-]
};

class ReferenceLine {
 public:
  using Curve = std::function<LinePoint(double s_m)>;

  // curve(s) for s in [0, length]; s must be arclength (|d position/ds| = 1).
  ReferenceLine(double length_m, Curve curve);

  double length_m() const { return length_m_; }
  LinePoint at(double s_m) const { return curve_(s_m); }

  // Straight line from origin along frame0's axis 3; twist(s) rotates the section about the
  // tangent (positive by the right-hand rule about axis 3).
  static ReferenceLine straight(const Vec3& origin_m, const Mat3& frame0, double length_m,
                                std::function<double(double s_m)> twist_rad);

  // Circular arc of radius r starting at origin with tangent frame0·e3, bending towards
  // frame0·e1 (the centre of curvature is at origin + r frame0·e1), turning by angle_rad.
  // The local frame turns with the tangent about frame0·e2.
  static ReferenceLine circular_arc(const Vec3& origin_m, const Mat3& frame0, double radius_m,
                                    double angle_rad);

  // A curve position(u), u in [u0, u1], re-parametrised by arclength (chords of (u1−u0)/4000:
  // the chord error of a smooth curve is O(h²)·curvature, far below 1e-8 of the length here).
  // Local frame by BeamDyn's rule: axis 3 the unit tangent t, axis 1 the unit vector along
  // (cos α, sin α, −(t_x cos α + t_y sin α)/t_z) with α = twist(u), axis 2 = axis 3 × axis 1.
  // For a line along z this is a rotation by α about z. Needs t_z > 0 everywhere: evaluating a
  // point where it is not throws InputError.
  static ReferenceLine parametric(std::function<Vec3(double u)> position,
                                  std::function<double(double u)> twist_rad, double u0, double u1);

  // Natural cubic splines of each coordinate and of the twist (rad) through key points, over
  // cumulative chord length; frames by the rule of parametric().
  static ReferenceLine through_key_points(const std::vector<Vec3>& points_m,
                                          const std::vector<double>& twist_rad);

 private:
  double length_m_;
  Curve curve_;
};

}  // namespace fowtsim::beam
