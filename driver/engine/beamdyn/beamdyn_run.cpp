#include "beamdyn/beamdyn_run.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <optional>

#include <fmt/format.h>

#include "beamdyn/beamdyn_channels.hpp"
#include "beamdyn/beamdyn_setup.hpp"
#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/error.hpp"
#include "scenes/scene_runner.hpp"

namespace fowtsim::driver {
namespace {

// BeamDyn's static driver writes the undeformed row at t0 and the converged solution at the next
// nine steps (t0 + dt … t0 + 9 dt); we write the same rows.
constexpr long kStaticRows = 9;

// Static solve under the case's loads at t, with BeamDyn's load-bisection fallback: all load at
// once, then halving the load increment (doubling the load steps) when the iteration fails.
void solve_static_robustly(const BeamDynSetup& setup, const beam::BeamModel& model, double t_s, beam::BeamInput& input,
                           beam::BeamState& state) {
  beamdyn_input(setup, model, state, t_s, input);
  const beam::BeamState start = state;
  for (int steps = 1;; steps *= 2) {
    beam::StaticOptions opt;
    opt.load_steps = steps;
    try {
      beam::solve_static(model, input, state, opt);
      return;
    } catch (const NumericalError&) {
      if (steps >= 1024) throw;
      state = start;
    }
  }
}

}  // namespace

bool is_beamdyn_driver_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string first;
  std::getline(in, first);
  std::transform(first.begin(), first.end(), first.begin(), [](unsigned char c) { return std::toupper(c); });
  return first.find("BEAMDYN DRIVER") != std::string::npos;
}

RunReport run_beamdyn_case(const RunRequest& request, const ProgressCallback& progress) {
  BeamDynSetup setup = beamdyn_setup(io::read_beamdyn_driver(request.deck_path));
  SingleBeamRun how;
  how.segments = request.beam_segments.value_or(48);
  how.integrator = request.beam_integrator.value_or("generalized_alpha");
  how.matrix_max_age = request.beam_matrix_max_age.value_or(how.matrix_max_age);
  how.channels = setup.out_list;
  how.scene = "beamdyn_driver";
  return run_single_beam(setup, how, request, progress);
}

void step_beamdyn(const BeamDynSetup& setup, const beam::BeamModel& model, beam::DynamicStepper& stepper, double t_s,
                  double dt_s, beam::BeamInput& input, beam::BeamState& state) {
  beamdyn_input(setup, model, state, t_s + stepper.input_time_fraction() * dt_s, input);
  stepper.step(input, dt_s, state);
}

RunReport run_single_beam(const BeamDynSetup& setup_in, const SingleBeamRun& how, const RunRequest& request,
                          const ProgressCallback& progress) {
  BeamDynSetup setup = setup_in;
  if (request.t_max_s) setup.t_final_s = setup.t_initial_s + *request.t_max_s;
  if (request.dt_s) setup.dt_s = *request.dt_s;
  const beam::BeamModel model = [&] {
    beam::BeamModel m = beam::discretise(setup.definition, how.segments);
    m.flow = setup.flow;
    m.water = setup.water;
    return m;
  }();

  std::vector<std::string> channel_warnings;
  const auto all = beamdyn_channels();
  std::vector<std::size_t> picked;
  for (const std::string& name : how.channels) {
    if (const auto i = find_beamdyn_channel(name)) {
      picked.push_back(*i);
    } else if (how.skip_unknown_channels) {
      channel_warnings.push_back(fmt::format("BeamDyn channel '{}' is not available and is not written", name));
    } else {
      throw InputError({"beam", std::nullopt, name, ""}, fmt::format("unknown beam channel '{}'", name));
    }
  }
  if (how.channels.empty())
    for (std::size_t i = 0; i < all.size(); ++i) picked.push_back(i);

  FixedStepPlan plan;
  plan.t0_s = setup.t_initial_s;
  plan.dt_s = setup.dt_s;
  // A static analysis is one solve in the first of the kStaticRows steps.
  plan.steps = setup.dynamic ? std::lround((setup.t_final_s - setup.t_initial_s) / setup.dt_s) : kStaticRows;
  plan.t_max_s = setup.t_final_s;
  plan.format = request.output_format.value_or("h5");
  plan.decimation = setup.dynamic ? how.decimation : 1;  // BeamDyn's static rows are all written
  plan.base = request.output_base.value_or(std::filesystem::path("runs") / request.deck_path.stem());
  plan.deck_hash = how.deck_hash;

  FixedStepScene scene;
  for (std::size_t i : picked) scene.written.push_back(all[i]);
  scene.metadata.deck_path = request.deck_path.string();
  scene.metadata.deck_hash = how.deck_hash;
  scene.metadata.dt_s = setup.dt_s;
  scene.metadata.dt_coupling_s = setup.dt_s;
  beam::DynamicOptions options;
  options.integrator = beam::integrator_from_name(how.integrator);
  options.spectral_radius = setup.spectral_radius;
  options.matrix_max_age = how.matrix_max_age;
  scene.metadata.extra = {{"scene", how.scene},
                          {"beam_segments", std::to_string(how.segments)},
                          {"beam_integrator", beam::integrator_name(options.integrator)},
                          {"beam_matrix_max_age", std::to_string(options.matrix_max_age)}};

  beam::BeamState state = beam::make_state(model);
  beam::BeamInput input;
  std::vector<double> values;
  values.reserve(all.size());
  bool solved = setup.dynamic;  // a static run's row at t0 shows BeamDyn's state before any solve
  scene.row = [&](double, std::span<double> row) {
    beam::BeamOutputs out = beam::beam_outputs(model, state);
    if (!solved) out.root_load.setZero();
    beamdyn_channel_values(model, out, values);
    for (std::size_t k = 0; k < picked.size(); ++k) row[k] = values[picked[k]];
  };
  std::optional<beam::DynamicStepper> stepper;
  if (setup.dynamic) {
    if (setup.quasi_static_init) solve_static_robustly(setup, model, setup.t_initial_s, input, state);
    stepper.emplace(model, options);
    scene.step = [&](double t, double dt) { step_beamdyn(setup, model, *stepper, t, dt, input, state); };
  } else {
    scene.step = [&](double t, double) {
      if (solved) return;  // the later static rows repeat the converged solution
      solve_static_robustly(setup, model, t, input, state);
      solved = true;
    };
  }
  RunReport report = run_fixed_steps(request, plan, std::move(scene), progress);
  report.coupling = "beam only";
  if (!setup.dynamic) report.large_steps = 1;  // one static solve
  // In the summary only, first, as the BeamDyn runs have always reported them.
  report.warnings.insert(report.warnings.begin(), channel_warnings.begin(), channel_warnings.end());
  return report;
}

}  // namespace fowtsim::driver
