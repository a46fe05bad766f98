#include "fowtsim/flexbody/spinning_beam.hpp"

#include <Eigen/Eigenvalues>

#include "fowtsim/flexbody/axial_force.hpp"

namespace fowtsim::flexbody {

SpinningBeam::SpinningBeam(const BeamStations& stations, const std::vector<ShapeFunction>& shapes,
                           const SpinningBeamOptions& options) {
  const SampledBody body = sample(quadrature_points(stations, options.rule), shapes);
  mass_ = generalized_mass(body);
  stiffness_ = generalized_stiffness(body);
  centrifugal_ = options.geometric_stiffening
                     ? geometric_stiffness(body, centrifugal_axial_force(stations, 1.0, options.root_radius))
                     : Eigen::MatrixXd::Zero(mass_.rows(), mass_.cols());
  // b = ∫ m (r + x) u = r ∫ m u + ∫ m x u.
  euler_load_ = options.root_radius * mass_first_moment(body) + mass_axial_moment(body);
  tip_.resize(static_cast<Eigen::Index>(shapes.size()));
  for (std::size_t j = 0; j < shapes.size(); ++j) tip_[static_cast<Eigen::Index>(j)] = shapes[j](stations.length()).u;
  mass_llt_.compute(mass_);
}

Eigen::VectorXd SpinningBeam::acceleration(const Eigen::VectorXd& q, double rate,
                                           double angular_acceleration) const {
  return mass_llt_.solve(-angular_acceleration * euler_load_ -
                         (stiffness_ + rate * rate * (centrifugal_ - mass_)) * q);
}

Eigen::VectorXd SpinningBeam::rotating_frequencies_squared(double rate) const {
  const Eigen::MatrixXd k = stiffness_ + rate * rate * (centrifugal_ - mass_);
  return Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(k, mass_, Eigen::EigenvaluesOnly)
      .eigenvalues();
}

}  // namespace fowtsim::flexbody
