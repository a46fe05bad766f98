#include "fowtsim/wind/benchmarks.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <numbers>

#include "fowtsim/wind/turbulence_generator.hpp"
#include "fowtsim/wind/wind_field.hpp"

namespace fowtsim::wind {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Times `lookups` queries at points on a 60-m circle about the hub, 0.01 s apart in time.
WindBenchRow time_lookups(const WindField& field, const std::string& name, int lookups) {
  const double hub = field.params().reference_height_m;
  double checksum = 0.0;
  const std::clock_t cpu_start = std::clock();
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < lookups; ++k) {
    const double angle = 0.37 * k;
    const Vec3 p(0.0, 60.0 * std::sin(angle), hub + 60.0 * std::cos(angle));
    checksum += field.velocity(p, 0.01 * (k % 50000)).x();
  }
  const double wall = seconds_since(start);
  const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return {name, wall, cpu, 1e6 * wall / lookups, "mean u over the calls " + std::to_string(checksum / lookups) + " m/s"};
}

}  // namespace

std::vector<WindBenchRow> bench_wind(double duration_fraction, int lookups) {
  WindParams p;
  p.model = WindModel::turbulent;
  p.speed_m_s = 12.0;
  p.reference_height_m = 90.0;
  p.shear_exponent = 0.2;
  p.turbulence.category = TurbulenceCategory::B;
  p.turbulence.model = TurbulenceModel::NTM;
  p.turbulence.ny = p.turbulence.nz = 31;
  p.turbulence.width_m = p.turbulence.height_m = 145.0;
  p.turbulence.dt_s = 0.05;
  p.turbulence.duration_s = 630.0 * duration_fraction;
  p.turbulence.seed = 13428;

  std::vector<WindBenchRow> rows;
  {  // the same field without TurbSim's tower points (grid bit-identical): the tower's cost by difference
    WindParams bare = p;
    bare.turbulence.tower_points = false;
    const std::clock_t cpu_start = std::clock();
    const auto start = std::chrono::steady_clock::now();
    const GeneratedTurbulence g = generate_turbulence(bare);
    const double wall = seconds_since(start);
    const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    rows.push_back({"generate 31x31 without tower points", wall, cpu, 0.0, "grid only (TurbulenceParams::tower_points = false)"});
  }
  const std::clock_t cpu_start = std::clock();
  const auto start = std::chrono::steady_clock::now();
  GeneratedTurbulence generated = generate_turbulence(p);
  const double wall = seconds_since(start);
  const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const TurbulenceStats& s = generated.stats;
  char duration[32];
  std::snprintf(duration, sizeof duration, "%g", p.turbulence.duration_s);
  rows.push_back({"generate 31x31, " + std::string(duration) + " s at 20 Hz (IEC NTM B, 12 m/s)",
                  wall, cpu, 0.0,
                  std::to_string(s.frequencies) + " frequencies: " + std::to_string(s.dense_frequencies) +
                      " dense Cholesky, " + std::to_string(s.embedding_frequencies) + " circulant embedding, " +
                      std::to_string(s.independent_frequencies) + " independent (max dropped coherence " +
                      std::to_string(s.max_dropped_coherence) + "); " + std::to_string(generated.field.n_tower) +
                      " tower points: " + std::to_string(s.tower_conditional_frequencies) + " conditional on the grid, " +
                      std::to_string(s.tower_independent_frequencies) + " independent"});

  const WindField turbulent(p, std::make_shared<const FullField>(std::move(generated.field)));
  rows.push_back(time_lookups(turbulent, "lookup in the full field (bilinear y-z, linear t)", lookups));
  WindParams shear;
  shear.model = WindModel::power_law;
  shear.speed_m_s = 12.0;
  const WindField power_law(shear);
  rows.push_back(time_lookups(power_law, "lookup in the power-law profile", lookups));
  return rows;
}

}  // namespace fowtsim::wind
