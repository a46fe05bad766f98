#include "scenes/toy_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "coupling/multi_rate_scheduler.hpp"
#include "decks/deck_helpers.hpp"
#include "fowtsim/core/channels.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/toy/exact_solution.hpp"
#include "run/channel_selection.hpp"
#include "scenes/scene_runner.hpp"

namespace fowtsim::driver {
namespace {

using Scheduler = MultiRateScheduler<toy::SlowOscillator, toy::FastOscillator>;

template <class Params>
Params read_oscillator(const io::ValidatedDeck& d) {
  Params p;
  p.mass_kg = d.number("mass_kg");
  p.stiffness_N_m = d.number("stiffness_N_m");
  p.damping_N_s_m = d.number("damping_N_s_m");
  p.initial_position_m = d.number("initial_position_m");
  p.divergence_limit_m = d.number("divergence_limit_m");
  return p;
}

CouplingSettings read_settings(const io::ValidatedDeck& deck, const RunRequest& request) {
  CouplingSettings s;
  s.t_max_s = request.t_max_s.value_or(deck.number("simulation.t_max_s"));
  if (request.dt_s)
    throw InputError({"toy", std::nullopt, "--dt", "simulation.dt_coupling_s in the deck"},
                     "--dt sets the time step of beam runs (BeamDyn driver inputs, beam decks); this scene's steps are set in the deck");
  s.dt_coupling_s = deck.number("simulation.dt_coupling_s");
  s.substeps = static_cast<int>(deck.integer("simulation.substeps"));
  s.mode = parse_coupling_mode(deck.string("simulation.coupling"));
  try {
    validate(s);
  } catch (const InputError& e) {
    // Point at where the setting came from: the command line or the deck entry.
    const bool from_command_line = request.t_max_s && e.context().variable == "t_max_s";
    throw InputError(e.context(), (from_command_line ? std::string("--tmax") : where(deck, "simulation." + e.context().variable)) +
                                      ": " + e.message());
  }
  return s;
}

// Every channel this scene can write, in a fixed order; values_of() fills the same order.
std::vector<ChannelInfo> all_channels(const toy::SlowOscillator::Params& slow, const toy::FastOscillator::Params& fast) {
  std::vector<ChannelInfo> all = toy::SlowOscillator::channels(slow);
  for (ChannelInfo& c : toy::FastOscillator::channels(fast)) all.push_back(c);
  all.push_back({"ToyExactSlowPos", "m", "exact slow position (matrix exponential)", "toy.exact"});
  all.push_back({"ToyExactFastRelPos", "m", "exact fast relative position (matrix exponential)", "toy.exact"});
  all.push_back({"ToySlowPosErr", "m", "ToySlowPos − ToyExactSlowPos", "toy.exact"});
  return all;
}
constexpr std::size_t kChannelCount = 9;
constexpr std::size_t kFirstExactChannel = 6;  // ToyExactSlowPos and after need the exact solution

// Channel values in all_channels() order; the exact solution (a matrix exponential) is evaluated
// only when a requested channel needs it.
std::array<double, kChannelCount> values_of(const Scheduler& s, const toy::ExactSolution& exact, bool need_exact) {
  const Eigen::Vector4d ze = need_exact ? exact.state_at(s.time_s()) : Eigen::Vector4d::Constant(NAN);
  const double x = s.slow_state().position_m;
  return {x, s.slow_state().velocity_m_s, s.slow_output().interface_force_N, s.fast_state().position_m,
          s.fast_state().velocity_m_s, s.fast_output().root_loads.force_N.x(), ze[0], ze[2], x - ze[0]};
}

}  // namespace

RunReport run_toy_scene(const io::ValidatedDeck& deck, const RunRequest& request, const ProgressCallback& progress) {
  const CouplingSettings settings = read_settings(deck, request);
  const auto slow = read_oscillator<toy::SlowOscillator::Params>(deck.section("toy_oscillators.slow"));
  const auto fast = read_oscillator<toy::FastOscillator::Params>(deck.section("toy_oscillators.fast"));
  const std::vector<ChannelInfo> all = all_channels(slow, fast);
  const std::vector<std::size_t> picked = select_channels(deck, all, "toy");

  // The scheduler's large step ΔT is the loop's step; read_settings has checked that it divides
  // the simulated time.
  FixedStepPlan plan = output_plan(request, deck);
  plan.dt_s = settings.dt_coupling_s;
  plan.steps = settings.large_steps();
  plan.t_max_s = settings.t_max_s;

  FixedStepScene scene;
  for (std::size_t i : picked) scene.written.push_back(all[i]);
  scene.metadata.deck_path = request.deck_path.string();
  scene.metadata.deck_hash = deck.hash();
  scene.metadata.seeds = {static_cast<std::uint64_t>(deck.integer("simulation.seed"))};
  scene.metadata.dt_s = settings.dt_s();
  scene.metadata.dt_coupling_s = settings.dt_coupling_s;
  scene.metadata.extra = {{"scene", "toy_oscillators"}, {"coupling", to_string(settings.mode)}};

  Scheduler scheduler(slow, fast, settings);
  const toy::ExactSolution exact(slow, fast);
  const bool need_exact = std::any_of(picked.begin(), picked.end(), [](std::size_t i) { return i >= kFirstExactChannel; });
  scene.step = [&](double, double) { scheduler.step(); };
  scene.save = [&](CheckpointWriter& w) { w.io(scheduler.state()); };  // the scene's whole state
  scene.load = [&](CheckpointReader& r) { r.io(scheduler.state()); };
  scene.row = [&](double, std::span<double> row) {
    const auto values = values_of(scheduler, exact, need_exact);
    for (std::size_t k = 0; k < picked.size(); ++k) row[k] = values[picked[k]];
  };
  RunReport report = run_fixed_steps(request, plan, std::move(scene), progress);
  report.substeps = settings.substeps;
  report.coupling = to_string(settings.mode);
  // An explicit RK4 step is stable only for |λ Δt| < 2√2 (imaginary axis). In the summary only,
  // first, as the toy scene has always reported it (its HDF5 warnings attribute stays empty).
  const double fast_limit_s = 2.0 * std::sqrt(2.0) / std::sqrt(fast.stiffness_N_m / fast.mass_kg);
  if (settings.dt_s() > fast_limit_s) {
    report.warnings.insert(report.warnings.begin(),
                           fmt::format("Δt = {:.4g} s exceeds the fast oscillator's RK4 stability limit {:.4g} s",
                                       settings.dt_s(), fast_limit_s));
  }
  return report;
}

}  // namespace fowtsim::driver
