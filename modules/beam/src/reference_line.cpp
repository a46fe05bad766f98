#include "fowtsim/beam/reference_line.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/core/spline.hpp"


namespace fowtsim::beam {

ReferenceLine::ReferenceLine(double length_m, Curve curve)
    : length_m_(length_m), curve_(std::move(curve)) {
  if (!(length_m_ > 0.0)) throw std::invalid_argument("ReferenceLine: length must be positive");
}

ReferenceLine ReferenceLine::straight(const Vec3& origin, const Mat3& frame0, double length,
                                      std::function<double(double)> twist_rad) {
  return ReferenceLine(length, [=](double s) {
    return LinePoint{origin + s * frame0.col(2), frame0 * rotation_z(twist_rad(s))};
  });
}

ReferenceLine ReferenceLine::circular_arc(const Vec3& origin, const Mat3& frame0, double radius,
                                          double angle) {
  return ReferenceLine(radius * angle, [=](double s) {
    const double phi = s / radius;  // turn about axis 2 that tilts axis 3 towards axis 1
    const Mat3 turn = rotation_y(phi);
    const Vec3 local(radius * (1.0 - std::cos(phi)), 0.0, radius * std::sin(phi));
    return LinePoint{origin + frame0 * local, frame0 * turn};
  });
}

ReferenceLine ReferenceLine::parametric(std::function<Vec3(double)> position,
                                        std::function<double(double)> twist_rad, double u0,
                                        double u1) {
  constexpr int kChords = 4000;
  auto table_u = std::make_shared<std::vector<double>>(kChords + 1);
  auto table_s = std::make_shared<std::vector<double>>(kChords + 1, 0.0);
  Vec3 previous = position(u0);
  for (int k = 0; k <= kChords; ++k) {
    const double u = u0 + (u1 - u0) * k / kChords;
    const Vec3 p = position(u);
    (*table_u)[k] = u;
    if (k > 0) (*table_s)[k] = (*table_s)[k - 1] + (p - previous).norm();
    previous = p;
  }
  const double h = 1e-7 * (u1 - u0);
  return ReferenceLine(table_s->back(), [=](double s) {
    const auto hi = std::clamp<std::size_t>(
        std::upper_bound(table_s->begin(), table_s->end(), s) - table_s->begin(), 1, kChords);
    const double w = (s - (*table_s)[hi - 1]) / ((*table_s)[hi] - (*table_s)[hi - 1]);
    const double u = (*table_u)[hi - 1] + w * ((*table_u)[hi] - (*table_u)[hi - 1]);
    const Vec3 t = (position(std::min(u + h, u1)) - position(std::max(u - h, u0))).normalized();
    // BeamDyn's frame rule divides by t_z: a line turning back (or across) z has no frame here.
    if (!(t.z() > 1e-6))
      throw InputError({"beam", std::nullopt, "reference line", "key points must advance along +z"},
                       fmt::format("the reference line does not advance along z at arclength {:.4g} m "
                                   "(tangent {:.3g}, {:.3g}, {:.3g})", s, t.x(), t.y(), t.z()));
    const double a = twist_rad(u);
    const Vec3 e1 = Vec3(std::cos(a), std::sin(a), -(t.x() * std::cos(a) + t.y() * std::sin(a)) / t.z()).normalized();
    Mat3 frame;
    frame << e1, t.cross(e1), t;
    return LinePoint{position(u), frame};
  });
}

ReferenceLine ReferenceLine::through_key_points(const std::vector<Vec3>& points,
                                                const std::vector<double>& twist_rad) {
  const std::size_t n = points.size();
  if (n < 2 || twist_rad.size() != n)
    throw std::invalid_argument("through_key_points: need ≥ 2 points, one twist per point");
  std::vector<double> u(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) u[i] = u[i - 1] + (points[i] - points[i - 1]).norm();
  std::array<std::vector<double>, 3> coord;
  for (const Vec3& p : points)
    for (int k = 0; k < 3; ++k) coord[k].push_back(p[k]);
  auto splines = std::make_shared<std::array<NaturalCubicSpline, 4>>(std::array<NaturalCubicSpline, 4>{
      NaturalCubicSpline(u, coord[0]), NaturalCubicSpline(u, coord[1]), NaturalCubicSpline(u, coord[2]),
      NaturalCubicSpline(u, twist_rad)});
  return parametric([splines](double uu) { return Vec3((*splines)[0](uu), (*splines)[1](uu), (*splines)[2](uu)); },
                    [splines](double uu) { return (*splines)[3](uu); }, 0.0, u.back());
}

}  // namespace fowtsim::beam
