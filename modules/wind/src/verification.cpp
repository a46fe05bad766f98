#include "fowtsim/wind/verification.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include <Eigen/Dense>

#include "fowtsim/core/error.hpp"
#include "fowtsim/wind/turbulence_generator.hpp"

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

double iec_event_worst_deviation(WindEventType type, int sign, double direction_deg) {
  constexpr double pi = std::numbers::pi, d = 126.0, hub = 90.0, alpha = 0.2, start = 5.0, lambda1 = 42.0;
  const double v = type == WindEventType::ECD ? 10.0 : 12.0;
  WindParams p;
  p.model = WindModel::power_law;
  p.speed_m_s = v;
  p.reference_height_m = hub;
  p.shear_exponent = alpha;
  p.direction_deg = direction_deg;
  p.event = {type, start, sign, d, 1, TurbulenceCategory::B};
  const WindField field(p);
  // IEC 61400-1 ed. 3 §6.3.2 written out: σ1 (NTM, I_ref 0.14), V_e1 = 0.8 · 1.4 · 50 m/s.
  const double sigma1 = 0.14 * (0.75 * v + 5.6), size = 1.0 + 0.1 * d / lambda1;
  const double v_gust = std::min(1.35 * (56.0 - v), 3.3 * sigma1 / size);
  const double theta_e = sign * 4.0 * std::atan(sigma1 / (v * size)), theta_cg = sign * 720.0 / v * pi / 180.0;
  const double ews = sign * (2.5 + 0.2 * 6.4 * sigma1 * std::pow(d / lambda1, 0.25));
  const Vec3 points[] = {{0, 0, hub}, {0, 0, hub + d / 2}, {0, 0, hub - d / 2}, {0, d / 2, hub}, {0, -d / 2, hub}};
  double worst = 0.0;
  for (int k = 0; k <= 400; ++k) {
    const double t = 0.075 * k, tau = t - start;
    for (const Vec3& x : points) {
      const double psi0 = direction_deg * pi / 180.0;
      const double y = x.x() * std::sin(psi0) + x.y() * std::cos(psi0);  // wind-frame lateral coordinate
      double speed = v * std::pow(x.z() / hub, alpha), turn = 0.0;
      if (tau >= 0.0) switch (type) {
          case WindEventType::EOG:
            if (tau <= 10.5) speed -= 0.37 * v_gust * std::sin(3 * pi * tau / 10.5) * (1 - std::cos(2 * pi * tau / 10.5));
            break;
          case WindEventType::EDC: turn = tau <= 6.0 ? 0.5 * theta_e * (1 - std::cos(pi * tau / 6.0)) : theta_e; break;
          case WindEventType::ECD:
            speed += tau <= 10.0 ? 0.5 * 15.0 * (1 - std::cos(pi * tau / 10.0)) : 15.0;
            turn = tau <= 10.0 ? 0.5 * theta_cg * (1 - std::cos(pi * tau / 10.0)) : theta_cg;
            break;
          case WindEventType::EWS_vertical:
            if (tau <= 12.0) speed += (x.z() - hub) / d * ews * (1 - std::cos(2 * pi * tau / 12.0));
            break;
          case WindEventType::EWS_horizontal:
            if (tau <= 12.0) speed += y / d * ews * (1 - std::cos(2 * pi * tau / 12.0));
            break;
          case WindEventType::none: break;
        }
      const double psi = psi0 + turn;
      worst = std::max(worst, (field.velocity(x, t) - speed * Vec3(std::cos(psi), -std::sin(psi), 0.0)).norm() / v);
    }
  }
  return worst;
}

EwmHubSigma ewm_hub_sigma(int seeds) {
  EwmHubSigma r;
  double sum = 0.0, square_sum = 0.0;
  for (int seed = 1; seed <= seeds; ++seed) {
    WindParams p = small_turbulent_field(static_cast<std::uint64_t>(seed));
    p.turbulence.model = TurbulenceModel::EWM;
    p.speed_m_s = 40.0;
    p.turbulence.ny = 3;  // node (1, 1) is the hub: y = 0, z = 90 m
    p.turbulence.width_m = 40.0;
    const GeneratedTurbulence g = generate_turbulence(p);
    r.record_sigma_m_s = g.stats.expected_sigma_m_s[0];
    r.iec_sigma_m_s = g.stats.iec_sigma_m_s[0];
    const double sigma = grid_point_statistics(g.field, 1, 1).sigma_m_s[0];
    sum += sigma * sigma;
    square_sum += sigma * sigma * sigma * sigma;
  }
  const double n = seeds;
  r.mean_variance_m2_s2 = sum / n;
  r.standard_error_m2_s2 = std::sqrt((square_sum / n - r.mean_variance_m2_s2 * r.mean_variance_m2_s2) / (n - 1.0));
  return r;
}

}  // namespace fowtsim::wind::verification
