#include "scenes/beam_scene.hpp"

#include <fmt/format.h>

#include "beamdyn/beamdyn_channels.hpp"
#include "beamdyn/beamdyn_run.hpp"
#include "beamdyn/beamdyn_setup.hpp"
#include "decks/deck_helpers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {
namespace {

using io::Schema;

Schema station_schema() {
  return Schema::map({
      {"eta", Schema::number().at_least(0.0).at_most(1.0).doc("arclength fraction from root (0) to tip (1)")},
      {"stiffness", Schema::sequence(Schema::number()).min_items(36).max_items(36)
                        .doc("6×6 sectional stiffness, row by row, BeamDyn order (shear 1, shear 2, axial, "
                             "bending 1, bending 2, torsion; axis 3 along the beam) [N, N·m, N·m²]")},
      {"mass", Schema::sequence(Schema::number()).min_items(36).max_items(36)
                   .doc("6×6 sectional mass per length about the reference line, row by row, BeamDyn order "
                        "[kg/m, kg, kg·m]")},
  });
}

Schema beam_schema() {
  return Schema::map({
      {"segments", Schema::integer().at_least(1).at_most(100000).default_value(48).doc("finite volumes")},
      {"integrator", Schema::choice({"generalized_alpha", "erk"}).default_value("generalized_alpha")
                         .doc("integrator of the locally linear system in each step")},
      {"spectral_radius", Schema::number().at_least(0.0).at_most(1.0).default_value(0.0)
                              .doc("generalized-α ρ∞ (0: most high-frequency dissipation)")},
      {"key_points_m", Schema::sequence(number_vector(3, "x, y, z")).min_items(2)
                           .doc("reference line through these points, root first, z increasing")},
      {"twist_deg", Schema::sequence(Schema::number()).min_items(2).doc("structural twist at each key point (BeamDyn sign)")},
      {"fit_degree", Schema::integer().at_least(1).at_most(20).default_value(5)
                         .doc("degree of the least-squares polynomial through the key points (BeamDyn's order_elem)")},
      {"stations", Schema::sequence(station_schema()).min_items(1).doc("sectional properties, eta ascending")},
      {"damping_mu_s", number_vector(6, "stiffness-proportional damping per component (BeamDyn mu)").optional()},
      {"mass_damping_1_s", Schema::number().unit("1_s").at_least(0.0).default_value(0.0).doc("mass-proportional damping μ_M")},
  });
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
      {"output", Schema::map({
                     {"format", Schema::choice({"h5", "out", "both"}).default_value("h5").doc("HDF5, OpenFAST text .out, or both")},
                     {"decimation", Schema::integer().at_least(1).default_value(1).doc("write every k-th step")},
                     {"channels", Schema::sequence(Schema::string()).optional().doc("BeamDyn channel names; absent = all")},
                 }).optional().doc("what to write")},
      {"beam", beam_schema().doc("the beam: reference line, sections, damping, discretisation")},
      {"root", Schema::map({
                   {"position_m", number_vector(3, "root position, global frame").optional()},
                   {"angular_velocity_rad_s", number_vector(3, "constant angular velocity of the root about the global origin").optional()},
               }).optional().doc("root motion; absent = fixed at the origin")},
      {"gravity_m_s2", number_vector(3, "gravity, global frame").optional()},
      {"loads", loads_schema().optional().doc("dead external loads")},
  });
}

bool is_beam_scene(const std::filesystem::path& deck) {
  const io::LoadedDeck loaded = io::load_deck(deck);
  return loaded.root.find("beam") != nullptr;
}

RunReport run_beam_scene(const RunRequest& request, const ProgressCallback& progress) {
  const io::ValidatedDeck deck = io::read_deck(beam_scene_schema(), request.deck_path);
  const io::ValidatedDeck b = deck.section("beam");
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < b.size("key_points_m"); ++i) {
    const auto p = b.numbers(fmt::format("key_points_m[{}]", i));
    points.emplace_back(p[0], p[1], p[2]);
  }
  const std::vector<double> twist = b.numbers("twist_deg");
  if (twist.size() != points.size())
    throw InputError({"beam", std::nullopt, "beam.twist_deg", ""},
                     where(deck, "beam.twist_deg") + fmt::format(": expected one twist per key point ({}), found {}", points.size(), twist.size()));
  const int degree = std::min(static_cast<int>(b.integer("fit_degree")), static_cast<int>(points.size()) - 1);
  beam::ReferenceLine line = [&] {
    try {
      return beamdyn_reference_line(points, twist, degree);
    } catch (const InputError& e) {
      throw InputError(e.context(), where(deck, "beam.key_points_m") + ": " + e.message());
    }
  }();
  BeamDynSetup setup{.definition = {std::move(line), {}}};
  double last_eta = -1.0;
  for (std::size_t i = 0; i < b.size("stations"); ++i) {
    const io::ValidatedDeck st = b.section(fmt::format("stations[{}]", i));
    const double eta = st.number("eta");
    if (!(eta > last_eta))
      throw InputError({"beam", std::nullopt, "eta", ""}, where(deck, fmt::format("beam.stations[{}].eta", i)) + ": eta must increase");
    last_eta = eta;
    setup.definition.stations.push_back({eta, mat6(st, "stiffness"), mat6(st, "mass")});
  }
  if (b.has("damping_mu_s")) {
    const auto mu = b.numbers("damping_mu_s");
    setup.definition.stiffness_damping = Eigen::Map<const Vec6>(mu.data());
  }
  setup.definition.mass_damping_1_s = b.number("mass_damping_1_s");
  setup.root_position_m = vec3_or_zero(deck, "root.position_m");
  setup.angular_velocity_rad_s = vec3_or_zero(deck, "root.angular_velocity_rad_s");
  setup.gravity_m_s2 = vec3_or_zero(deck, "gravity_m_s2");
  setup.distributed_load << vec3_or_zero(deck, "loads.distributed_force_N_m"), vec3_or_zero(deck, "loads.distributed_moment_N_m_m");
  setup.tip_load << vec3_or_zero(deck, "loads.tip_force_N"), vec3_or_zero(deck, "loads.tip_moment_N_m");
  setup.dynamic = deck.string("simulation.analysis") == "dynamic";
  setup.t_final_s = deck.number("simulation.t_max_s");
  setup.dt_s = deck.number("simulation.dt_s");
  setup.spectral_radius = b.number("spectral_radius");

  SingleBeamRun how;
  how.segments = request.beam_segments.value_or(static_cast<int>(b.integer("segments")));
  how.integrator = request.beam_integrator.value_or(b.string("integrator"));
  how.matrix_max_age = request.beam_matrix_max_age.value_or(how.matrix_max_age);
  how.skip_unknown_channels = false;
  how.scene = "beam";
  how.deck_hash = deck.hash();
  if (deck.has("output")) {
    how.decimation = deck.integer("output.decimation");
    if (deck.has("output.channels")) {
      how.channels = deck.strings("output.channels");
      for (std::size_t i = 0; i < how.channels.size(); ++i)
        if (!find_beamdyn_channel(how.channels[i]))
          throw InputError({"beam", std::nullopt, how.channels[i], ""},
                           where(deck, fmt::format("output.channels[{}]", i)) + ": unknown beam channel '" + how.channels[i] + "'");
    }
  }
  RunRequest r = request;
  if (!r.output_format) r.output_format = deck.has("output") ? deck.string("output.format") : "h5";
  if (!r.output_base) r.output_base = std::filesystem::path("runs") / request.deck_path.stem();
  return run_single_beam(setup, how, r, progress);
}

}  // namespace fowtsim::driver
