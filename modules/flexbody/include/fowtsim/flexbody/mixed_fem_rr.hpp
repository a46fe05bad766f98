#pragma once
// The seed's mixed FEM–Rayleigh–Ritz model (Sec. 3.4, eq. 19; planar case of Sec. 5.5, eq. 34),
// linearised for small motion (θ_y = 0 in eq. 34; no axial load, so no geometric stiffness):
// body a (FEM, possibly Guyan/Craig–Bampton reduced) ends at B with DOF g^a = [u_z, θ_y]
// (deflection and slope, beam_fem.hpp); body b is a Rayleigh–Ritz body with origin B, clamped to
// a's node B, so its points move by w(x) = u_z + θ_y x + Σ_j g_j u_j(x), x measured from B.
//
// Body b's mass matrix in its frame (eq. 2, thin-beam line integrals of Sec. 4.1), planar rows
// "r" = (v_z, ω_y) and "g" = shapes — kinetic energy ½∫m (v_z − ω_y x + Σ ġ_j u_j)²:
//   M'_rr = [∫m, −∫m x; −∫m x, ∫m x²],  M'_rg = [∫m u_j; −∫m x u_j],  M'_gg = ∫m u_i u_j.
// Eq. 34 at θ_y = 0: (v_z, ω_y) = B'_ab [u̇_z, θ̇_y] with B'_ab = [1 0; 0 −1]. Eq. 19 then gives
//   M_q = [M_00  M_0a                      0          ]      K_q = [K^a  0   ]
//         [M_a0  M_aa + B'ᵀ M'_rr B'       B'ᵀ M'_rg  ]            [0    K_gg]
//         [0     (B'ᵀ M'_rg)ᵀ              M'_gg      ]
// (K'_rr = K'_rg = 0: rigid motion of b stores no strain energy; K_gg = ∫EI κ_i κ_j).
#include "fowtsim/flexbody/integrals.hpp"

#include <Eigen/Dense>

namespace fowtsim::flexbody {

struct MixedModel {
  Eigen::MatrixXd M, K;  // DOF order [body a's DOF (last two: u_z, θ_y at B), g_1..g_n of body b]
};

// `body_b` sampled on b's own table (x from B, e.g. segment(stations, x_B, L)) with shapes clamped
// at B. Throws InputError if body a has fewer than 2 DOF or M^a and K^a differ in size.
MixedModel couple_rr_body(const Eigen::MatrixXd& Ma, const Eigen::MatrixXd& Ka,
                          const SampledBody& body_b);

}  // namespace fowtsim::flexbody
