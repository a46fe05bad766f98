#include "beamdyn/beamdyn_run.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "beamdyn/beamdyn_channels.hpp"
#include "beamdyn/beamdyn_setup.hpp"
#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/core/version.hpp"
#include "run/interrupt.hpp"
#include "run/output_set.hpp"

namespace fowtsim::driver {
namespace {

// BeamDyn's static driver writes the undeformed row at t0 and the converged solution at the next
// nine steps (t0 + dt … t0 + 9 dt); we write the same rows.
constexpr int kStaticRows = 9;

// Static solve with BeamDyn's load-bisection fallback: all load at once, then halving the load
// increment (doubling the load steps) when the iteration fails.
void solve_static_robustly(const beam::BeamModel& model, const beam::BeamInput& input, beam::BeamState& state) {
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

RunReport run_single_beam(const BeamDynSetup& setup_in, const SingleBeamRun& how, const RunRequest& request,
                          const ProgressCallback& progress) {
  BeamDynSetup setup = setup_in;
  if (request.t_max_s) setup.t_final_s = setup.t_initial_s + *request.t_max_s;
  if (request.dt_s) setup.dt_s = *request.dt_s;
  const beam::BeamModel model = beam::discretise(setup.definition, how.segments);

  RunReport report;
  report.coupling = "beam only";
  const auto all = beamdyn_channels();
  std::vector<std::size_t> picked;
  for (const std::string& name : how.channels) {
    if (const auto i = find_beamdyn_channel(name)) {
      picked.push_back(*i);
    } else if (how.skip_unknown_channels) {
      report.warnings.push_back(fmt::format("BeamDyn channel '{}' is not available and is not written", name));
    } else {
      throw InputError({"beam", std::nullopt, name, ""}, fmt::format("unknown beam channel '{}'", name));
    }
  }
  if (how.channels.empty())
    for (std::size_t i = 0; i < all.size(); ++i) picked.push_back(i);
  std::vector<ChannelInfo> written;
  for (std::size_t i : picked) written.push_back(all[i]);

  const long steps = setup.dynamic ? std::lround((setup.t_final_s - setup.t_initial_s) / setup.dt_s) : 0;
  OutputSet outputs(request.output_base.value_or(std::filesystem::path("runs") / request.deck_path.stem()),
                    request.output_format.value_or("h5"));
  report.outputs = outputs.paths();
  report.t_max_s = setup.t_final_s;
  io::RunMetadata metadata;
  metadata.version = kVersion;
  metadata.deck_path = request.deck_path.string();
  metadata.deck_hash = how.deck_hash;
  metadata.dt_s = setup.dt_s;
  metadata.dt_coupling_s = setup.dt_s;
  beam::DynamicOptions options;
  options.integrator = beam::integrator_from_name(how.integrator);
  options.spectral_radius = setup.spectral_radius;
  options.matrix_max_age = how.matrix_max_age;
  metadata.extra = {{"scene", how.scene},
                    {"beam_segments", std::to_string(how.segments)},
                    {"beam_integrator", beam::integrator_name(options.integrator)},
                    {"beam_matrix_max_age", std::to_string(options.matrix_max_age)}};
  outputs.begin(written, metadata);

  beam::BeamState state = beam::make_state(model);
  beam::BeamInput input;
  std::vector<double> row(picked.size()), values;
  values.reserve(all.size());
  auto write_row = [&](double t, bool zero_loads) {
    beam::BeamOutputs out = beam::beam_outputs(model, state);
    if (zero_loads) out.root_load.setZero();  // BeamDyn's t0 row before any solve
    beamdyn_channel_values(model, out, values);
    for (std::size_t k = 0; k < picked.size(); ++k) row[k] = values[picked[k]];
    outputs.append(t, row);
  };

  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  double t = setup.t_initial_s;
  try {
    if (!setup.dynamic) {
      write_row(t, true);
      beamdyn_input(setup, model, state, t, input);
      solve_static_robustly(model, input, state);
      for (int k = 1; k <= kStaticRows; ++k) write_row(setup.t_initial_s + k * setup.dt_s, false);
      t = setup.t_initial_s + kStaticRows * setup.dt_s;
      report.large_steps = 1;
    } else {
      if (setup.quasi_static_init) {
        beamdyn_input(setup, model, state, t, input);
        solve_static_robustly(model, input, state);
      }
      write_row(t, false);
      beam::DynamicStepper stepper(model, options);
      long k = 1;
      for (; k <= steps && interrupt_signal() == 0; ++k) {  // a signal stops the run at the end of a step
        const double t0 = setup.t_initial_s + (k - 1) * setup.dt_s;
        beamdyn_input(setup, model, state, t0 + stepper.input_time_fraction() * setup.dt_s, input);
        stepper.step(input, setup.dt_s, state);
        t = setup.t_initial_s + k * setup.dt_s;
        if (k % how.decimation == 0) write_row(t, false);
        if (progress) progress(t, setup.t_final_s);
      }
      report.large_steps = k - 1;
      if (k <= steps) report.interrupted_by = interrupt_signal();
    }
  } catch (const NumericalError& e) {
    outputs.finish({elapsed(), std::string("failed: ") + e.what(), t, {}});
    throw;
  }
  report.wall_s = elapsed();
  report.simulated_s = t;
  outputs.finish({report.wall_s, report.interrupted_by ? interrupted_status(t, report.interrupted_by) : "completed", t, {}});
  return report;
}

}  // namespace fowtsim::driver
