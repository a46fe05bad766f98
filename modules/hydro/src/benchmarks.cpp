#include "fowtsim/hydro/benchmarks.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <Eigen/Geometry>
#include <numbers>

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/hydro/oc3.hpp"

namespace fowtsim::hydro::benchmarks {
namespace {

using Clock = std::chrono::steady_clock;

double micros(Clock::duration d, int repeats) {
  return std::chrono::duration<double, std::micro>(d).count() / repeats;
}

FrameMotion pitched(double pitch_rad) {
  FrameMotion pose;
  pose.orientation = euler123_to_matrix(Vec3(0.0, pitch_rad, 0.0));
  return pose;
}

// Morison load history over one wave period (n_time samples) for a given strip refinement.
std::vector<Vec6> morison_history(const Params& params, const FrameMotion& pose, const DeepWaterAiry& wave,
                                  int n_time) {
  Hydro::Input in = make_input(params);
  in.platform = pose;
  Points points(3, node_count(params));
  strip_points(params, pose, in.surface_elevation_m, points);
  std::vector<Vec6> history;
  for (int i = 0; i < n_time; ++i) {
    fill_kinematics(wave, wave.period_s * i / n_time, points, in);
    history.push_back(Hydro::outputs(params, in, {}).morison);
  }
  return history;
}

// max_t |a − b| / max_t |b| for the force (head) and moment (tail) of two load histories.
std::pair<double, double> history_error(const std::vector<Vec6>& a, const std::vector<Vec6>& b) {
  double df = 0.0, dm = 0.0, f = 0.0, m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    df = std::max(df, (a[i] - b[i]).head<3>().norm());
    dm = std::max(dm, (a[i] - b[i]).tail<3>().norm());
    f = std::max(f, b[i].head<3>().norm());
    m = std::max(m, b[i].tail<3>().norm());
  }
  return {df / f, dm / m};
}

BenchRow morison_row(const std::string& name, const FrameMotion& pose, int repeats) {
  const DeepWaterAiry wave{3.0, 10.0};
  const Params coarse = oc3_hywind_params();
  Params fine = coarse;
  for (MemberParams& m : fine.members) m.strips *= 4;
  const auto [ef, em] = history_error(morison_history(coarse, pose, wave, 40), morison_history(fine, pose, wave, 40));
  BenchRow row{name, node_count(coarse), coarse.hydrostatic_quadrature_points, 0.0, 0.0, ef, em,
               "4x strips per member"};
  Hydro::Input in = make_input(coarse);
  in.platform = pose;
  Points points(3, node_count(coarse));
  strip_points(coarse, pose, in.surface_elevation_m, points);
  fill_kinematics(wave, 1.3, points, in);
  volatile double sink = 0.0;  // keeps the timed calls from being optimised away
  auto t0 = Clock::now();
  for (int i = 0; i < repeats; ++i) {
    in.platform.position_m.x() = 1e-9 * (i & 1);
    sink = sink + Hydro::outputs(coarse, in, {}).total[0];
  }
  row.us_per_call = micros(Clock::now() - t0, repeats);
  t0 = Clock::now();
  for (int i = 0; i < repeats; ++i) {
    FrameMotion p = pose;
    p.position_m.x() = 1e-9 * (i & 1);
    strip_points(coarse, p, in.surface_elevation_m, points);
    sink = sink + points(0, 0);
  }
  row.us_per_strip_points = micros(Clock::now() - t0, repeats);
  return row;
}

BenchRow hydrostatic_row(int repeats) {
  const FrameMotion pose = pitched(10.0 * std::numbers::pi / 180.0);
  const Params coarse = oc3_hywind_params();
  Params fine = coarse;
  fine.hydrostatic_quadrature_points = std::min(64, 4 * coarse.hydrostatic_quadrature_points);
  Hydro::Input in = make_input(coarse);
  in.platform = pose;
  const Vec6 a = Hydro::outputs(coarse, in, {}).buoyancy;
  Hydro::Input in_fine = make_input(fine);
  in_fine.platform = pose;
  const Vec6 b = Hydro::outputs(fine, in_fine, {}).buoyancy;
  BenchRow row{"hydrostatics, 10 deg pitch", node_count(coarse), coarse.hydrostatic_quadrature_points,
               0.0, 0.0, (a - b).head<3>().norm() / b.head<3>().norm(),
               (a - b).tail<3>().norm() / b.tail<3>().norm(), "4x Gauss points (max 64)"};
  volatile double sink = 0.0;
  const auto t0 = Clock::now();
  for (int i = 0; i < repeats; ++i) {
    in.platform.position_m.x() = 1e-9 * (i & 1);
    sink = sink + Hydro::outputs(coarse, in, {}).total[0];
  }
  row.us_per_call = micros(Clock::now() - t0, repeats);
  return row;
}

}  // namespace

double DeepWaterAiry::omega() const { return 2.0 * std::numbers::pi / period_s; }
double DeepWaterAiry::wavenumber() const { return omega() * omega() / gravity_m_s2; }

void fill_kinematics(const DeepWaterAiry& wave, double t, const Points& points, Hydro::Input& in) {
  const double w = wave.omega(), k = wave.wavenumber(), a = wave.amplitude_m;
  for (Eigen::Index j = 0; j < points.cols(); ++j) {
    const Vec3 p = points.col(j);
    const double decay = std::exp(k * std::min(p.z(), 0.0));
    const double theta = k * p.x() - w * t;
    const double c = std::cos(theta), s = std::sin(theta);
    in.fluid_velocity_m_s.col(j) = a * w * decay * Vec3(c, 0.0, s);
    in.fluid_acceleration_m_s2.col(j) = a * w * w * decay * Vec3(s, 0.0, -c);
    in.dynamic_pressure_Pa[j] = wave.water_density_kg_m3 * wave.gravity_m_s2 * a * decay * c;
  }
}

std::vector<BenchRow> oc3_bench(int repeats) {
  return {morison_row("Morison, upright, H 6 m T 10 s", FrameMotion{}, repeats),
          morison_row("Morison, 10 deg pitch, H 6 m T 10 s", pitched(10.0 * std::numbers::pi / 180.0), repeats),
          hydrostatic_row(repeats)};
}

}  // namespace fowtsim::hydro::benchmarks
