#include "fowtsim/wind/verification.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include <Eigen/Dense>

#include "fowtsim/core/error.hpp"

namespace fowtsim::wind::verification {

double sampler_coherence_error(CoherentSampler& sampler, int ny, double dy_m, double dz_m, double decay_per_m) {
  using Complex = std::complex<double>;
  const std::size_t n = sampler.point_count(), draws = sampler.draws();
  Eigen::MatrixXcd cov = Eigen::MatrixXcd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  std::vector<Complex> xi(draws), x(n);
  for (std::size_t l = 0; l < draws; ++l) {
    std::fill(xi.begin(), xi.end(), Complex(0.0, 0.0));
    xi[l] = 1.0;
    sampler.sample(xi, x);
    const Eigen::Map<Eigen::VectorXcd> v(x.data(), static_cast<Eigen::Index>(n));
    cov += v * v.adjoint();
  }
  double worst = 0.0;
  for (Eigen::Index j = 0; j < cov.rows(); ++j)
    for (Eigen::Index k = 0; k < cov.cols(); ++k) {
      const double r = std::hypot(static_cast<double>(j % ny - k % ny) * dy_m, static_cast<double>(j / ny - k / ny) * dz_m);
      worst = std::max(worst, std::abs(cov(j, k) - std::exp(-decay_per_m * r)));
    }
  return worst;
}

WindParams small_turbulent_field(std::uint64_t seed) {
  WindParams p;
  p.model = WindModel::turbulent;
  p.speed_m_s = 10.0;
  p.reference_height_m = 90.0;
  p.turbulence.category = TurbulenceCategory::A;
  p.turbulence.ny = 4;
  p.turbulence.nz = 3;
  p.turbulence.width_m = 60.0;   // dy = 20 m
  p.turbulence.height_m = 40.0;  // dz = 20 m
  p.turbulence.dt_s = 0.25;
  p.turbulence.duration_s = 600.0;
  p.turbulence.seed = seed;
  return p;
}

PointStatistics grid_point_statistics(const WindGrid& grid, int iy, int iz) {
  PointStatistics s;
  const double n = grid.nt;
  for (int c = 0; c < 3; ++c) {
    auto value = [&](int it) {
      return static_cast<double>(grid.grid[((static_cast<std::size_t>(it) * grid.nz + iz) * grid.ny + iy) * 3 + c]);
    };
    double mean = 0.0, variance = 0.0;
    for (int it = 0; it < grid.nt; ++it) mean += value(it) / n;
    for (int it = 0; it < grid.nt; ++it) variance += (value(it) - mean) * (value(it) - mean) / n;
    s.mean_m_s[c] = mean;
    s.sigma_m_s[c] = std::sqrt(variance);
  }
  return s;
}

std::array<double, 3> max_velocity_deviation(const WindField& field, const Vec3& point_m, const std::vector<double>& time_s,
                                             const std::array<std::vector<double>, 3>& reference) {
  for (const std::vector<double>& r : reference)
    if (r.size() != time_s.size()) {
      throw InputError({"wind.verification", std::nullopt, "reference", "give one reference value per time"},
                       "reference velocity history and times differ in length");
    }
  std::array<double, 3> worst{};
  for (std::size_t k = 0; k < time_s.size(); ++k) {
    const Vec3 v = field.velocity(point_m, time_s[k]);
    for (int c = 0; c < 3; ++c) worst[c] = std::max(worst[c], std::abs(v[c] - reference[c][k]));
  }
  return worst;
}

}  // namespace fowtsim::wind::verification
