#include "fowtsim/slender/time_domain.hpp"

#include <cmath>
#include <string>

#include "fowtsim/core/error.hpp"
#include "fowtsim/slender/time_stepping.hpp"

namespace fowtsim::slender {

TimeDomainResult simulate(const Model& model, const Modes& modes, const WaveHistory& waves, const TimeDomainOptions& o) {
  const double dt = o.time_step_s, half = 0.5 * dt;
  if (std::abs(waves.sample_interval_s - half) > 1e-12 * half || waves.velocity_m_s.cols() < 2 * o.steps + 1 ||
      waves.velocity_m_s.rows() != model.strips.x_m.size())
    throw InputError({"slender.time_domain", std::nullopt, "wave history", "sample the waves at Δt/2 over the run"},
                     "the wave history does not cover " + std::to_string(o.steps) + " steps of " + std::to_string(dt) +
                         " s at half-step samples on every strip");
  const SlenderBody::Params p = make_time_domain_params(model, modes, o.recovery);
  SlenderBody::Input in = make_input(p);
  SlenderBody::Workspace work = make_workspace(p);
  SlenderBody::Output out = make_output(p);
  SlenderBody::State state = SlenderBody::make_state(p);
  // The history's samples 2k + c (c = 0, 1, 2) as the input's columns: a step takes three, an output one.
  const auto load = [&](int columns) {
    const Eigen::Index k = 2 * state.step;
    in.velocity_m_s.leftCols(columns) = waves.velocity_m_s.middleCols(k, columns);
    in.acceleration_m_s2.leftCols(columns) = waves.acceleration_m_s2.middleCols(k, columns);
  };

  const int outputs = o.steps / o.output_every + 1;
  const auto N = model.strips.x_m.size(), n = model.mass.rows();
  TimeDomainResult r{VecX(outputs), MatX(n, outputs), MatX(N, outputs), MatX(N, outputs), MatX(N, outputs)};
  const auto record = [&](int column) {
    load(1);
    SlenderBody::outputs(p, in, state, work, out);
    r.time_s(column) = static_cast<double>(state.step) * dt;
    r.q.col(column) = out.q;
    r.displacement_m.col(column) = out.displacement_m;
    r.moment_elastic_N_m.col(column) = out.moment_elastic_N_m;
    r.moment_inertia_relief_N_m.col(column) = out.moment_inertia_relief_N_m;
  };
  record(0);
  for (int step = 1; step <= o.steps; ++step) {
    load(3);
    SlenderBody::advance(p, in, (step - 1) * dt, dt, state, work);
    if (step % o.output_every == 0) record(step / o.output_every);
  }
  return r;
}

}  // namespace fowtsim::slender
