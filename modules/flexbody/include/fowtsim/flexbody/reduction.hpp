#pragma once
// Superelement reductions of a FEM body with its interface DOF as masters (seed Sec. 3.4, 5.5):
// the "q^0" block of eq. 19 becomes empty (Guyan) or k fixed-interface modal coordinates
// (Craig–Bampton), and the masters g^a (B's u_z, θ_y) stay physical so eq. 19 couples them as-is.
//   Guyan:          x = [Ψ; I] x_m,                 Ψ = −K_ss⁻¹ K_sm (static constraint modes)
//   Craig–Bampton:  x = [Φ_k Ψ; 0 I] [η; x_m],     Φ_k the k lowest modes of (K_ss, M_ss)
// (slaves s, masters m). Reduced M_r = Tᵀ M T, K_r = Tᵀ K T.
#include <Eigen/Dense>

namespace fowtsim::flexbody {

struct ReducedBody {
  Eigen::MatrixXd T;     // full DOF (original order) × reduced DOF [η_1..η_k, masters]
  Eigen::MatrixXd M, K;  // reduced, DOF order [η_1..η_k, masters]: the masters stay last
};

// The masters are the last `masters` DOF of (M, K). k = 0 is the Guyan reduction; Φ_k are
// mass-normalised. Throws InputError unless 0 < masters < n and 0 <= k <= n − masters.
ReducedBody craig_bampton(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, int masters, int k);

}  // namespace fowtsim::flexbody
