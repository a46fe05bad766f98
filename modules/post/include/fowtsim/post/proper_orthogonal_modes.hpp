#pragma once
// Proper orthogonal modes (POMs) of nodal deflections, seed 000 §4.6.4, eqs. 4.1–4.2: the singular
// value decomposition X = U S Vᵀ of the matrix of deflections. The seed stacks one column per time
// step (N DOFs × M steps); we take the transpose, one row per time sample and one column per node,
// as channels are stored, so the seed's U (the POM shapes) is our V and the seed's V (the time
// histories) is our U:
//
//   X (samples × nodes) = Σᵢ σᵢ aᵢ φᵢᵀ,   aᵢ unit time history, φᵢ unit shape.
//
// The seed decomposes the deflections as they are (no mean removed), so a static deflection is part
// of the first mode; `remove_node_means` subtracts each node's mean first (the classic POD of the
// fluctuation). The seed's ratio of a mode is σᵢ / Σⱼ σⱼ (singular values, not their squares); the
// share of the mean square σᵢ² / Σⱼ σⱼ² is given beside it.
#include <Eigen/Dense>

namespace fowtsim::post {

struct ProperOrthogonalModes {
  Eigen::VectorXd singular_values;        // σᵢ, descending, deflection unit · √samples (r = min(samples, nodes))
  Eigen::VectorXd singular_value_ratios;  // σᵢ / Σⱼ σⱼ, – (seed §4.6.4: 92.8 / 6.1 / 0.6 % for the 120-m spar)
  Eigen::VectorXd energy_fractions;       // σᵢ² / Σⱼ σⱼ², – (share of the mean-square deflection)
  Eigen::MatrixXd shapes;                 // (nodes × r) φᵢ, unit columns; sign: largest |component| positive
  Eigen::MatrixXd modal_amplitudes;       // (samples × r) σᵢ aᵢ(t), deflection unit: X = amplitudes · shapesᵀ
  Eigen::VectorXd node_means;             // (nodes) means removed before the SVD; zero when none were
};

// POMs of `deflections` (samples × nodes, at least one of each). BDCSVD (Eigen's divide and conquer
// SVD, accurate as JacobiSVD, fast for thousands of samples).
ProperOrthogonalModes proper_orthogonal_modes(const Eigen::MatrixXd& deflections, bool remove_node_means = false);

}  // namespace fowtsim::post
