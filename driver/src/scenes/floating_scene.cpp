#include "scenes/floating_scene.hpp"

#include "decks/deck_helpers.hpp"
#include "decks/hydro_deck.hpp"
#include "decks/mooring_deck.hpp"
#include "decks/structure_deck.hpp"
#include "decks/waves_deck.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "run/channel_selection.hpp"
#include "scenes/scene_runner.hpp"
#include "scenes/sea_modules.hpp"

namespace fowtsim::driver {
namespace {

using io::Schema;

// Platform pose and velocity of a multibody state, in the form hydro and mooring take.
FrameMotion platform_motion(const multibody::State& s) {
  FrameMotion m;
  m.position_m = s.position_m;
  m.orientation = s.orientation.toRotationMatrix();
  m.velocity_m_s = s.velocity_m_s;
  m.angular_velocity_rad_s = s.angular_velocity_rad_s;
  return m;
}

// The loads on the structure at any Runge–Kutta stage: the sea (hydro with its added mass, and
// mooring) at the stage pose. Generator torque stays zero: the rotor is parked or spins freely
// (no aerodynamics in this scene).
class StageLoads final : public multibody::LoadProvider {
 public:
  explicit StageLoads(SeaModules& sea) : sea_(sea) {}
  void loads(double t, const multibody::State& s, multibody::AppliedLoads& out) override {
    sea_.evaluate(t, platform_motion(s));
    const Vec6 load = sea_.platform_load();
    out.platform_force_N += load.head<3>();
    out.platform_moment_N_m += load.tail<3>();
    out.platform_added_mass = sea_.added_mass();
  }

 private:
  SeaModules& sea_;
};

}  // namespace

Schema floating_scene_schema() {
  return Schema::map({
      {"simulation", simulation_schema("large (coupling) step").doc("time span and step")},
      {"output", output_schema().optional().doc("what to write")},
      {"structure", structure_schema().doc("rigid multibody: platform, tower, nacelle, rotor, drivetrain")},
      {"waves", waves_schema().optional().doc("incident sea; absent = still water")},
      {"hydro", hydro_schema().optional().doc("Morison strips, hydrostatics, linear extras; absent = none")},
      {"mooring", mooring_schema().optional().doc("mooring lines; absent = none")},
  });
}

bool is_floating_scene(const std::filesystem::path& deck) {
  return io::load_deck(deck).root.find("structure") != nullptr;
}

RunReport run_floating_scene(const RunRequest& request, const ProgressCallback& progress) {
  const io::ValidatedDeck deck = io::read_deck(floating_scene_schema(), request.deck_path);
  const multibody::Model model = [&] {
    try {
      return multibody::make_model(structure_params(deck.section("structure")));
    } catch (const InputError& e) {
      rethrow_located(deck.section("structure"), e);
    }
  }();
  multibody::State state = multibody::Multibody::make_state(model);
  SeaModules sea(deck, platform_motion(state));
  StageLoads stage_loads(sea);

  std::vector<ChannelInfo> all = multibody::Multibody::channels(model);
  const std::size_t sea_first = all.size();
  for (const ChannelInfo& c : sea.channels()) all.push_back(c);
  const std::vector<std::size_t> picked = select_channels(deck, all, "floating");

  FixedStepScene scene;
  for (std::size_t i : picked) scene.written.push_back(all[i]);
  scene.metadata.seeds = sea.seeds();
  scene.metadata.extra = {{"scene", "floating"}};
  std::vector<double> values(all.size());
  scene.step = [&](double t, double dt) { multibody::Multibody::advance(model, stage_loads, t, dt, state); };
  scene.row = [&](double t, std::span<double> row) {
    multibody::AppliedLoads loads;
    stage_loads.loads(t, state, loads);
    const multibody::Output mo = multibody::Multibody::outputs(model, loads, state, t);
    std::copy(mo.channels.begin(), mo.channels.end(), values.begin());
    sea.channel_values(t, std::span<double>(values).subspan(sea_first));
    for (std::size_t k = 0; k < picked.size(); ++k) row[k] = values[picked[k]];
  };
  RunReport report = run_fixed_steps(request, deck, std::move(scene), progress);
  report.coupling = "rigid multibody, sea loads at every RK4 stage";
  return report;
}

}  // namespace fowtsim::driver
