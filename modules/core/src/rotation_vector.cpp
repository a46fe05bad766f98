#include "fowtsim/core/rotation_vector.hpp"

#include <algorithm>
#include <cmath>

#include "fowtsim/core/rotation.hpp"

namespace fowtsim {
namespace {
// Below this angle the closed forms lose digits to cancellation; the Taylor series to the
// terms kept are exact to double precision there (next term ~ φ⁴/720 < 1e-19).
constexpr double kSeriesAngle = 1e-4;
}  // namespace

Mat3 rotation_matrix(const Vec3& phi) {
  const double a2 = phi.squaredNorm();
  const double a = std::sqrt(a2);
  const Mat3 p = skew(phi);
  double s, c;  // sin a / a, (1 − cos a)/a²
  if (a < kSeriesAngle) {
    s = 1.0 - a2 / 6.0;
    c = 0.5 - a2 / 24.0;
  } else {
    s = std::sin(a) / a;
    c = (1.0 - std::cos(a)) / a2;
  }
  return Mat3::Identity() + s * p + c * p * p;
}

Vec3 rotation_vector(const Mat3& r) {
  const double cos_a = std::clamp(0.5 * (r.trace() - 1.0), -1.0, 1.0);
  const Vec3 w(r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1));  // 2 sin a n
  const double sin_a = 0.5 * w.norm();
  const double a = std::atan2(sin_a, cos_a);
  if (a < kSeriesAngle) return 0.5 * (1.0 + a * a / 6.0) * w;
  if (a < 3.0) return a / (2.0 * sin_a) * w;
  // Near π, sin a → 0: take the axis from the symmetric part r + rᵀ = 2 cos a I + 2(1 − cos a) nnᵀ.
  const Mat3 b = (0.5 * (r + r.transpose()) - cos_a * Mat3::Identity()) / (1.0 - cos_a);
  Eigen::Index k;
  b.diagonal().maxCoeff(&k);
  Vec3 n = b.col(k) / std::sqrt(b(k, k));
  if (n.dot(w) < 0.0) n = -n;
  return a * n;
}

Mat3 right_jacobian(const Vec3& phi) {
  const double a2 = phi.squaredNorm();
  const double a = std::sqrt(a2);
  const Mat3 p = skew(phi);
  double b, c;  // (1 − cos a)/a², (a − sin a)/a³
  if (a < kSeriesAngle) {
    b = 0.5 - a2 / 24.0;
    c = 1.0 / 6.0 - a2 / 120.0;
  } else {
    b = (1.0 - std::cos(a)) / a2;
    c = (a - std::sin(a)) / (a2 * a);
  }
  return Mat3::Identity() - b * p + c * p * p;
}

Mat3 right_jacobian_inverse(const Vec3& phi) {
  const double a2 = phi.squaredNorm();
  const double a = std::sqrt(a2);
  const Mat3 p = skew(phi);
  double d;  // 1/a² − (1 + cos a)/(2 a sin a)
  if (a < kSeriesAngle) {
    d = 1.0 / 12.0 + a2 / 720.0;
  } else {
    d = 1.0 / a2 - (1.0 + std::cos(a)) / (2.0 * a * std::sin(a));
  }
  return Mat3::Identity() + 0.5 * p + d * p * p;
}

Vec3 wiener_milenkovic(const Mat3& r) {
  const Vec3 phi = rotation_vector(r);
  const double a = phi.norm();
  if (a < kSeriesAngle) return phi * (1.0 + a * a / 48.0);  // 4 tan(a/4)/a ≈ 1 + a²/48
  return 4.0 * std::tan(0.25 * a) / a * phi;
}

}  // namespace fowtsim
