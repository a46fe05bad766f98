#include <chrono>
#include <cmath>
#include <limits>

#include "fowtsim/beam/benchmarks.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::beam::benchmarks {
namespace {

constexpr double kEndTime = 0.0064;  // seed §2.5.1

// Node positions at kEndTime, or empty if the run broke down.
VecX strip_positions(const BeamModel& model, const DynamicOptions& options, double dt, double& wall) {
  const auto start = std::chrono::steady_clock::now();
  BeamState state = make_state(model);
  BeamInput in;
  in.tip_load[3] = steel_strip_rollup_moment();
  DynamicStepper stepper(model, options);
  const int steps = static_cast<int>(std::lround(kEndTime / dt));
  try {
    for (int k = 0; k < steps; ++k) stepper.step(in, dt, state);
  } catch (const NumericalError&) {
    return VecX();
  }
  wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  VecX x(3 * model.node_count());
  for (int n = 0; n < model.node_count(); ++n) x.segment<3>(3 * n) = state.position_m[n];
  return x;
}

double rms_per_node(const VecX& v) { return std::sqrt(v.squaredNorm() / (v.size() / 3)); }

}  // namespace

std::vector<TimeStepRow> strip_time_step_study(int segments, const DynamicOptions& options,
                                               const std::vector<double>& dts, double reference_dt) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const BeamModel model = discretise(steel_strip(), segments);
  VecX undeformed(3 * model.node_count());
  for (int n = 0; n < model.node_count(); ++n) undeformed.segment<3>(3 * n) = model.nodes[n].position_m;
  double wall = 0.0;
  const VecX ref = strip_positions(model, options, reference_dt, wall);
  if (ref.size() == 0)
    throw NumericalError({"beam", std::nullopt, "reference run", "use a smaller reference step"},
                         "the reference run of the time-step study broke down");
  std::vector<TimeStepRow> rows;
  std::vector<VecX> solutions;
  for (double dt : dts) {
    TimeStepRow row;
    row.dt_s = dt;
    solutions.push_back(strip_positions(model, options, dt, row.wall_s));
    row.failed = solutions.back().size() == 0;
    row.rms_vs_reference = row.failed ? nan : rms_per_node(solutions.back() - ref);
    row.relative = row.rms_vs_reference / rms_per_node(ref - undeformed);
    rows.push_back(row);
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const bool pair = i + 1 < rows.size() && !rows[i].failed && !rows[i + 1].failed;
    rows[i].rms_vs_half = pair ? rms_per_node(solutions[i] - solutions[i + 1]) : nan;
  }
  for (std::size_t i = 0; i < rows.size(); ++i)
    rows[i].order = i + 1 < rows.size() ? std::log2(rows[i].rms_vs_half / rows[i + 1].rms_vs_half) : nan;
  return rows;
}

}  // namespace fowtsim::beam::benchmarks
