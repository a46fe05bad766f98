#pragma once
// Tower influence on the inflow at a blade node (AeroDyn TwrPotent / TwrShadow, as documented in
// the OpenFAST AeroDyn theory manual, "Tower influence models"):
//  * potential flow around a 2-D cylinder (a doublet in the uniform stream), baseline or with
//    Bak's drag-source correction (Bak, Madsen & Johansen 2001, Risø-R-1280);
//  * a downstream wake deficit: Powles (1983, Wind Engineering 7(1):26–42), applied inside the
//    wake half-width |ȳ| ≤ √r̄, or Eames (Gaussian), both only downstream (x̄ > 0), and limited to
//    a deficit of half the local speed.
// Coordinates are normalised by the local tower radius in a frame on the tower axis: x̄ along the
// wind component normal to the axis, ȳ = axis × x̄, r̄ = √(x̄² + ȳ²). The disturbance is
//   Δv = W [(u_pot + u_shadow) x̂ + v_pot ŷ],  W = |V⊥| (undisturbed wind normal to the axis),
//   baseline: u_pot = (ȳ² − x̄²)/r̄⁴,  v_pot = −2 x̄ ȳ / r̄⁴,
//   Bak:      the same at x̄' = x̄ + 0.1, plus C_d x̄'/(2π r̄'²) and C_d ȳ/(2π r̄'²),
//   Powles:   u_shadow = −C_d/√r̄ · cos²(π ȳ / (2√r̄)),
//   Eames:    u_shadow = −C_d/(TI x̄ √(2π)) · exp(−½ (ȳ/(TI x̄))²).
// Beyond a tower end the nearest axis point is the end; for an axial distance z̄ < 1 (in radii) x̄
// and ȳ are divided by cos(π z̄ / 2), which tapers the potential flow by cos²; nothing for z̄ ≥ 1.
// No disturbance within 0.01 D of the surface nor beyond 20 D (clearance measured to the axis
// point minus the radius).
#include "fowtsim/aero/params.hpp"
#include "fowtsim/core/types.hpp"

namespace fowtsim::aero {

// Disturbance velocity [m/s] in g to add to the undisturbed inflow `inflow_m_s` at `point_m`.
// tower_base_m is the axis point at elevation 0, tower_axis a unit vector up the axis (both in g).
// Zero when both tower models are off. Allocates nothing.
Vec3 tower_disturbance(const Params& params, const Vec3& tower_base_m, const Vec3& tower_axis,
                       const Vec3& point_m, const Vec3& inflow_m_s);

}  // namespace fowtsim::aero
