#include "scenes/beam_scene.hpp"

#include <fmt/format.h>

#include "beamdyn/beamdyn_channels.hpp"
#include "beamdyn/beamdyn_run.hpp"
#include "beamdyn/beamdyn_setup.hpp"
#include "decks/beam_deck.hpp"
#include "decks/deck_helpers.hpp"
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

Schema loads_schema() {
  return Schema::map({
      {"distributed_force_N_m", number_vector(3, "dead distributed force per length, global frame").optional()},
      {"distributed_moment_N_m_m", number_vector(3, "dead distributed moment per length, global frame").optional()},
      {"tip_force_N", number_vector(3, "dead tip force, global frame").optional()},
      {"tip_moment_N_m", number_vector(3, "dead tip moment, global frame").optional()},
  });
}

Vec3 vec3_or_zero(const io::ValidatedDeck& d, const std::string& path) {
  if (!d.has(path)) return Vec3::Zero();
  const std::vector<double> v = d.numbers(path);
  return Vec3(v[0], v[1], v[2]);
}

}  // namespace

Schema beam_scene_schema() {
  return Schema::map({
      {"simulation", Schema::map({
                         {"analysis", Schema::choice({"static", "dynamic"}).default_value("dynamic").doc("solve")},
                         {"t_max_s", Schema::number().unit("s").greater_than(0.0).default_value(1.0).doc("simulated time (dynamic)")},
                         {"dt_s", Schema::number().unit("s").greater_than(0.0).default_value(0.005).doc("beam time step (dynamic)")},
                     }).doc("static or dynamic analysis")},
      {"output", output_schema().optional().doc("what to write (BeamDyn channel names)")},
      {"beam", beam_keys().schema().doc("the beam: reference line, sections, damping, discretisation")},
      {"root", Schema::map({
                   {"position_m", number_vector(3, "root position, global frame").optional()},
                   {"angular_velocity_rad_s", number_vector(3, "constant angular velocity of the root about the global origin").optional()},
               }).optional().doc("root motion; absent = fixed at the origin")},
      {"gravity_m_s2", number_vector(3, "gravity, global frame").optional()},
      {"loads", loads_schema().optional().doc("dead external loads")},
  });
}

RunReport run_beam_scene(const RunRequest& request, const ProgressCallback& progress) {
  const io::ValidatedDeck deck = io::read_deck(beam_scene_schema(), request.deck_path);
  BeamKeys beam;
  beam_keys().read_into(deck.section("beam"), beam);
  BeamDynSetup setup{.definition = beam_definition(deck, "beam", beam)};
  setup.root_position_m = vec3_or_zero(deck, "root.position_m");
  setup.angular_velocity_rad_s = vec3_or_zero(deck, "root.angular_velocity_rad_s");
  setup.gravity_m_s2 = vec3_or_zero(deck, "gravity_m_s2");
  setup.distributed_load << vec3_or_zero(deck, "loads.distributed_force_N_m"), vec3_or_zero(deck, "loads.distributed_moment_N_m_m");
  setup.tip_load << vec3_or_zero(deck, "loads.tip_force_N"), vec3_or_zero(deck, "loads.tip_moment_N_m");
  setup.dynamic = deck.string("simulation.analysis") == "dynamic";
  setup.t_final_s = deck.number("simulation.t_max_s");
  setup.dt_s = deck.number("simulation.dt_s");
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
