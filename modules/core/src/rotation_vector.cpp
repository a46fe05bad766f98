#include "fowtsim/core/rotation_vector.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace fowtsim {
namespace {

// The scalar factors below are even functions of the angle a. Below kSeriesAngle they are summed
// as Taylor series in x = a² instead of from sin, cos and atan2: exact to double precision there
// (the first dropped term is below 1e-17 of the sum at the threshold) and several times cheaper
// than the library calls, which matters because the beam takes ~2 exponentials, a logarithm and
// two Jacobians per section and step, nearly all of small angles. The closed forms take over
// above, where they no longer lose digits to cancellation.
constexpr double kSeriesAngle = 0.5;

template <std::size_t N>
double series(const double (&coefficients)[N], double x) {
  double sum = coefficients[N - 1];
  for (std::size_t k = N - 1; k-- > 0;) sum = sum * x + coefficients[k];
  return sum;
}

// sin a / a = Σ (−x)^k / (2k+1)!
constexpr double kSinc[] = {1.0, -1.0 / 6, 1.0 / 120, -1.0 / 5040, 1.0 / 362880, -1.0 / 39916800,
                            1.0 / 6227020800.0, -1.0 / 1307674368000.0};
// (1 − cos a)/a² = Σ (−x)^k / (2k+2)!
constexpr double kCosc[] = {1.0 / 2, -1.0 / 24, 1.0 / 720, -1.0 / 40320, 1.0 / 3628800, -1.0 / 479001600,
                            1.0 / 87178291200.0, -1.0 / 20922789888000.0};
// (a − sin a)/a³ = Σ (−x)^k / (2k+3)!
constexpr double kSincResidual[] = {1.0 / 6, -1.0 / 120, 1.0 / 5040, -1.0 / 362880, 1.0 / 39916800,
                                    -1.0 / 6227020800.0, 1.0 / 1307674368000.0, -1.0 / 355687428096000.0};
// 1/a² − (1 + cos a)/(2 a sin a) = (1 − (a/2) cot(a/2))/a² = Σ_{n≥1} |B_2n| x^{n−1} / (2n)!
constexpr double kJacobianInverse[] = {1.0 / 12, 1.0 / 720, 1.0 / 30240, 1.0 / 1209600, 1.0 / 47900160,
                                       691.0 / 1307674368000.0, 7.0 / 523069747200.0,
                                       3617.0 / 10670622842880000.0};
// asin(s)/s = Σ (2k)! / (4^k (k!)² (2k+1)) s^{2k}: the angle from 2 sin a = |axial part| of r.
constexpr double kAsinOverSin[] = {1.0, 1.0 / 6, 3.0 / 40, 5.0 / 112, 35.0 / 1152, 63.0 / 2816, 231.0 / 13312,
                                   143.0 / 10240, 6435.0 / 557056};
constexpr double kAsinSeriesSine = 0.1;  // below it the first dropped term (s¹⁸) is < 1e-20

// I + f φ̃ + g φ̃², with φ̃² = φφᵀ − a² I written out (no 3×3 product): the common form of the
// exponential and both Jacobians.
Mat3 identity_plus(const Vec3& phi, double a2, double f, double g) {
  Mat3 m = g * phi * phi.transpose();
  m.diagonal().array() += 1.0 - g * a2;
  m(1, 0) += f * phi.z();
  m(0, 1) -= f * phi.z();
  m(0, 2) += f * phi.y();
  m(2, 0) -= f * phi.y();
  m(2, 1) += f * phi.x();
  m(1, 2) -= f * phi.x();
  return m;
}

}  // namespace

Mat3 rotation_matrix(const Vec3& phi) {
  const double a2 = phi.squaredNorm();
  double s, c;  // sin a / a, (1 − cos a)/a²
  if (a2 < kSeriesAngle * kSeriesAngle) {
    s = series(kSinc, a2);
    c = series(kCosc, a2);
  } else {
    const double a = std::sqrt(a2);
    s = std::sin(a) / a;
    c = (1.0 - std::cos(a)) / a2;
  }
  return identity_plus(phi, a2, s, c);
}

Vec3 rotation_vector(const Mat3& r) {
  const double cos_a = std::clamp(0.5 * (r.trace() - 1.0), -1.0, 1.0);
  const Vec3 w(r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1));  // 2 sin a n
  const double sin_a2 = 0.25 * w.squaredNorm();
  if (cos_a > 0.0 && sin_a2 < kAsinSeriesSine * kAsinSeriesSine) return 0.5 * series(kAsinOverSin, sin_a2) * w;
  const double sin_a = std::sqrt(sin_a2);
  const double a = std::atan2(sin_a, cos_a);
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
  double b, c;  // (1 − cos a)/a², (a − sin a)/a³
  if (a2 < kSeriesAngle * kSeriesAngle) {
    b = series(kCosc, a2);
    c = series(kSincResidual, a2);
  } else {
    const double a = std::sqrt(a2);
    b = (1.0 - std::cos(a)) / a2;
    c = (a - std::sin(a)) / (a2 * a);
  }
  return identity_plus(phi, a2, -b, c);
}

Mat3 right_jacobian_inverse(const Vec3& phi) {
  const double a2 = phi.squaredNorm();
  double d;  // 1/a² − (1 + cos a)/(2 a sin a)
  if (a2 < kSeriesAngle * kSeriesAngle) {
    d = series(kJacobianInverse, a2);
  } else {
    const double a = std::sqrt(a2);
    d = 1.0 / a2 - (1.0 + std::cos(a)) / (2.0 * a * std::sin(a));
  }
  return identity_plus(phi, a2, 0.5, d);
}

Vec3 wiener_milenkovic(const Mat3& r) {
  const Vec3 phi = rotation_vector(r);
  const double a = phi.norm();
  if (a < 1e-4) return phi * (1.0 + a * a / 48.0);  // 4 tan(a/4)/a ≈ 1 + a²/48, next term < 1e-19
  return 4.0 * std::tan(0.25 * a) / a * phi;
}

}  // namespace fowtsim
