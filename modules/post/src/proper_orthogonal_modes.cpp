#include "fowtsim/post/proper_orthogonal_modes.hpp"

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::post {

ProperOrthogonalModes proper_orthogonal_modes(const Eigen::MatrixXd& deflections, bool remove_node_means) {
  if (deflections.rows() < 1 || deflections.cols() < 1)
    throw Error({"post.pom", std::nullopt, "deflections", ""},
                fmt::format("proper_orthogonal_modes: deflections is {}×{}, needs at least one sample and one node",
                            deflections.rows(), deflections.cols()));
  ProperOrthogonalModes modes;
  modes.node_means = Eigen::VectorXd::Zero(deflections.cols());
  if (remove_node_means) modes.node_means = deflections.colwise().mean().transpose();
  const Eigen::MatrixXd fluctuation = deflections.rowwise() - modes.node_means.transpose();

  const Eigen::BDCSVD<Eigen::MatrixXd> svd(fluctuation, Eigen::ComputeThinU | Eigen::ComputeThinV);
  modes.singular_values = svd.singularValues();
  modes.shapes = svd.matrixV();
  modes.modal_amplitudes = svd.matrixU() * modes.singular_values.asDiagonal();
  // An SVD fixes each pair (aᵢ, φᵢ) up to a common sign; fix it so results do not flip between runs.
  for (Eigen::Index i = 0; i < modes.shapes.cols(); ++i) {
    Eigen::Index largest = 0;
    modes.shapes.col(i).cwiseAbs().maxCoeff(&largest);
    if (modes.shapes(largest, i) < 0.0) {
      modes.shapes.col(i) *= -1.0;
      modes.modal_amplitudes.col(i) *= -1.0;
    }
  }
  const double sum = modes.singular_values.sum(), sum_of_squares = modes.singular_values.squaredNorm();
  modes.singular_value_ratios = sum > 0.0 ? Eigen::VectorXd(modes.singular_values / sum) : Eigen::VectorXd::Zero(modes.singular_values.size());
  modes.energy_fractions = sum_of_squares > 0.0 ? Eigen::VectorXd(modes.singular_values.array().square() / sum_of_squares)
                                                : Eigen::VectorXd::Zero(modes.singular_values.size());
  return modes;
}

}  // namespace fowtsim::post
