#include "fowtsim/flexbody/shape_integrals.hpp"

#include "fowtsim/core/error.hpp"

namespace fowtsim::flexbody {

ShapeIntegrals shape_integrals(const std::vector<MassPoint>& points) {
  const Eigen::Index nf = points.empty() ? 0 : points.front().phi.cols();
  ShapeIntegrals si;
  si.Psi = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, nf);
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      si.Sigma[k][l] = Eigen::RowVectorXd::Zero(nf);
      si.Upsilon[k][l] = Eigen::MatrixXd::Zero(nf, nf);
    }
  for (const MassPoint& p : points) {
    if (p.phi.cols() != nf)
      throw InputError({"flexbody", std::nullopt, "mass points", "give every point the same shapes"},
                       "shape integrals need the same number of shapes at every point");
    si.mass += p.dm;
    si.sigma += p.dm * p.s0;
    si.sigma2 += p.dm * p.s0 * p.s0.transpose();
    si.Psi += p.dm * p.phi;
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) {
        si.Sigma[k][l] += (p.dm * p.s0(k)) * p.phi.row(l);
        si.Upsilon[k][l] += p.dm * p.phi.row(k).transpose() * p.phi.row(l);
      }
  }
  return si;
}

std::vector<MassPoint> straight_beam_mass_points(const SampledBody& body, const Eigen::Vector3d& direction) {
  std::vector<MassPoint> out;
  out.reserve(body.points.size());
  for (std::size_t k = 0; k < body.points.size(); ++k) {
    const QuadraturePoint& q = body.points[k];
    MassPoint p{q.w * q.m, Eigen::Vector3d(q.x, 0.0, 0.0), direction * body.u.row(static_cast<Eigen::Index>(k))};
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace fowtsim::flexbody
