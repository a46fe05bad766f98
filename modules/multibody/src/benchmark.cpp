#include "fowtsim/multibody/benchmark.hpp"

#include <chrono>
#include <cmath>

#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/oc3.hpp"

namespace fowtsim::multibody {
namespace {

class FreeSystem : public LoadProvider {
 public:
  void loads(double, const State&, AppliedLoads& out) override { out.gravity = false; }
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::vector<BenchRow> bench_multibody(int steps) {
  std::vector<BenchRow> rows;
  for (const bool flexible_tower : {false, true})
  for (const double dt : {0.02, 0.05, 0.1}) {
    Params p = oc3_hywind_params();
    if (flexible_tower) set_oc3_flexible_tower(p);
    p.max_step_s = dt;
    p.drivetrain.torsional_damping_N_m_s_rad = 0.0;
    p.initial_conditions.rotor_speed_rpm = 12.1;
    p.initial_conditions.platform_angular_velocity_deg_s = Vec3(0.5, 1.0, 0.3);
    const Model model = make_model(p);
    FreeSystem provider;
    State s = Multibody::make_state(model);
    const double e0 = invariants(model, s, false).kinetic_energy_J;
    auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) Multibody::advance(model, provider, i * dt, dt, s);
    const double step_time = seconds_since(start) / steps;
    const Invariants end = invariants(model, s, false);

    AppliedLoads loads;
    loads.gravity = false;
    Evaluation eval;
    start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) evaluate(model, s, loads, 0.0, eval);
    const double eval_time = seconds_since(start) / steps;
    start = std::chrono::steady_clock::now();
    double sink = 0.0;
    for (int i = 0; i < steps; ++i) sink += Multibody::outputs(model, loads, s).channels[0];
    const double out_time = seconds_since(start) / steps;
    (void)sink;

    BenchRow row;
    row.name = flexible_tower ? "OC3 free, 12.1 rpm, flexible drivetrain, flexible tower (4 modes)"
                              : "OC3 free, 12.1 rpm, flexible drivetrain";
    row.steps = steps;
    row.dt_s = dt;
    row.substeps = 1;
    row.us_per_step = 1e6 * step_time;
    row.us_per_evaluation = 1e6 * eval_time;
    row.us_per_outputs = 1e6 * out_time;
    row.energy_drift = std::abs(end.kinetic_energy_J + end.potential_energy_J - e0) / e0;
    rows.push_back(row);
  }
  return rows;
}

}  // namespace fowtsim::multibody
