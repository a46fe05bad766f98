#include <cmath>

#include <fmt/format.h>

#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::beam {
namespace {

BeamInput scaled(const BeamInput& input, double s) {
  BeamInput out = input;
  out.frame.acceleration_m_s2 *= s;
  out.frame.gravity_m_s2 *= s;
  for (Vec6& l : out.node_loads) l *= s;
  out.tip_load *= s;
  return out;
}

// RMS over nodes of |u*|/L and |θ*|: the seed's stopping measure (§2.5.1), made dimensionless.
double increment_size(const VecX& q, double length) {
  double sum = 0.0;
  const int n = static_cast<int>(q.size() / 6);
  for (int i = 0; i < n; ++i)
    sum += q.segment<3>(6 * i).squaredNorm() / (length * length) + q.segment<3>(6 * i + 3).squaredNorm();
  return std::sqrt(sum / n);
}

}  // namespace

StaticReport solve_static(const BeamModel& model, const BeamInput& input, BeamState& state,
                          const StaticOptions& options) {
  StaticReport report;
  if (!model.free_tip()) state.tip_offset_m = input.tip_displacement_m;  // the held tip where the input puts it
  LinearizedBeam system;
  VecX q;
  for (int step = 1; step <= options.load_steps; ++step) {
    const BeamInput loads = scaled(input, static_cast<double>(step) / options.load_steps);
    bool converged = false;
    for (int it = 0; it < options.max_iterations && !converged; ++it) {
      linearize(model, loads, state, Inertia::static_only, system);
      q = system.rhs;
      if (!system.stiffness.factor())
        throw NumericalError({"beam.static", std::nullopt, "stiffness", "check the sectional stiffness"},
                             "singular stiffness matrix in the static solve");
      system.stiffness.solve_in_place(q);
      if (!q.allFinite())
        throw NumericalError({"beam.static", std::nullopt, "increment", "use more load steps"},
                             "non-finite increment in the static solve");
      // Damped Newton: keep each iterate a moderate rotation so the exact update stays near the
      // tangent's region of validity.
      double max_rot = 0.0;
      for (int i = 0; i < model.node_count(); ++i)
        max_rot = std::max(max_rot, q.segment<3>(6 * i + 3).norm());
      if (max_rot > options.max_rotation_rad) q *= options.max_rotation_rad / max_rot;
      update_base(q, state);
      ++report.iterations;
      report.final_increment = increment_size(q, model.length_m);
      converged = report.final_increment < options.tolerance;
    }
    if (!converged)
      throw NumericalError(
          {"beam.static", std::nullopt, "increment", "use more load steps (static load_steps)"},
          fmt::format("static solve did not converge in {} iterations at load step {}/{} "
                      "(last increment {:.3e})",
                      options.max_iterations, step, options.load_steps, report.final_increment));
  }
  for (Vec6& v : state.velocity) v.setZero();
  state.acceleration_valid = false;
  return report;
}

}  // namespace fowtsim::beam
