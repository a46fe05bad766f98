#include "fowtsim/beam/riser.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "section_mechanics.hpp"

namespace fowtsim::beam::riser {

RiserSetup seed_case(char which) {
  if (which < 'a' || which > 'd') throw std::invalid_argument("riser case a, b, c or d");
  RiserSetup s{.pipe = {ReferenceLine::straight(Vec3(0.0, 0.0, -300.0), Mat3::Identity(), 300.0, [](double) { return 0.0; })}};
  PipeDefinition& p = s.pipe;
  p.outer_diameter_m = 0.254;
  p.inner_diameter_m = 0.2286;
  p.youngs_modulus_pa = 209e9;
  p.poisson_ratio = 0.3;
  p.pipe_density_kg_m3 = 7800.0;
  p.fluid_density_kg_m3 = 900.0;
  p.fluid_viscosity_pa_s = 0.009;
  p.wall_roughness_m = 0.05e-3;
  p.stiffness_damping_s = 0.001;
  p.root_end = EndCondition::clamped;
  p.tip_end = EndCondition::clamped;
  // (a), (b): flowing up from the wellhead at its pressure; (c) top valve shut: the wellhead's
  // pressure stands in the still oil; (d) bottom valve shut: the oil column open to the air on top.
  p.flow_velocity_m_s = which == 'a' || which == 'b' ? 2.242 : 0.0;
  p.boundary_pressure_pa = which == 'd' ? 0.0 : 20.68e6;
  p.pressure_at_tip = which == 'd';

  s.water.density_kg_m3 = 1025.0;
  s.water.outer_diameter_m = p.outer_diameter_m;
  s.water.added_mass_coefficient = 1.8 - 1.0;
  s.water.drag_coefficient = 1.0;
  s.water.surface_z_m = 0.0;

  s.top.stretch_m = which == 'a' ? 0.3 : 0.0;
  s.top.stretch_time_s = 1.0;
  s.top.sway_amplitude_m = 5.0;
  s.top.sway_period_s = 10.0;  // 2π/(0.2π)
  s.top.sway_start_s = 1.0;
  return s;
}

BeamModel riser_model(const RiserSetup& setup, int segments) {
  BeamModel model = discretise_pipe(setup.pipe, segments);
  model.water = setup.water;
  return model;
}

void riser_input(const RiserSetup& setup, double t_s, BeamInput& input) {
  input.frame.gravity_m_s2 = setup.gravity_m_s2;
  input.tip_displacement_m = setup.top.displacement(t_s);
  input.tip_velocity_m_s = setup.top.velocity(t_s);
}

void bending_moments(const BeamModel& model, const BeamState& state, std::vector<double>& out) {
  out.resize(model.sections.size());
  SectionLinearization lin;
  NodePose a, b;
  for (std::size_t j = 0; j < model.sections.size(); ++j) {
    section_poses(model, state, model.sections[j], a, b);
    linearize_section(model.sections[j], a, b, lin);
    out[j] = std::hypot(lin.resultant(3), lin.resultant(4));  // about the two bending axes
  }
}

namespace {

// Largest distance of a node from the chord between the bottom and the (moved) top.
double deflection(const BeamModel& model, const BeamState& state) {
  const Vec3 bottom = model.root_position_m, top = model.tip_position_m + state.tip_offset_m;
  const Vec3 e = (top - bottom).normalized();
  double worst = 0.0;
  for (const Vec3& x : state.position_m) {
    const Vec3 r = x - bottom;
    worst = std::max(worst, (r - r.dot(e) * e).norm());
  }
  return worst;
}

}  // namespace

RiserRun simulate(const RiserSetup& setup, int segments, double dt_s, double t_end_s,
                  const std::vector<double>& snapshot_times_s, int sample_every, double spectral_radius) {
  const BeamModel model = riser_model(setup, segments);
  BeamState state = make_state(model);
  BeamInput input;
  riser_input(setup, 0.0, input);
  solve_static(model, input, state);

  DynamicOptions options;
  options.spectral_radius = spectral_radius;
  DynamicStepper stepper(model, options);
  RiserRun run;
  run.snapshot_times_s = snapshot_times_s;
  run.max_bending_moment_n_m.assign(model.sections.size(), 0.0);
  for (const SectionModel& sec : model.sections)
    run.section_s_m.push_back(sec.inboard >= 0 ? model.nodes[sec.inboard].s_m + sec.alpha * sec.length_m
                                               : sec.alpha * sec.length_m);
  std::vector<double> moments;
  auto sample = [&] {
    bending_moments(model, state, moments);
    for (std::size_t j = 0; j < moments.size(); ++j)
      run.max_bending_moment_n_m[j] = std::max(run.max_bending_moment_n_m[j], moments[j]);
    run.max_deflection_m = std::max(run.max_deflection_m, deflection(model, state));
  };
  auto snapshot = [&] {
    std::vector<Vec3> shape{model.root_position_m};
    shape.insert(shape.end(), state.position_m.begin(), state.position_m.end());
    shape.push_back(model.tip_position_m + state.tip_offset_m);
    run.snapshots_m.push_back(std::move(shape));
  };
  const long steps = std::lround(t_end_s / dt_s);
  std::size_t next = 0;
  for (long k = 0; k <= steps; ++k) {
    const double t = k * dt_s;
    const bool snap = next < snapshot_times_s.size() && t >= snapshot_times_s[next] - 0.5 * dt_s;
    if (snap) {
      snapshot();
      ++next;
    }
    if (snap || k % sample_every == 0) sample();
    if (k == steps) break;
    riser_input(setup, t + stepper.input_time_fraction() * dt_s, input);
    stepper.step(input, dt_s, state);
    ++run.steps;
  }
  run.max_bending_moment_n_m_overall = *std::max_element(run.max_bending_moment_n_m.begin(), run.max_bending_moment_n_m.end());
  const int mid = model.node_count() / 2;
  run.final_mid_sway_m = (state.position_m[mid] - model.nodes[mid].position_m).dot(setup.top.sway_direction);
  return run;
}

}  // namespace fowtsim::beam::riser
