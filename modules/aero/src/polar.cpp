#include "fowtsim/aero/polar.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <utility>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/interpolation.hpp"
#include "fowtsim/core/spline.hpp"

namespace fowtsim::aero {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

[[noreturn]] void bad_table(const std::string& name, const std::string& what) {
  throw InputError({"aero", std::nullopt, fmt::format("aero.airfoils[{}].polar", name),
                    "transcribe the full ±180° table from the airfoil file"},
                   fmt::format("airfoil '{}': {}", name, what));
}

}  // namespace

double wrap_angle(double angle_rad) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  // Already in [−π, π) (the induction solver's angles): fmod of a value in [0, 2π) is that value,
  // so skipping it gives the same bits.
  const double shifted = angle_rad + std::numbers::pi;
  if (shifted >= 0.0 && shifted < two_pi) return shifted - std::numbers::pi;
  double a = std::fmod(shifted, two_pi);
  if (a < 0.0) a += two_pi;
  return a - std::numbers::pi;
}

Polar::Polar(std::string name, const std::vector<double>& alpha_deg, std::vector<double> cl,
             std::vector<double> cd, std::vector<double> cm, PolarInterpolation interpolation)
    : name_(std::move(name)), interpolation_(interpolation), cl_(std::move(cl)), cd_(std::move(cd)),
      cm_(std::move(cm)) {
  const std::size_t n = alpha_deg.size();
  if (n < 2) bad_table(name_, fmt::format("{} rows (expected at least 2)", n));
  if (cl_.size() != n || cd_.size() != n || cm_.size() != n) {
    bad_table(name_, fmt::format("column sizes differ (alpha {}, cl {}, cd {}, cm {})", n, cl_.size(),
                                 cd_.size(), cm_.size()));
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(alpha_deg[i]) || !std::isfinite(cl_[i]) || !std::isfinite(cd_[i]) ||
        !std::isfinite(cm_[i])) {
      bad_table(name_, fmt::format("row {} has a non-finite entry", i + 1));
    }
    if (cd_[i] < 0.0) bad_table(name_, fmt::format("row {}: cd = {} (expected >= 0)", i + 1, cd_[i]));
    if (i > 0 && !(alpha_deg[i] > alpha_deg[i - 1])) {
      bad_table(name_, fmt::format("alpha_deg not strictly increasing at row {}", i + 1));
    }
  }
  if (std::abs(alpha_deg.front() + 180.0) > 1e-6 || std::abs(alpha_deg.back() - 180.0) > 1e-6) {
    bad_table(name_, fmt::format("alpha_deg spans [{}, {}] (expected exactly [-180, 180])",
                                 alpha_deg.front(), alpha_deg.back()));
  }
  alpha_.resize(n);
  for (std::size_t i = 0; i < n; ++i) alpha_[i] = alpha_deg[i] * kDegree;
  if (interpolation_ == PolarInterpolation::cubic_spline) {
    cl2_ = natural_spline_second_derivatives(alpha_, cl_);
    cd2_ = natural_spline_second_derivatives(alpha_, cd_);
    cm2_ = natural_spline_second_derivatives(alpha_, cm_);
  }
  // Uniform cells no wider than the narrowest table interval, each with the interval holding the
  // start of the cell before it: a lookup steps forward from there (at most a few rows) instead
  // of a binary search over the table, and finds the same interval as bracket_index().
  double narrowest = 2.0 * std::numbers::pi;
  for (std::size_t i = 0; i + 1 < n; ++i) narrowest = std::min(narrowest, alpha_[i + 1] - alpha_[i]);
  const int cells = static_cast<int>(std::min(4096.0, std::ceil(2.0 * std::numbers::pi / narrowest)));
  cells_per_rad_ = cells / (2.0 * std::numbers::pi);
  interval_of_cell_.resize(cells);
  for (int c = 0; c < cells; ++c)
    interval_of_cell_[c] = static_cast<int>(
        bracket_index(std::span<const double>(alpha_), -std::numbers::pi + (c - 1) / cells_per_rad_));
  separation_ = derive_separation(*this);
}

std::size_t Polar::interval(double a) const {
  // The cell of a, clamped (a NaN takes cell 0); the hint is at or below the interval of a (its
  // cell may come out one too high by rounding: the hint is that of the cell before).
  const double t = (a + std::numbers::pi) * cells_per_rad_;
  const int cells = static_cast<int>(interval_of_cell_.size());
  const int c = t >= 0.0 ? (t < cells ? static_cast<int>(t) : cells - 1) : 0;
  std::size_t i = static_cast<std::size_t>(interval_of_cell_[c]);
  const std::size_t last = alpha_.size() - 2;
  while (i < last && alpha_[i + 1] <= a) ++i;
  return i;
}

AirfoilCoefficients Polar::evaluate(double alpha_rad) const {
  const double a = wrap_angle(alpha_rad);
  const std::size_t i = interval(a);
  if (interpolation_ == PolarInterpolation::cubic_spline) {
    return {natural_spline_value(alpha_, cl_, cl2_, i, a), natural_spline_value(alpha_, cd_, cd2_, i, a),
            natural_spline_value(alpha_, cm_, cm2_, i, a)};
  }
  const double s = (a - alpha_[i]) / (alpha_[i + 1] - alpha_[i]);
  return {lerp(cl_[i], cl_[i + 1], s), lerp(cd_[i], cd_[i + 1], s), lerp(cm_[i], cm_[i + 1], s)};
}

}  // namespace fowtsim::aero
