#pragma once
// Eigen aliases used throughout fowtsim. Fixed-size types for 3-vectors and 3x3 frames so that
// the time loop never allocates; dynamic types only for assembled systems built once.
#include <Eigen/Core>

namespace fowtsim {

using Vec3 = Eigen::Vector3d;   // 3-vector: position [m], force [N], angle [rad], … (unit per use)
using Mat3 = Eigen::Matrix3d;   // 3x3 matrix: transformation T_ab (rotates b-components to a), inertia
using Vec6 = Eigen::Matrix<double, 6, 1>;  // [translation; rotation] generalised vector
using Mat6 = Eigen::Matrix<double, 6, 6>;
using VecX = Eigen::VectorXd;   // dynamic vector, sized at initialisation
using MatX = Eigen::MatrixXd;   // dynamic matrix, sized at initialisation

}  // namespace fowtsim
