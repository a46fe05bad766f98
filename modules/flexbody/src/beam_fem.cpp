#include "fowtsim/flexbody/beam_fem.hpp"

#include "fowtsim/core/error.hpp"
#include "fowtsim/flexbody/quadrature.hpp"
#include "fowtsim/flexbody/station_segment.hpp"

namespace fowtsim::flexbody {
namespace {

// Hermite cubics on an element of length h at s ∈ [0, h], DOF [w_a, θ_a, w_b, θ_b]: values N and
// second derivatives N'' with respect to s.
void hermite(double s, double h, Eigen::Vector4d& N, Eigen::Vector4d& N2) {
  const double t = s / h;
  N << 1 - 3 * t * t + 2 * t * t * t, h * (t - 2 * t * t + t * t * t), 3 * t * t - 2 * t * t * t,
      h * (t * t * t - t * t);
  N2 << (12 * t - 6) / (h * h), (6 * t - 4) / h, (6 - 12 * t) / (h * h), (6 * t - 2) / h;
}

}  // namespace

BeamFem clamped_beam_fem(const BeamStations& stations, int elements) {
  if (elements < 1)
    throw InputError({"flexbody", std::nullopt, "elements", "give at least 1 element"},
                     "a beam FEM needs at least one element");
  const QuadratureRule exact{QuadratureRule::Kind::GaussLegendre, 1, 4};
  quadrature_points(stations, exact);  // validates the table (InputError) before it is cut
  const double h = stations.length() / elements;
  const int n = 2 * (elements + 1);  // with the root node, removed at the end
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n), K = Eigen::MatrixXd::Zero(n, n);
  for (int e = 0; e < elements; ++e) {
    const double a = e * h, b = e + 1 == elements ? stations.length() : (e + 1) * h;
    Eigen::Matrix4d Me = Eigen::Matrix4d::Zero(), Ke = Eigen::Matrix4d::Zero();
    Eigen::Vector4d N, N2;
    for (const auto& p : quadrature_points(segment(stations, a, b), exact)) {
      hermite(p.x, b - a, N, N2);
      Me += p.w * p.m * N * N.transpose();
      Ke += p.w * p.EI * N2 * N2.transpose();
    }
    M.block<4, 4>(2 * e, 2 * e) += Me;
    K.block<4, 4>(2 * e, 2 * e) += Ke;
  }
  BeamFem out;
  out.nodes = Eigen::VectorXd::LinSpaced(elements, h, stations.length());
  out.M = M.bottomRightCorner(n - 2, n - 2);
  out.K = K.bottomRightCorner(n - 2, n - 2);
  return out;
}

}  // namespace fowtsim::flexbody
