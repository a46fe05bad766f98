#pragma once
// Euler–Bernoulli beam finite elements in one bending plane: the FEM body "a" of the seed's mixed
// FEM–Rayleigh–Ritz model (Sec. 3.4, 5.5). Hermite cubic elements, two DOF per node — deflection w
// [m] and slope θ = w' [-] (the seed's q^a = [u_z, θ_y] at B, eq. 34) — consistent mass
// M_e = ∫ m Nᵀ N dx and stiffness K_e = ∫ EI N''ᵀ N'' dx, integrated exactly (4-point Gauss between
// the stations, which keep m and EI linear: degree ≤ 7 integrands).
#include "fowtsim/flexbody/stations.hpp"

#include <Eigen/Dense>

namespace fowtsim::flexbody {

struct BeamFem {
  Eigen::VectorXd nodes;  // x of the nodes 1..N [m] (the clamped root node 0 is removed)
  Eigen::MatrixXd M, K;   // 2N × 2N, DOF order [w_1, θ_1, …, w_N, θ_N]: the last two are the tip's
};

// The table cut into `elements` equal elements, clamped at x = 0 (w_0 = θ_0 = 0).
// Throws InputError for elements < 1 or a table that is not a body (quadrature.hpp).
BeamFem clamped_beam_fem(const BeamStations& stations, int elements);

}  // namespace fowtsim::flexbody
