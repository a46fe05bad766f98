#include "scenes/beam_scene.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "beamdyn/beamdyn_channels.hpp"
#include "beamdyn/beamdyn_run.hpp"
#include "beamdyn/beamdyn_setup.hpp"
#include "decks/beam_deck.hpp"
#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/error.hpp"
#include "scenes/scene_runner.hpp"

namespace fowtsim::driver {
namespace {

using io::Schema;

// The `beam:` keys (decks/beam_deck.hpp): 48 finite volumes unless the deck says, at most 100,000.
const DeckSection<BeamKeys>& beam_keys() {
  static const DeckSection<BeamKeys> section = beam_section(48, 100000);
  return section;
}

// The scene's keys besides `beam` and `output`, each once with the field it fills
// (decks/deck_section.hpp); absent vectors stay zero.
struct RootKeys {
  Vec3 position_m = Vec3::Zero();
  Vec3 angular_velocity_rad_s = Vec3::Zero();
};
struct LoadKeys {
  Vec3 distributed_force_N_m = Vec3::Zero(), distributed_moment_N_m_m = Vec3::Zero();
  Vec3 tip_force_N = Vec3::Zero(), tip_moment_N_m = Vec3::Zero();
};
struct SceneKeys {
  std::string analysis;
  double t_max_s = 0.0, dt_s = 0.0;
  RootKeys root;
  Vec3 gravity_m_s2 = Vec3::Zero();
  LoadKeys loads;
};

const DeckSection<SceneKeys>& scene_keys() {
  static const DeckSection<SceneKeys> section = [] {
    DeckSection<SceneKeys> simulation;  // the simulation mapping's keys, into the same struct
    simulation.key("analysis", Schema::choice({"static", "dynamic"}).default_value("dynamic").doc("solve"), &SceneKeys::analysis)
        .key("t_max_s", Schema::number().unit("s").greater_than(0.0).default_value(1.0).doc("simulated time (dynamic)"),
             &SceneKeys::t_max_s)
        .key("dt_s", Schema::number().unit("s").greater_than(0.0).default_value(0.005).doc("beam time step (dynamic)"),
             &SceneKeys::dt_s);
    DeckSection<RootKeys> root;
    root.key("position_m", number_vector(3, "root position, global frame").optional(), &RootKeys::position_m)
        .key("angular_velocity_rad_s", number_vector(3, "constant angular velocity of the root about the global origin").optional(),
             &RootKeys::angular_velocity_rad_s);
    DeckSection<LoadKeys> loads;
    loads.key("distributed_force_N_m", number_vector(3, "dead distributed force per length, global frame").optional(),
              &LoadKeys::distributed_force_N_m)
        .key("distributed_moment_N_m_m", number_vector(3, "dead distributed moment per length, global frame").optional(),
             &LoadKeys::distributed_moment_N_m_m)
        .key("tip_force_N", number_vector(3, "dead tip force, global frame").optional(), &LoadKeys::tip_force_N)
        .key("tip_moment_N_m", number_vector(3, "dead tip moment, global frame").optional(), &LoadKeys::tip_moment_N_m);
    DeckSection<SceneKeys> s;
    s.section("simulation", simulation, [](SceneKeys& k) -> SceneKeys& { return k; }, false, "static or dynamic analysis")
        .section("root", root, &SceneKeys::root, true, "root motion; absent = fixed at the origin")
        .key("gravity_m_s2", number_vector(3, "gravity, global frame").optional(), &SceneKeys::gravity_m_s2)
        .section("loads", loads, &SceneKeys::loads, true, "dead external loads");
    return s;
  }();
  return section;
}

}  // namespace

Schema beam_scene_schema() {
  const Schema keys = scene_keys().schema();
  auto field = [&](const char* name) {
    for (const io::SchemaField& f : keys.spec().fields)
      if (f.key == name) return f;
    throw std::logic_error(std::string("beam scene key ") + name);
  };
  // The documented order: simulation, output, beam, root, gravity, loads.
  return Schema::map({
      field("simulation"),
      {"output", output_schema().optional().doc("what to write (BeamDyn channel names)")},
      {"beam", beam_keys().schema().doc("the beam: reference line, sections, damping, discretisation")},
      field("root"),
      field("gravity_m_s2"),
      field("loads"),
  });
}

RunReport run_beam_scene(const RunRequest& request, const ProgressCallback& progress) {
  const io::ValidatedDeck deck = io::read_deck(beam_scene_schema(), request.deck_path, request.deck_settings);
  BeamKeys beam;
  beam_keys().read_into(deck.section("beam"), beam);
  SceneKeys keys;
  scene_keys().read_into(deck, keys);
  BeamDynSetup setup{.definition = beam_definition(deck, "beam", beam)};
  setup.root_position_m = keys.root.position_m;
  setup.angular_velocity_rad_s = keys.root.angular_velocity_rad_s;
  setup.gravity_m_s2 = keys.gravity_m_s2;
  setup.distributed_load << keys.loads.distributed_force_N_m, keys.loads.distributed_moment_N_m_m;
  setup.tip_load << keys.loads.tip_force_N, keys.loads.tip_moment_N_m;
  setup.dynamic = keys.analysis == "dynamic";
  setup.t_final_s = keys.t_max_s;
  setup.dt_s = keys.dt_s;
  setup.spectral_radius = beam.spectral_radius;

  SingleBeamRun how;
  how.segments = request.beam_segments.value_or(beam.segments);
  how.integrator = request.beam_integrator.value_or(beam.integrator);
  how.matrix_max_age = request.beam_matrix_max_age.value_or(how.matrix_max_age);
  how.skip_unknown_channels = false;
  how.scene = "beam";
  how.deck_hash = deck.hash();
  const OutputKeys output = output_keys(deck);
  how.decimation = output.decimation;
  if (output.channels) {
    how.channels = *output.channels;
    for (std::size_t i = 0; i < how.channels.size(); ++i)
      if (!find_beamdyn_channel(how.channels[i]))
        throw InputError({"beam", std::nullopt, how.channels[i], ""},
                         where(deck, fmt::format("output.channels[{}]", i)) + ": unknown beam channel '" + how.channels[i] + "'");
  }
  RunRequest r = request;
  if (!r.output_format) r.output_format = output.format;
  if (!r.output_base) r.output_base = std::filesystem::path("runs") / request.deck_path.stem();
  return run_single_beam(setup, how, r, progress);
}

}  // namespace fowtsim::driver
