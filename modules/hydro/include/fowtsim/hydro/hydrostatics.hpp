#pragma once
// Nonlinear hydrostatics at the instantaneous position (seed 000 §4.2: "buoyancy force and the
// location of the center of buoyancy using the instantaneous position of the platform"): the
// exact submerged volume and its first moment of a tilted circular frustum cut by a horizontal
// plane, at any angle, partly or fully submerged or dry.
//
// Method (README "Hydrostatics"). Slice the member across its axis: each slice is a disc of radius
// R(s) centred on the axis point c(s), tilted by θ (sin θ = |k − (k·e)e|). The plane z = h cuts
// the disc along a chord at in-plane distance y0 = (h − c_z)/sin θ from the centre, t = y0/R:
//   submerged area      A(t)  = R² (π − acos t + t √(1 − t²))
//   first moment (y)    M(t)  = −(2/3) R³ (1 − t²)^{3/2}     along w = k_⊥/|k_⊥| in the disc
// The axis splits exactly (the disc's top and bottom heights c_z ± R sin θ are linear in s) into
//   fully submerged  → closed-form frustum volume and centroid,
//   dry              → nothing,
//   cut obliquely    → ∫ (A, A c + M w) ds by Gauss–Legendre after s = s1 + (s2 − s1)(1 − cos φ)/2,
//                      which makes the (1 ∓ t)^{3/2} end behaviour analytic in φ, so the rule
//                      converges exponentially (16 points: relative error < 1e-12, tests).
#include "fowtsim/core/types.hpp"
#include "fowtsim/hydro/member_geometry.hpp"

namespace fowtsim::hydro {

struct SubmergedVolume {
  double volume_m3 = 0.0;                 // V [m³]
  Vec3 first_moment_m4 = Vec3::Zero();    // ∫ r dV in g [m⁴]; centre of buoyancy = this / V
};

// Part of the member below z = surface_z_m. quadrature_points in [1, 64].
SubmergedVolume submerged_volume(const MemberGeometry& member, double surface_z_m,
                                 int quadrature_points);

// Gauss–Legendre rule on [−1, 1] with n points (1 ≤ n ≤ 64), computed once on first use.
struct GaussRule {
  int n = 0;
  double nodes[64] = {};
  double weights[64] = {};
};
const GaussRule& gauss_legendre(int n);

}  // namespace fowtsim::hydro
