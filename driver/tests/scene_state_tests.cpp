// Scene states (scenes/floating_scene.hpp, coupling/multi_rate_scheduler.hpp): each one plain,
// copyable struct whose field lists name every field; the floating scene's is read by a row
// without change, and a copy of it continues bit-identically.
#include <fstream>

#include <catch2/catch.hpp>

#include "coupling/multi_rate_scheduler.hpp"
#include "fowtsim/core/fields.hpp"
#include "fowtsim/io/deck.hpp"
#include "fowtsim/testing/skip.hpp"
#include "fowtsim/toy/fast_oscillator.hpp"
#include "fowtsim/toy/slow_oscillator.hpp"
#include "run/checkpoint.hpp"
#include "scenes/floating_scene.hpp"
#include "scenes/slender_analysis.hpp"
#include "scenes/slender_scene.hpp"
#include "scenes/slender_time_domain.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

template <class T>
void check_every_field_listed(const char* name) {
  INFO(name << ": a field added to the struct must be added to its field list (io, or scratch for workspace)");
  CHECK(listed_field_count<T>() == member_count<T>());
}

// A short deck: the shipped `deck` for `t_max_s`, every channel written.
io::ValidatedDeck short_deck(const std::string& name, const std::string& deck, const std::string& overrides = "") {
  const auto dir = testing::scratch_dir("scene_state_" + name);
  std::ofstream(dir / "deck.yaml") << "include: [" << (testing::source_dir() / "inputs" / deck).string() << "]\n" << overrides;
  return io::read_deck(floating_scene_schema(), dir / "deck.yaml");
}

// Steps a scene to t = steps·dt, then checks that a row leaves the state's bytes as they were and
// that a copy of the state, stepped on, gives the same bytes and rows as the original.
void check_row_and_copy(const io::ValidatedDeck& deck, int steps) {
  FloatingScene scene(deck);
  FloatingState s = scene.make_state();
  const double dt = deck.number("simulation.dt_s");
  for (int k = 0; k < steps; ++k) scene.step(k * dt, dt, s);
  const double t = steps * dt;

  const std::string before = state_bytes(s);
  std::vector<double> row(scene.written().size());
  scene.row(t, s, row);
  CHECK(state_bytes(s) == before);

  FloatingState copy = s;
  for (int k = 0; k < 3; ++k) {
    scene.step(t + k * dt, dt, s);
    scene.step(t + k * dt, dt, copy);
  }
  CHECK(state_bytes(copy) == state_bytes(s));
  std::vector<double> row_copy(row.size());
  scene.row(t + 3 * dt, s, row);
  scene.row(t + 3 * dt, copy, row_copy);
  CHECK(row == row_copy);
}

}  // namespace

TEST_CASE("every field of the scene states is in its field list", "[unit][scene_state]") {
  check_every_field_listed<multibody::State>("multibody::State");
  check_every_field_listed<hydro::RadiationState>("hydro::RadiationState");
  check_every_field_listed<hydro::Hydro::State>("hydro::Hydro::State");
  check_every_field_listed<aero::Aero::State>("aero::Aero::State");
  check_every_field_listed<aero::Aero::Input>("aero::Aero::Input");
  check_every_field_listed<aero::Aero::Output>("aero::Aero::Output");
  check_every_field_listed<aero::RotorResult>("aero::RotorResult");
  check_every_field_listed<beam::BeamState>("beam::BeamState");
  check_every_field_listed<beam::StepMatrixCache>("beam::StepMatrixCache");
  check_every_field_listed<SeaModules::Data>("SeaModules::Data");
  check_every_field_listed<RotorAero::Data>("RotorAero::Data");
  check_every_field_listed<FlexibleRotorState>("FlexibleRotorState");
  check_every_field_listed<ShaftMotion>("ShaftMotion");
  check_every_field_listed<FlexibleRotor::HubLoad>("FlexibleRotor::HubLoad");
  check_every_field_listed<FlexibleRotor::Data>("FlexibleRotor::Data");
  check_every_field_listed<TurbineBlades::SpinProfile>("TurbineBlades::SpinProfile");
  check_every_field_listed<TurbineBlades::Data>("TurbineBlades::Data");
  check_every_field_listed<TurbineController::Data>("TurbineController::Data");
  check_every_field_listed<TurbineRiser::Data>("TurbineRiser::Data");
  check_every_field_listed<HeldDemands>("HeldDemands");
  check_every_field_listed<FloatingState>("FloatingState");
  // The toy oscillators' scene state: the scheduler's module pair.
  check_every_field_listed<FrameMotion>("FrameMotion");
  check_every_field_listed<RootLoads>("RootLoads");
  check_every_field_listed<toy::SlowOscillator::State>("toy::SlowOscillator::State");
  check_every_field_listed<toy::SlowOscillator::Input>("toy::SlowOscillator::Input");
  check_every_field_listed<toy::FastOscillator::State>("toy::FastOscillator::State");
  check_every_field_listed<toy::FastOscillator::Input>("toy::FastOscillator::Input");
  check_every_field_listed<ModulePair<toy::SlowOscillator, toy::FastOscillator>::State>("ModulePair::State");
  // The slender scene's state: the module's, the sea's current block and the statistics' sums.
  check_every_field_listed<slender::SlenderBody::State>("slender::SlenderBody::State");
  check_every_field_listed<slender::WaveBlock>("slender::WaveBlock");
  check_every_field_listed<slender::HarmonicSums>("slender::HarmonicSums");
  check_every_field_listed<slender::DeviationSums>("slender::DeviationSums");
  check_every_field_listed<SlenderTimeState>("SlenderTimeState");
}

TEST_CASE("slender time domain: a row leaves the scene state as it is, and a copy continues bit-identically",
          "[unit][scene_state]") {
  const SlenderCase c = read_slender_case(testing::source_dir() / "inputs/slender/riser_jonswap.yaml",
                                          {"simulation.t_max_s=60.0", "analysis.transient_s=10.0"});
  const SlenderResults r = solve_frequency_domain(c.deck);
  SlenderTimeDomain time_domain(c.deck, r.model, r.modes, c.dt_s, 1200);
  SlenderTimeState s = time_domain.make_state();
  for (int k = 0; k < 700; ++k) time_domain.step(s);  // past the window's start, near the first block's end
  const std::string before = state_bytes(s);
  const VecX row = time_domain.outputs(s).moment_inertia_relief_N_m;
  CHECK(state_bytes(s) == before);
  SlenderTimeState copy = s;
  for (int k = 0; k < 100; ++k) {  // into the sea's second block
    time_domain.step(s);
    time_domain.step(copy);
  }
  CHECK(s.waves.first_sample > 0);
  CHECK(state_bytes(copy) == state_bytes(s));
  const VecX copied = time_domain.outputs(copy).moment_inertia_relief_N_m;  // outputs() returns the workspace's
  CHECK(copied == time_domain.outputs(s).moment_inertia_relief_N_m);
  CHECK(row.allFinite());
}

TEST_CASE("member_count counts an aggregate's members, whatever their types", "[unit][scene_state]") {
  struct Mixed {
    Vec3 v = Vec3::Zero();
    std::vector<double> list;
    std::array<double, 3> fixed{};
    std::optional<int> maybe;
    double x = 0.0;
  };
  STATIC_REQUIRE(member_count<Mixed>() == 5);
}

TEST_CASE("flexible blades: a row leaves the scene state as it is, and a copy continues bit-identically",
          "[unit][scene_state]") {
  check_row_and_copy(short_deck("flexible", "oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml"), 10);
}

TEST_CASE("a riser hung from the spar: a row leaves the scene state as it is, and a copy continues bit-identically",
          "[unit][scene_state][riser]") {
  check_row_and_copy(short_deck("riser", "oc3_hywind/turbine_riser_15mps.yaml",
                                "waves: {model: regular, height_m: 6.0, period_s: 10.0}\n"), 10);
}

TEST_CASE("rigid blades with unsteady aerodynamics: a row leaves the scene state as it is, and a copy continues "
          "bit-identically",
          "[unit][scene_state]") {
  check_row_and_copy(short_deck("rigid_ua", "oc3_hywind/turbine_ntm_12mps_irregular_unsteady_aero.yaml"), 10);
}

TEST_CASE("potential flow with its radiation memory: a row leaves the scene state as it is, and a copy continues "
          "bit-identically",
          "[unit][scene_state]") {
  testing::shared_dir_or_skip();  // the WAMIT files are read from the shared reference data
  check_row_and_copy(short_deck("wamit", "oc3_hywind/free_decay_pitch_wamit.yaml"), 10);
}
