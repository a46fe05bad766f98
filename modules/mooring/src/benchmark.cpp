#include "fowtsim/mooring/benchmark.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/mooring/presets.hpp"
#include "fowtsim/mooring/quasi_static_mooring.hpp"
#include "fowtsim/mooring/stiffness.hpp"

namespace fowtsim::mooring {
namespace {

using Clock = std::chrono::steady_clock;
constexpr int kSteps = 1200;  // 60 s at 0.05 s

QuasiStaticMooring::Input pose_at(int step) {
  const double t = 0.05 * step, deg = std::numbers::pi / 180.0;
  const double wave = std::sin(2.0 * std::numbers::pi * t / 10.0), slow = std::sin(2.0 * std::numbers::pi * t / 60.0);
  QuasiStaticMooring::Input u;
  u.platform.position_m = Vec3(10.0 + 4.0 * slow + 0.5 * wave, 0.3 * wave, 0.5 * wave);
  u.platform.orientation = euler123_to_matrix(Vec3(0.5 * deg * wave, (3.0 + 2.0 * wave) * deg, 2.0 * deg * slow));
  u.time_s = t;
  return u;
}

template <class Call>
MooringBenchRow time_calls(const char* name, int repeats, std::size_t line_count, Call&& call) {
  double sink = 0.0;
  long iterations = 0;
  for (int k = 0; k < kSteps; ++k) sink += call(pose_at(k), iterations);  // untimed warm-up pass
  iterations = 0;
  const auto start = Clock::now();
  for (int r = 0; r < repeats; ++r) {
    for (int k = 0; k < kSteps; ++k) sink += call(pose_at(k), iterations);
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  MooringBenchRow row;
  row.case_name = name;
  row.calls = repeats * kSteps;
  row.microseconds_per_call = 1e6 * seconds / row.calls;
  volatile double keep = sink;  // the timed results are used, so the calls cannot be optimised away
  (void)keep;
  row.iterations_per_line = static_cast<double>(iterations) / (row.calls * static_cast<double>(line_count));
  return row;
}

long line_iterations(const QuasiStaticMooring::Output& y) {
  long n = 0;
  for (std::size_t i = 0; i < y.line_count; ++i) n += y.lines[i].iterations;
  return n;
}

}  // namespace

std::vector<MooringBenchRow> bench_mooring(int repeats) {
  const MooringParams oc3 = oc3_hywind_mooring();
  const MooringParams taut = seed_taut_mooring(-93.2, 4.7, 4.0e5);
  std::vector<MooringBenchRow> rows;
  QuasiStaticMooring::State warm = QuasiStaticMooring::make_state(oc3);
  rows.push_back(time_calls("oc3 catenary (3 lines), warm start", repeats, 3, [&](const auto& u, long& it) {
    const auto y = QuasiStaticMooring::evaluate(oc3, u, warm);
    it += line_iterations(y);
    return y.force_N.x();
  }));
  const QuasiStaticMooring::State cold_state = QuasiStaticMooring::make_state(oc3);
  rows.push_back(time_calls("oc3 catenary (3 lines), cold start", repeats, 3, [&](const auto& u, long& it) {
    QuasiStaticMooring::State cold = cold_state;
    const auto y = QuasiStaticMooring::evaluate(oc3, u, cold);
    it += line_iterations(y);
    return y.force_N.x();
  }));
  rows.push_back(time_calls("oc3 solve + analytic 6x6 stiffness, warm", repeats, 3, [&](const auto& u, long&) {
    QuasiStaticMooring::evaluate(oc3, u, warm);
    return linearized_stiffness(oc3, u, warm)(0, 0);
  }));
  QuasiStaticMooring::State taut_state = QuasiStaticMooring::make_state(taut);
  rows.push_back(time_calls("seed taut springs (4 lines)", repeats, 4, [&](const auto& u, long&) {
    return QuasiStaticMooring::evaluate(taut, u, taut_state).force_N.x();
  }));
  return rows;
}

}  // namespace fowtsim::mooring
