#include "scenes/scene_runner.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "decks/implausible_values.hpp"
#include "fowtsim/core/version.hpp"
#include "run/interrupt.hpp"
#include "run/earlier_rows.hpp"
#include "run/output_set.hpp"

namespace fowtsim::driver {

using io::Schema;

namespace {

// Each key once: name, schema and the field it fills (decks/deck_section.hpp).
DeckSection<SimulationKeys> simulation_section(const char* step_doc) {
  DeckSection<SimulationKeys> s;
  s.key("t_max_s", Schema::number().unit("s").greater_than(0.0).default_value(600.0).doc("simulated time"), &SimulationKeys::t_max_s)
      .key("dt_s", Schema::number().unit("s").greater_than(0.0).default_value(0.05).doc(step_doc), &SimulationKeys::dt_s);
  return s;
}

const DeckSection<OutputKeys>& output_section() {
  static const DeckSection<OutputKeys> section = [] {
    DeckSection<OutputKeys> s;
    s.key("format", Schema::choice({"h5", "out", "outb", "both"}).default_value("h5").doc("HDF5, OpenFAST text .out, OpenFAST binary .outb, or both (.h5 and .out)"),
          &OutputKeys::format)
        .key("decimation", Schema::integer().at_least(1).default_value(1).doc("write every k-th step (the large step where there are two)"),
             &OutputKeys::decimation)
        .key("channels", Schema::sequence(Schema::string()).optional().doc("channel names; absent = all"), &OutputKeys::channels);
    return s;
  }();
  return section;
}

}  // namespace

Schema simulation_schema(const char* step_doc) { return simulation_section(step_doc).schema(); }

SimulationKeys simulation_keys(const io::ValidatedDeck& deck) {
  SimulationKeys keys;
  simulation_section("").read_into(deck.section("simulation"), keys);
  return keys;
}

Schema output_schema() { return output_section().schema(); }

OutputKeys output_keys(const io::ValidatedDeck& deck) {
  OutputKeys keys;
  if (deck.has("output")) output_section().read_into(deck.section("output"), keys);
  return keys;
}

FixedStepPlan output_plan(const RunRequest& request, const io::ValidatedDeck& deck) {
  const OutputKeys keys = output_keys(deck);
  FixedStepPlan plan;
  plan.format = request.output_format.value_or(keys.format);
  plan.decimation = keys.decimation;
  plan.base = request.output_base.value_or(std::filesystem::path("runs") / request.deck_path.stem());
  plan.deck_hash = deck.hash();
  return plan;
}

RunReport run_fixed_steps(const RunRequest& request, const io::ValidatedDeck& deck, FixedStepScene scene,
                          const ProgressCallback& progress) {
  FixedStepPlan plan = output_plan(request, deck);
  const SimulationKeys simulation = simulation_keys(deck);
  plan.t_max_s = request.t_max_s.value_or(simulation.t_max_s);
  plan.dt_s = simulation.dt_s;
  const double t_max = plan.t_max_s, dt = plan.dt_s;
  if (request.dt_s)
    throw InputError({"scene", std::nullopt, "--dt", "simulation.dt_s in the deck"},
                     "--dt sets the time step of beam runs (BeamDyn driver inputs, beam decks); this scene's steps are "
                     "set in the deck (" + where(deck, "simulation.dt_s") + ")");
  // Every check before any file is opened: a failed start must not touch an earlier output.
  plan.steps = std::lround(t_max / dt);
  if (plan.steps < 1 || std::abs(static_cast<double>(plan.steps) * dt - t_max) > 1e-9 * t_max) {
    const std::string culprit = request.t_max_s ? fmt::format("--tmax {:.10g}", t_max)
                                                : fmt::format("simulation.t_max_s = {:.10g}", t_max);
    throw InputError({"scene", std::nullopt, request.t_max_s ? "--tmax" : "simulation.t_max_s",
                      fmt::format("a multiple of dt_s = {:.10g} s, e.g. {:.10g}", dt, std::max(1L, plan.steps) * dt)},
                     where(deck, "simulation.dt_s") + ": the time step must divide the simulated time (" + culprit +
                         " is not a whole number of steps of " + fmt::format("{:.10g}", dt) + " s)");
  }
  scene.metadata.deck_path = std::filesystem::absolute(request.deck_path).lexically_normal().string();
  scene.metadata.deck_hash = deck.hash();
  scene.metadata.dt_s = dt;
  scene.metadata.dt_coupling_s = dt;
  for (std::string& w : implausible_values(deck)) scene.input_warnings.push_back(std::move(w));
  return run_fixed_steps(request, plan, std::move(scene), progress);
}

RunReport run_fixed_steps(const RunRequest& request, const FixedStepPlan& plan, FixedStepScene scene,
                          const ProgressCallback& progress) {
  const double dt = plan.dt_s;
  const long steps = plan.steps;
  // Checkpoints (issue 16): <output>.chk every T, and a restart from one, both checked first.
  long checkpoint_steps = 0, k0 = 0;
  if ((request.checkpoint_every_s || request.restart_path) && !scene.save)
    throw InputError({"scene", std::nullopt, "--checkpoint-every/--restart", "the floating-turbine, toy or slender scene"},
                     "this run does not write checkpoints (the floating turbine with the built-in controller, the toy "
                     "oscillators and the slender body do)");
  if (request.checkpoint_every_s) {
    checkpoint_steps = std::lround(*request.checkpoint_every_s / dt);
    // A multiple of the row interval too: a restart's output then continues the rows exactly
    // (its first row, at the checkpoint, is one the uninterrupted run writes).
    const double row_interval = static_cast<double>(plan.decimation) * dt;
    if (checkpoint_steps < 1 || std::abs(checkpoint_steps * dt - *request.checkpoint_every_s) > 1e-9 * *request.checkpoint_every_s ||
        checkpoint_steps % plan.decimation != 0)
      throw InputError({"scene", std::nullopt, "--checkpoint-every", fmt::format("a multiple of the row interval {:.10g} s", row_interval)},
                       fmt::format("--checkpoint-every {:.10g} is not a whole number of rows of {:.10g} s (dt_s {:.10g} s × "
                                   "output.decimation {})",
                                   *request.checkpoint_every_s, row_interval, dt, plan.decimation));
  }
  std::optional<LoadedCheckpoint> checkpoint;
  if (request.restart_path) {
    checkpoint = read_checkpoint(*request.restart_path, plan.deck_hash, dt);
    k0 = checkpoint->header.step;
    if (k0 >= steps)
      throw InputError({"scene", std::nullopt, "--restart", "a checkpoint before the end of the run"},
                       fmt::format("{}: the checkpoint is at t = {:.10g} s, the run ends at {:.10g} s",
                                   request.restart_path->string(), plan.t0_s + k0 * dt, plan.t_max_s));
    CheckpointReader reader(checkpoint->state, *request.restart_path);
    scene.load(reader);
    if (checkpoint->state.peek() != std::char_traits<char>::eof()) reader.mismatch("the state's length");
  }
  // A restart continues the output of the run that wrote the checkpoint unless -o names another.
  const std::filesystem::path base = checkpoint && !request.output_base ? checkpoint->output_base : plan.base;
  const std::filesystem::path checkpoint_file = base.string() + ".chk";
  const std::filesystem::path absolute_base = std::filesystem::absolute(base);  // recorded in checkpoints
  OutputSet outputs(base, plan.format, std::move(scene.whole_files), scene.end_file_suffixes);
  scene.metadata.version = kVersion;
  if (!request.deck_settings.empty()) {  // the deck hash covers them; this says what they were
    std::string settings;
    for (const std::string& s : request.deck_settings) settings += (settings.empty() ? "" : "\n") + s;
    scene.metadata.extra.emplace_back("deck_settings", settings);
  }
  outputs.begin(scene.written, scene.metadata);
  // t0 + k·dt, not a running sum: every row time is exact to one rounding (and t0 = 0 adds none).
  auto time_of = [&](long step) { return plan.t0_s + static_cast<double>(step) * dt; };
  std::vector<std::string> notes = outputs.notes();
  if (checkpoint) {
    const double row_interval = static_cast<double>(plan.decimation) * dt;
    EarlierRows earlier = earlier_rows(checkpoint->output_base, outputs, scene.written, plan.deck_hash, time_of(k0), row_interval);
    std::vector<double> values(scene.written.size());
    for (std::size_t r = 0; r < earlier.table.rows(); ++r) {
      for (std::size_t c = 0; c < values.size(); ++c) values[c] = earlier.table.columns[c + 1][r];
      outputs.append(earlier.table.columns[0][r], values);
    }
    // Continuing a dead run's temporary continues all of that run's files (.h5 and .out).
    const auto& kept = outputs.set_aside();
    if (std::find(kept.begin(), kept.end(), earlier.source) != kept.end())
      for (const auto& file : kept) outputs.adopt(file);
    notes.insert(notes.end(), earlier.notes.begin(), earlier.notes.end());
  }

  RunReport report;
  report.warnings = notes;
  report.warnings.insert(report.warnings.end(), scene.input_warnings.begin(), scene.input_warnings.end());
  // A run far outside sense still runs, but says so (e.g. dt 1e-12 s wrote 600 MB in 60 s).
  const double rows = static_cast<double>(steps - k0) / static_cast<double>(plan.decimation) + 1.0;
  const double bytes = rows * static_cast<double>(scene.written.size() + 1) * (plan.format == "both" ? 2.0 * 8.0 : 8.0);
  if (steps - k0 > 50'000'000L)
    report.warnings.push_back(fmt::format("{} steps of {:.3g} s: check simulation.dt_s", steps - k0, dt));
  if (bytes > 2e9)
    report.warnings.push_back(fmt::format("about {:.1f} GB of output: raise output.decimation or pick output.channels", bytes / 1e9));
  report.outputs = outputs.paths();
  if (checkpoint_steps > 0) report.outputs.push_back(checkpoint_file);
  report.t_max_s = plan.t_max_s;
  std::vector<double> row(scene.written.size());
  auto write_row = [&](double t) {
    scene.row(t, row);
    outputs.append(t, row);
  };
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  long k = k0;
  double t = time_of(k);
  try {
    write_row(t);
    while (k < steps && interrupt_signal() == 0) {  // a signal stops the run at the end of a step
      scene.step(t, dt);
      ++k;
      t = time_of(k);
      if (k % plan.decimation == 0) write_row(t);
      if (checkpoint_steps > 0 && k % checkpoint_steps == 0) {
        outputs.sync();  // the rows first: a checkpoint is never ahead of the saved rows
        write_checkpoint(checkpoint_file, {hash_field(plan.deck_hash), k, dt}, absolute_base, scene.save);
      }
      if (progress) progress(t, plan.t_max_s);
    }
    if (k == steps && scene.end_files) outputs.write_end_files(scene.end_files());
  } catch (const std::exception& e) {  // numerical trouble, or a failing external controller
    // The failure is what the user needs: a file that cannot be closed on top of it keeps its
    // rows and says "running" or "incomplete" (the writers' own guarantees).
    try {
      outputs.finish({elapsed(), std::string("failed: ") + e.what(), t, report.warnings});
    } catch (...) {
    }
    throw;
  }
  report.wall_s = elapsed();
  report.simulated_s = t;
  report.large_steps = k - k0;
  if (k < steps) {
    report.interrupted_by = interrupt_signal();
    for (const auto& p : outputs.end_paths()) std::erase(report.outputs, p);  // an interrupted run writes none
  }
  if (scene.warnings) scene.warnings(report.warnings);
  outputs.finish({report.wall_s, report.interrupted_by ? interrupted_status(t, report.interrupted_by) : "completed", t,
                  report.warnings});
  return report;
}

}  // namespace fowtsim::driver
