#include "fowtsim/waves/precomputed_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "depth_factors.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/core/fft.hpp"
#include "fowtsim/core/interpolation.hpp"

namespace fowtsim::waves {
namespace {

// Quantities stored per sample (and per Wheeler level), in this order.
enum Quantity : std::size_t { kHorizontalVelocity, kVerticalVelocity, kHorizontalAcceleration,
                              kVerticalAcceleration, kDynamicPressure, kQuantities };

[[noreturn]] void bad_input(const std::string& variable, const std::string& message, const std::string& hint = {}) {
  throw InputError({"waves.precompute", std::nullopt, variable, hint}, message);
}

// Stretched level z' of a point at z under surface elevation η (Wheeler): h (z − η)/(h + η).
double wheeler_level(double z, double eta, double depth) {
  if (std::isinf(depth)) return z - eta;
  return depth * (z - eta) / (depth + eta);
}

// Levels from 0 down to below z_lowest (+2 for the cubic stencil), spacing max(Δ0, growth·|z'|),
// never below the seabed; returned ascending.
std::vector<double> make_wheeler_levels(double z_lowest, double depth, double top_spacing, double growth) {
  std::vector<double> levels{0.0};
  int below = 0;
  while (below < 2) {
    const double z = levels.back();
    if (z <= -depth) break;
    double next = z - std::max(top_spacing, growth * std::abs(z));
    if (next <= -depth) next = -depth;
    levels.push_back(next);
    if (next < z_lowest) ++below;
    if (levels.size() > 100000) bad_input("wheeler levels", "too many Wheeler levels", "raise wheeler_growth");
  }
  if (levels.size() < 4) {  // shallow column: four even levels over the whole depth
    levels = {0.0, -depth / 3.0, -2.0 * depth / 3.0, -depth};
  }
  std::reverse(levels.begin(), levels.end());
  return levels;
}

}  // namespace

PrecomputedKinematics::PrecomputedKinematics(const WaveField& field, std::span<const Vec3> points_m,
                                             const PrecomputeOptions& options)
    : direction_(field.direction()),
      depth_m_(field.depth_m()),
      stretching_(field.params().stretching),
      elevation_only_(options.elevation_only) {
  if (options.oversampling > 64)
    bad_input("oversampling", fmt::format("oversampling must be 0 (automatic) to 64, found {}", options.oversampling));
  if (!(std::isfinite(options.samples_per_shortest_period) && options.samples_per_shortest_period > 0.0 &&
        options.samples_per_shortest_period <= 64.0))
    bad_input("samples_per_shortest_period",
              fmt::format("expected 0 < value <= 64, found {}", options.samples_per_shortest_period));
  if (!(std::isfinite(options.wheeler_surface_spacing) && options.wheeler_surface_spacing > 0.0))
    bad_input("wheeler_surface_spacing", fmt::format("expected > 0, found {}", options.wheeler_surface_spacing));
  if (!(std::isfinite(options.wheeler_growth) && options.wheeler_growth > 0.0))
    bad_input("wheeler_growth", fmt::format("expected > 0, found {}", options.wheeler_growth));
  std::size_t oversampling = options.oversampling;
  if (oversampling == 0) {
    const double f_max = field.calm() ? 0.0 : field.components().back().omega_rad_s / (2.0 * std::numbers::pi);
    const double wanted = options.samples_per_shortest_period * f_max * field.record_dt_s();
    oversampling = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(wanted - 1e-9)));
  }
  samples_ = field.record_samples() * oversampling;
  if (samples_ > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    bad_input("oversampling", fmt::format("{} samples per series exceed the FFT size limit", samples_),
              "lower the oversampling or shorten the record");
  duration_s_ = field.record_duration_s();
  dt_s_ = duration_s_ / static_cast<double>(samples_);
  const double h = depth_m_;

  // Points, columns (distinct x, y) and the layout of storage_.
  std::map<std::pair<double, double>, std::size_t> column_of;
  std::vector<std::vector<std::size_t>> column_points;
  points_.reserve(points_m.size());
  for (std::size_t i = 0; i < points_m.size(); ++i) {
    const Vec3& p = points_m[i];
    if (!p.allFinite())
      bad_input(fmt::format("points[{}]", i), fmt::format("point {} has non-finite coordinates", i));
    Point point;
    point.position_m = p;
    if (p.z() < -h) {
      if (p.z() < -h - 1e-9 * std::max(1.0, h))
        bad_input(fmt::format("points[{}]", i),
                  fmt::format("point {} ({}, {}, {}) is below the seabed at z = {} m", i, p.x(), p.y(), p.z(), -h),
                  "points must lie at or above the seabed z = -depth_m");
      point.position_m.z() = -h;
    }
    const auto [it, inserted] = column_of.try_emplace({p.x(), p.y()}, columns_.size());
    if (inserted) {
      columns_.emplace_back();
      column_points.emplace_back();
    }
    point.column = it->second;
    column_points[point.column].push_back(i);
    points_.push_back(point);
  }

  const std::size_t n_comp = field.components().size();
  const auto components = field.components();
  std::optional<InverseRealFft> fft;
  if (!field.calm()) fft.emplace(samples_);
  std::vector<std::complex<double>> base(n_comp);        // A_n e^{−i k_n s} / 2 for one column
  std::vector<detail::DepthFactors> factors(n_comp);     // at one level
  const double rho_g = field.params().water_density_kg_m3 * field.params().gravity_m_s2;

  // One series per call: coefficients c_n = base_n · transfer_n, written with `stride`.
  const auto synthesise = [&](auto transfer, double* out, std::size_t stride) {
    if (!fft) {
      for (std::size_t j = 0; j < samples_; ++j) out[j * stride] = 0.0;
      return;
    }
    fft->clear();
    std::complex<double>* c = fft->coefficients();
    for (std::size_t n = 0; n < n_comp; ++n) c[components[n].harmonic] = base[n] * transfer(n);
    // A Nyquist component (a replayed record of even length, oversampling 1): c2r takes c_{M/2} once
    // and only its real part, exactly Re[T A e^{−iks} e^{iπj}] on the samples: undo the halving.
    if (2 * components.back().harmonic == samples_) c[samples_ / 2] *= 2.0;
    const double* y = fft->execute();
    for (std::size_t j = 0; j < samples_; ++j) out[j * stride] = y[j];
  };
  const auto all_quantities = [&](double* out, std::size_t stride) {
    using C = std::complex<double>;
    synthesise([&](std::size_t n) { return C(components[n].omega_rad_s * factors[n].cosh_over_sinh, 0.0); },
               out + kHorizontalVelocity, stride);
    synthesise([&](std::size_t n) { return C(0.0, components[n].omega_rad_s * factors[n].sinh_over_sinh); },
               out + kVerticalVelocity, stride);
    synthesise([&](std::size_t n) {
      const double om = components[n].omega_rad_s;
      return C(0.0, om * om * factors[n].cosh_over_sinh);
    }, out + kHorizontalAcceleration, stride);
    synthesise([&](std::size_t n) {
      const double om = components[n].omega_rad_s;
      return C(-om * om * factors[n].sinh_over_sinh, 0.0);
    }, out + kVerticalAcceleration, stride);
    synthesise([&](std::size_t n) { return C(rho_g * factors[n].cosh_over_cosh, 0.0); },
               out + kDynamicPressure, stride);
  };
  const auto set_factors = [&](double z) {
    for (std::size_t n = 0; n < n_comp; ++n)
      factors[n] = detail::depth_factors(components[n].wavenumber_rad_m, z, h);
  };

  // η per column first (Wheeler needs its range to place the levels).
  std::size_t total = columns_.size() * samples_;
  storage_.assign(total, 0.0);
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    const Vec3& p = points_[column_points[c].front()].position_m;
    const double s = p.x() * direction_.x() + p.y() * direction_.y();
    for (std::size_t n = 0; n < n_comp; ++n) {
      const double phase = -components[n].wavenumber_rad_m * s;
      base[n] = 0.5 * components[n].amplitude_m * std::complex<double>(std::cos(phase), std::sin(phase));
    }
    columns_[c].elevation_offset = c * samples_;
    synthesise([](std::size_t) { return std::complex<double>(1.0, 0.0); }, storage_.data() + c * samples_, 1);
  }
  if (elevation_only_) return;

  // Layout of the kinematics blocks.
  const double top_spacing = field.calm() ? 1.0 : options.wheeler_surface_spacing / field.highest_wavenumber_rad_m();
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    Column& column = columns_[c];
    if (stretching_ == Stretching::none) {
      for (std::size_t i : column_points[c]) {
        Point& point = points_[i];
        if (point.position_m.z() > 0.0) continue;  // always dry without stretching
        point.kind = PointKind::exact;
        point.offset = total;
        total += samples_ * kQuantities;
      }
    } else {
      const double eta_max = *std::max_element(storage_.begin() + static_cast<std::ptrdiff_t>(column.elevation_offset),
                                               storage_.begin() + static_cast<std::ptrdiff_t>(column.elevation_offset + samples_));
      double z_lowest = 0.0;
      bool any_wet = false;
      for (std::size_t i : column_points[c]) {
        const double z = points_[i].position_m.z();
        // Interpolated η can exceed the sample maximum slightly; the two extra levels cover it.
        if (z > eta_max) continue;
        any_wet = true;
        z_lowest = std::min(z_lowest, std::max(-h, wheeler_level(z, eta_max, h)));
        points_[i].kind = PointKind::wheeler;
      }
      if (!any_wet) continue;
      column.levels_m = make_wheeler_levels(z_lowest, h, top_spacing, options.wheeler_growth);
      column.level_offset = total;
      total += samples_ * column.levels_m.size() * kQuantities;
    }
  }
  storage_.resize(total, 0.0);
  storage_.shrink_to_fit();

  // Fill the kinematics blocks.
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    Column& column = columns_[c];
    const Vec3& p = points_[column_points[c].front()].position_m;
    const double s = p.x() * direction_.x() + p.y() * direction_.y();
    for (std::size_t n = 0; n < n_comp; ++n) {
      const double phase = -components[n].wavenumber_rad_m * s;
      base[n] = 0.5 * components[n].amplitude_m * std::complex<double>(std::cos(phase), std::sin(phase));
    }
    if (stretching_ == Stretching::none) {
      for (std::size_t i : column_points[c]) {
        const Point& point = points_[i];
        if (point.kind != PointKind::exact) continue;
        set_factors(point.position_m.z());
        all_quantities(storage_.data() + point.offset, kQuantities);
      }
    } else {
      const std::size_t levels = column.levels_m.size();
      for (std::size_t l = 0; l < levels; ++l) {
        set_factors(column.levels_m[l]);
        all_quantities(storage_.data() + column.level_offset + l * kQuantities, levels * kQuantities);
      }
    }
  }
}

std::size_t PrecomputedKinematics::wheeler_levels(std::size_t index) const {
  return columns_.at(points_.at(index).column).levels_m.size();
}

double PrecomputedKinematics::interpolate_elevation(const Column& column, const PeriodicStencil& ts) const {
  const double* eta = storage_.data() + column.elevation_offset;
  return ts.weight[0] * eta[ts.index[0]] + ts.weight[1] * eta[ts.index[1]] + ts.weight[2] * eta[ts.index[2]] +
         ts.weight[3] * eta[ts.index[3]];
}

double PrecomputedKinematics::elevation(std::size_t index, double t) const { return elevation(index, stencil(t)); }

double PrecomputedKinematics::elevation(std::size_t index, const PeriodicStencil& ts) const {
  const Point& point = points_.at(index);
  return interpolate_elevation(columns_[point.column], ts);
}

WaveKinematics PrecomputedKinematics::at(std::size_t index, double t) const { return at(index, stencil(t)); }

WaveKinematics PrecomputedKinematics::at(std::size_t index, const PeriodicStencil& ts) const {
  const Point& point = points_.at(index);
  const Column& column = columns_[point.column];
  WaveKinematics out;
  out.elevation_m = interpolate_elevation(column, ts);
  double q[kQuantities] = {0.0, 0.0, 0.0, 0.0, 0.0};

  if (point.kind == PointKind::dry) {
    return out;
  } else if (point.kind == PointKind::exact) {
    const double* data = storage_.data() + point.offset;
    for (int a = 0; a < 4; ++a) {
      const double* row = data + ts.index[a] * kQuantities;
      for (std::size_t k = 0; k < kQuantities; ++k) q[k] += ts.weight[a] * row[k];
    }
  } else {
    const double z = point.position_m.z();
    const double eta = out.elevation_m;
    // Dry above the surface; a trough at or below the seabed leaves no water column (dry too).
    if (z > eta || !(depth_m_ + eta > 0.0)) return out;
    const double zp = std::clamp(wheeler_level(z, eta, depth_m_), -depth_m_, 0.0);
    const std::vector<double>& lv = column.levels_m;
    const std::size_t levels = lv.size();
    // Stencil of 4 levels around zp (one-sided at the ends).
    const auto upper = static_cast<std::size_t>(std::upper_bound(lv.begin(), lv.end(), zp) - lv.begin());
    const std::size_t first = std::min(upper >= 2 ? upper - 2 : 0, levels - 4);
    double wz[4];
    for (int b = 0; b < 4; ++b) {
      double w = 1.0;
      for (int c = 0; c < 4; ++c)
        if (c != b) w *= (zp - lv[first + c]) / (lv[first + b] - lv[first + c]);
      wz[b] = w;
    }
    const double* data = storage_.data() + column.level_offset;
    for (int a = 0; a < 4; ++a) {
      const double* sample = data + (ts.index[a] * levels + first) * kQuantities;
      for (int b = 0; b < 4; ++b) {
        const double w = ts.weight[a] * wz[b];
        const double* row = sample + static_cast<std::size_t>(b) * kQuantities;
        for (std::size_t k = 0; k < kQuantities; ++k) q[k] += w * row[k];
      }
    }
  }
  out.wetted = true;
  out.velocity_m_s = Vec3(direction_.x() * q[kHorizontalVelocity], direction_.y() * q[kHorizontalVelocity],
                          q[kVerticalVelocity]);
  out.acceleration_m_s2 = Vec3(direction_.x() * q[kHorizontalAcceleration],
                               direction_.y() * q[kHorizontalAcceleration], q[kVerticalAcceleration]);
  out.dynamic_pressure_Pa = q[kDynamicPressure];
  return out;
}

}  // namespace fowtsim::waves
