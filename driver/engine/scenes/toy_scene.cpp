#include "scenes/toy_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "coupling/multi_rate_scheduler.hpp"
#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/channels.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/toy/exact_solution.hpp"
#include "run/channel_selection.hpp"
#include "scenes/scene_runner.hpp"

namespace fowtsim::driver {
namespace {

using Scheduler = MultiRateScheduler<toy::SlowOscillator, toy::FastOscillator>;

using io::Schema;

// The toy's `simulation` keys, each once with the field it fills (decks/deck_section.hpp): the
// coupling settings and the seed recorded in the output.
struct ToySimulation {
  CouplingSettings settings;
  std::uint64_t seed = 0;
};

const DeckSection<ToySimulation>& toy_simulation_section() {
  static const DeckSection<ToySimulation> section = [] {
    DeckSection<ToySimulation> s;
    s.key("t_max_s", Schema::number().unit("s").greater_than(0.0).doc("simulated time"),
          [](ToySimulation& t) -> double& { return t.settings.t_max_s; })
        .key("dt_coupling_s", Schema::number().unit("s").greater_than(0.0).doc("large (coupling) step ΔT"),
             [](ToySimulation& t) -> double& { return t.settings.dt_coupling_s; })
        .key("substeps", Schema::integer().at_least(1).at_most(100000).default_value(10)
                             .doc("small steps per large step: Δt = ΔT / substeps"),
             [](ToySimulation& t) -> int& { return t.settings.substeps; })
        .key("coupling", Schema::choice({"multi_rate", "predictor_corrector", "single_rate"})
                             .default_value("multi_rate").doc("how slow and fast subsystems exchange state"),
             [](ToySimulation& t) -> CouplingMode& { return t.settings.mode; }, parse_coupling_mode)
        .key("seed", Schema::integer().at_least(0).default_value(0).doc("random seed (recorded in the output)"), &ToySimulation::seed);
    return s;
  }();
  return section;
}

ToySimulation toy_simulation(const io::ValidatedDeck& deck) {
  return toy_simulation_section().read(deck.section("simulation"));
}

// An oscillator's keys, each once with the Params field it fills (decks/deck_section.hpp); the
// slow and the fast oscillator have the same fields in two types.
template <class Params>
DeckSection<Params> oscillator_section(const char* what) {
  DeckSection<Params> s;
  s.key("mass_kg", Schema::number().unit("kg").greater_than(0.0).doc(std::string(what) + " mass"), &Params::mass_kg)
      .key("stiffness_N_m", Schema::number().unit("N_m").greater_than(0.0).doc("spring stiffness"), &Params::stiffness_N_m)
      .key("damping_N_s_m", Schema::number().unit("N_s_m").at_least(0.0).default_value(0.0).doc("dashpot"), &Params::damping_N_s_m)
      .key("initial_position_m", Schema::number().unit("m").default_value(0.0).doc("initial displacement"),
           &Params::initial_position_m)
      .key("divergence_limit_m", Schema::number().unit("m").greater_than(0.0).default_value(1e3)
                                     .doc("|displacement| above this stops the run as divergent"),
           &Params::divergence_limit_m);
  return s;
}
const char* const kSlow = "slow (heavy) oscillator";
const char* const kFast = "fast (light, stiff) oscillator, relative to the slow one";

CouplingSettings read_settings(const io::ValidatedDeck& deck, const RunRequest& request) {
  CouplingSettings s = toy_simulation(deck).settings;
  if (request.t_max_s) s.t_max_s = *request.t_max_s;
  if (request.dt_s)
    throw InputError({"toy", std::nullopt, "--dt", "simulation.dt_coupling_s in the deck"},
                     "--dt sets the time step of beam runs (BeamDyn driver inputs, beam decks); this scene's steps are set in the deck");
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

Schema toy_scene_schema() {
  return Schema::map({
      {"simulation", toy_simulation_section().schema().doc("time stepping and coupling")},
      {"output", output_schema().optional().doc("what to write; absent = HDF5, all channels")},
      {"toy_oscillators", Schema::map({
                              {"slow", oscillator_section<toy::SlowOscillator::Params>(kSlow).schema()},
                              {"fast", oscillator_section<toy::FastOscillator::Params>(kFast).schema()},
                          }).doc("verification scene: coupled oscillators with an exact solution")},
  });
}

RunReport run_toy_scene(const io::ValidatedDeck& deck, const RunRequest& request, const ProgressCallback& progress) {
  const CouplingSettings settings = read_settings(deck, request);
  const auto slow = oscillator_section<toy::SlowOscillator::Params>(kSlow).read(deck.section("toy_oscillators.slow"));
  const auto fast = oscillator_section<toy::FastOscillator::Params>(kFast).read(deck.section("toy_oscillators.fast"));
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
  scene.metadata.seeds = {toy_simulation(deck).seed};
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
