#include "fowtsim/waves/benchmarks.hpp"

#include <chrono>
#include <cmath>

#include "fowtsim/waves/precomputed_kinematics.hpp"
#include "fowtsim/waves/wave_field.hpp"

namespace fowtsim::waves::benchmarks {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

WaveParams three_hour_jonswap() {
  WaveParams p;
  p.model = WaveModel::jonswap;
  p.hs_m = 6.0;
  p.tp_s = 10.0;
  p.gamma = 3.3;
  p.duration_s = 10800.0;
  p.dt_s = 0.25;
  p.depth_m = 320.0;
  p.seed = 1;
  return p;
}

std::vector<Vec3> spar_points(std::size_t count) {
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < count; ++i) {
    const double z = count == 1 ? 0.0 : -120.0 + 120.0 * static_cast<double>(i) / static_cast<double>(count - 1);
    points.emplace_back(0.0, 0.0, z);
  }
  return points;
}

std::vector<SynthesisRow> synthesis_cost(const WaveParams& params, const std::vector<std::size_t>& point_counts) {
  std::vector<SynthesisRow> rows;
  for (Stretching stretching : {Stretching::none, Stretching::wheeler}) {
    WaveParams p = params;
    p.stretching = stretching;
    for (std::size_t count : point_counts) {
      SynthesisRow row;
      row.stretching = stretching;
      row.points = count;
      auto start = std::chrono::steady_clock::now();
      const WaveField field(p);
      row.field_s = seconds_since(start);
      const std::vector<Vec3> points = spar_points(count);
      start = std::chrono::steady_clock::now();
      const PrecomputedKinematics pre(field, points);
      row.precompute_s = seconds_since(start);
      row.memory_MB = static_cast<double>(pre.memory_bytes()) / 1e6;
      rows.push_back(row);
    }
  }
  return rows;
}

std::vector<LookupRow> lookup_cost(const WaveParams& params, std::size_t points, std::size_t steps) {
  std::vector<LookupRow> rows;
  const double dt = 0.05;  // off the record grid (0.25 s): every lookup interpolates
  for (Stretching stretching : {Stretching::none, Stretching::wheeler}) {
    WaveParams p = params;
    p.stretching = stretching;
    const WaveField field(p);
    const std::vector<Vec3> xyz = spar_points(points);
    const PrecomputedKinematics pre(field, xyz);
    LookupRow row;
    row.stretching = stretching;
    row.components = field.components().size();

    volatile double sink = 0.0;
    auto start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < steps; ++k) {
      const double t = 100.0 + dt * static_cast<double>(k);
      for (std::size_t i = 0; i < points; ++i) sink = sink + pre.at(i, t).velocity_m_s.x();
    }
    row.precomputed_ns = seconds_since(start) * 1e9 / static_cast<double>(steps * points);

    const std::size_t direct_steps = std::max<std::size_t>(1, steps / 100);
    double max_diff = 0.0, sum_sq = 0.0;
    start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < direct_steps; ++k) {
      const double t = 100.0 + dt * static_cast<double>(k);
      for (std::size_t i = 0; i < points; ++i) {
        const WaveKinematics d = field.evaluate(xyz[i], t);
        sink = sink + d.velocity_m_s.x();
        max_diff = std::max(max_diff, (pre.at(i, t).velocity_m_s - d.velocity_m_s).norm());
        sum_sq += d.velocity_m_s.squaredNorm();
      }
    }
    // The lookups inside the loop are ~1e-4 of its time; not subtracted.
    row.direct_ns = seconds_since(start) * 1e9 / static_cast<double>(direct_steps * points);
    row.max_velocity_difference_m_s = max_diff;
    row.velocity_rms_m_s = std::sqrt(sum_sq / static_cast<double>(direct_steps * points));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace fowtsim::waves::benchmarks
