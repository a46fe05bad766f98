#include "fowtsim/flexbody/blade_shapes.hpp"

#include "fowtsim/flexbody/shape_functions.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fowtsim::flexbody {
namespace {

// Direction of a shape's curvature in the (flap, edge) blade axes at twist θ (header).
Eigen::Vector2d curvature_direction(int shape, double theta, BladeShapeFrame frame) {
  const bool edge = shape == 2;
  if (frame == BladeShapeFrame::untwisted) return edge ? Eigen::Vector2d(0, 1) : Eigen::Vector2d(1, 0);
  const double c = std::cos(theta), s = std::sin(theta);
  return edge ? Eigen::Vector2d(s, c) : Eigen::Vector2d(c, -s);
}

// Running integrals A(x) = ∫_0^x Φ'' ds and B(x) = ∫_0^x s Φ'' ds of one shape, advanced from point
// to point; Φ' = A and Φ = x A − B. Each advance is split at the stations (θ has a kink there) and
// integrated by 8-point Gauss: φ'' is a quartic and θ is linear on each piece, so the error is that
// of cos/sin of a linear function over < 1 station interval (rounding for real blades).
class CurvatureIntegral {
 public:
  CurvatureIntegral(const ElastoDynBlade& blade, const ShapeFunction& shape, int index, BladeShapeFrame frame)
      : blade_(blade), shape_(shape), index_(index), frame_(frame), gauss_(gauss_legendre(8)) {
    for (double f : blade.span_fraction) stations_.push_back(f * blade.length());
  }

  void advance_to(double x) {
    double a = x_;
    auto next = std::upper_bound(stations_.begin(), stations_.end(), a);
    while (a < x) {
      const double b = (next != stations_.end() && *next < x) ? *next++ : x;
      piece(a, b);
      a = b;
    }
    x_ = x;
  }
  Eigen::Vector2d slope() const { return A_; }
  Eigen::Vector2d displacement() const { return x_ * A_ - B_; }

 private:
  void piece(double a, double b) {
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    for (const auto& [t, w] : gauss_) {
      const double s = mid + half * t;
      const Eigen::Vector2d f =
          shape_(s).kappa * curvature_direction(index_, blade_twist(blade_, s), frame_);
      A_ += half * w * f;
      B_ += half * w * s * f;
    }
  }

  const ElastoDynBlade& blade_;
  const ShapeFunction& shape_;
  int index_;
  BladeShapeFrame frame_;
  std::vector<std::pair<double, double>> gauss_;
  std::vector<double> stations_;
  double x_ = 0.0;
  Eigen::Vector2d A_ = Eigen::Vector2d::Zero(), B_ = Eigen::Vector2d::Zero();
};

}  // namespace

SampledBlade sample_blade(const ElastoDynBlade& blade, const BladeRule& rule, BladeShapeFrame frame) {
  SampledBlade out;
  out.points = blade_points(blade, rule);  // validates the blade
  // The running integrals advance root to tip; Gauss points come in descending order within a panel.
  std::vector<std::size_t> order(out.points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return out.points[a].x < out.points[b].x; });
  const double L = blade.length();
  const ShapeFunction shapes[kBladeShapes] = {polynomial_shape(blade.flap1_shape, L),
                                              polynomial_shape(blade.flap2_shape, L),
                                              polynomial_shape(blade.edge1_shape, L)};
  const auto n = static_cast<Eigen::Index>(out.points.size());
  for (Eigen::MatrixXd* m : {&out.u_flap, &out.u_edge, &out.nu_flap, &out.nu_edge, &out.kappa_f, &out.kappa_e,
                             &out.phi, &out.dphi})
    m->setZero(n, kBladeShapes);
  for (int j = 0; j < kBladeShapes; ++j) {
    CurvatureIntegral integral(blade, shapes[j], j, frame);
    for (const std::size_t i : order) {
      const BladePoint& p = out.points[i];
      const auto k = static_cast<Eigen::Index>(i);
      integral.advance_to(p.x);
      const Eigen::Vector2d u = integral.displacement(), nu = integral.slope();
      const ShapeValue v = shapes[j](p.x);
      const Eigen::Vector2d kappa = v.kappa * curvature_direction(j, p.twist, frame);
      const double c = std::cos(p.twist), s = std::sin(p.twist);
      out.u_flap(k, j) = u.x();
      out.u_edge(k, j) = u.y();
      out.nu_flap(k, j) = nu.x();
      out.nu_edge(k, j) = nu.y();
      out.kappa_f(k, j) = kappa.dot(Eigen::Vector2d(c, -s));  // principal axes e_f, e_e (header)
      out.kappa_e(k, j) = kappa.dot(Eigen::Vector2d(s, c));
      out.phi(k, j) = v.u;
      out.dphi(k, j) = v.nu;
    }
  }
  return out;
}

}  // namespace fowtsim::flexbody
