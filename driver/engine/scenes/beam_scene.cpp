#include "scenes/beam_scene.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "beamdyn/beamdyn_channels.hpp"
#include "beamdyn/beamdyn_run.hpp"
#include "beamdyn/beamdyn_setup.hpp"
#include "decks/beam_deck.hpp"
#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/beam/pipe.hpp"
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
  bool static_start = false;
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
             &SceneKeys::dt_s)
        .key("static_start", Schema::boolean().default_value(false)
                                 .doc("dynamic: start from the static equilibrium under the loads at the start time"),
             &SceneKeys::static_start);
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

// The `pipe:` and `fluid:` keys of the pipe scene (beam::PipeDefinition).
struct PipeKeys {
  int segments = 0;
  std::string integrator;
  double spectral_radius = 0.0;
  double length_m = 0.0, outer_diameter_m = 0.0, inner_diameter_m = 0.0, youngs_modulus_Pa = 0.0, poisson_ratio = 0.0;
  double shear_coefficient = 1.0, density_kg_m3 = 0.0, damping_mu_s = 0.0;
  std::string root_end, tip_end;
};
struct FluidKeys {
  double density_kg_m3 = 0.0, velocity_m_s = 0.0, viscosity_Pa_s = 0.0, roughness_m = 0.0, pressure_Pa = 0.0;
  std::optional<std::string> pressure_at;
  std::string valve;
  bool seed_momentum_flux = false;
};
// The pipe scene's `sea:` (beam::SurroundingWater) and `tip_motion:` (beam::RampAndSway) keys.
struct SeaKeys {
  double density_kg_m3 = 0.0, inertia_coefficient = 0.0, drag_coefficient = 0.0, surface_z_m = 0.0;
  Vec3 current_m_s = Vec3::Zero();
};
struct TipMotionKeys {
  double stretch_m = 0.0, stretch_time_s = 0.0, sway_amplitude_m = 0.0, sway_period_s = 0.0, sway_start_s = 0.0;
  Vec3 sway_direction = Vec3::UnitY();
};

const DeckSection<PipeKeys>& pipe_keys() {
  static const DeckSection<PipeKeys> section = [] {
    auto positive = [](const char* unit, const char* doc) { return Schema::number().unit(unit).greater_than(0.0).doc(doc); };
    DeckSection<PipeKeys> p;
    p.key("segments", Schema::integer().at_least(1).at_most(100000).default_value(40).doc("finite volumes"), &PipeKeys::segments)
        .key("integrator", Schema::choice({"generalized_alpha", "erk"}).default_value("generalized_alpha")
                               .doc("integrator of the locally linear system in each step"),
             &PipeKeys::integrator)
        .key("spectral_radius", Schema::number().at_least(0.0).at_most(1.0).default_value(0.0).doc("generalized-α ρ∞"),
             &PipeKeys::spectral_radius)
        .key("length_m", positive("m", "length of the straight pipe, along the root frame's z"), &PipeKeys::length_m)
        .key("outer_diameter_m", positive("m", "outer diameter of the wall"), &PipeKeys::outer_diameter_m)
        .key("inner_diameter_m", Schema::number().unit("m").at_least(0.0).doc("bore (flow passage) diameter"),
             &PipeKeys::inner_diameter_m)
        .key("youngs_modulus_Pa", positive("Pa", "Young's modulus of the wall"), &PipeKeys::youngs_modulus_Pa)
        .key("poisson_ratio", Schema::number().greater_than(-1.0).less_than(0.5).default_value(0.3).doc("G = E / (2 (1 + ν))"),
             &PipeKeys::poisson_ratio)
        .key("shear_coefficient", Schema::number().greater_than(0.0).default_value(1.0).doc("k in k G A (the seed: 1)"),
             &PipeKeys::shear_coefficient)
        .key("density_kg_m3", positive("kg_m3", "density of the wall"), &PipeKeys::density_kg_m3)
        .key("damping_mu_s", Schema::number().unit("s").at_least(0.0).default_value(0.0).doc("stiffness-proportional damping μ_K"),
             &PipeKeys::damping_mu_s)
        .key("root_end", Schema::choice({"clamped", "pinned"}).default_value("clamped").doc("how the root is held"),
             &PipeKeys::root_end)
        .key("tip_end", Schema::choice({"free", "clamped", "pinned"}).default_value("free")
                            .doc("how the tip is held (free: the fluid leaves as a jet)"),
             &PipeKeys::tip_end);
    return p;
  }();
  return section;
}

const DeckSection<FluidKeys>& fluid_keys() {
  static const DeckSection<FluidKeys> section = [] {
    auto non_negative = [](const char* unit, const char* doc) { return Schema::number().unit(unit).at_least(0.0).default_value(0.0).doc(doc); };
    DeckSection<FluidKeys> f;
    f.key("density_kg_m3", non_negative("kg_m3", "density of the fluid inside"), &FluidKeys::density_kg_m3)
        .key("velocity_m_s", Schema::number().unit("m_s").default_value(0.0).doc("mean flow speed, + from root to tip"),
             &FluidKeys::velocity_m_s)
        .key("viscosity_Pa_s", non_negative("Pa_s", "dynamic viscosity (0: inviscid, no wall friction)"), &FluidKeys::viscosity_Pa_s)
        .key("roughness_m", non_negative("m", "wall roughness ε of the Haaland friction factor"), &FluidKeys::roughness_m)
        .key("pressure_Pa", Schema::number().unit("Pa").default_value(0.0).doc("internal gauge pressure at the end named by pressure_at"),
             &FluidKeys::pressure_Pa)
        .key("pressure_at", Schema::choice({"tip", "root"}).optional()
                                .doc("where pressure_Pa is given (default: the tip, or the open end when a valve is closed)"),
             &FluidKeys::pressure_at)
        .key("valve", Schema::choice({"open", "closed_tip", "closed_root"}).default_value("open")
                          .doc("a closed valve stops the flow (velocity_m_s must be 0): closed_tip holds the source's pressure "
                               "(given at the root), closed_root leaves the column open at the tip (pressure_Pa there, "
                               "0 = atmospheric)"),
             &FluidKeys::valve)
        .key("seed_momentum_flux", Schema::boolean().default_value(false)
                                       .doc("the seed's eq. 3.17 flux (half the flow's Coriolis force; for comparison only)"),
             &FluidKeys::seed_momentum_flux);
    return f;
  }();
  return section;
}

const DeckSection<SeaKeys>& sea_keys() {
  static const DeckSection<SeaKeys> section = [] {
    DeckSection<SeaKeys> w;
    w.key("density_kg_m3", Schema::number().unit("kg_m3").greater_than(0.0).default_value(1025.0).doc("sea water density"),
          &SeaKeys::density_kg_m3)
        .key("inertia_coefficient", Schema::number().at_least(1.0).default_value(1.0)
                                        .doc("Morison C_m; the added mass is (C_m − 1) ρ A_e normal to the axis (still water)"),
             &SeaKeys::inertia_coefficient)
        .key("drag_coefficient", Schema::number().at_least(0.0).default_value(0.0)
                                     .doc("Morison C_d on the normal velocity of the water relative to the pipe"),
             &SeaKeys::drag_coefficient)
        .key("surface_z_m", Schema::number().unit("m").default_value(0.0)
                                .doc("still-water level, global z: volumes whose node is above it are dry"),
             &SeaKeys::surface_z_m)
        .key("current_m_s", number_vector(3, "uniform current, global frame").optional(), &SeaKeys::current_m_s);
    return w;
  }();
  return section;
}

const DeckSection<TipMotionKeys>& tip_motion_keys() {
  static const DeckSection<TipMotionKeys> section = [] {
    auto length = [](const char* doc) { return Schema::number().unit("m").default_value(0.0).doc(doc); };
    auto time = [](double d, const char* doc) { return Schema::number().unit("s").greater_than(0.0).default_value(d).doc(doc); };
    DeckSection<TipMotionKeys> m;
    m.key("stretch_m", length("axial displacement of the tip, along the pipe from root to tip, reached at stretch_time_s "
                              "(seed 000 eq. 3.66)"),
          &TipMotionKeys::stretch_m)
        .key("stretch_time_s", time(1.0, "duration of the stretch's linear ramp from t = 0"), &TipMotionKeys::stretch_time_s)
        .key("sway_amplitude_m", length("amplitude A of the sway A sin(2π (t − sway_start_s)/sway_period_s) (eq. 3.67)"),
             &TipMotionKeys::sway_amplitude_m)
        .key("sway_period_s", time(10.0, "period of the sway"), &TipMotionKeys::sway_period_s)
        .key("sway_start_s", Schema::number().unit("s").at_least(0.0).default_value(0.0).doc("the sway starts here (0 before)"),
             &TipMotionKeys::sway_start_s)
        .key("sway_direction", number_vector(3, "direction of the sway, global frame (normalised)").optional(),
             &TipMotionKeys::sway_direction);
    return m;
  }();
  return section;
}

beam::EndCondition end_condition(const std::string& name) {
  return name == "pinned" ? beam::EndCondition::pinned : name == "clamped" ? beam::EndCondition::clamped : beam::EndCondition::free;
}

// The scene's own keys around the structure key (`beam` or `pipe`) in the documented order:
// simulation, output, the structure, root, gravity, loads (and fluid for the pipe).
Schema scene_schema(std::vector<io::SchemaField> structure) {
  const Schema keys = scene_keys().schema();
  auto field = [&](const char* name) {
    for (const io::SchemaField& f : keys.spec().fields)
      if (f.key == name) return f;
    throw std::logic_error(std::string("beam scene key ") + name);
  };
  std::vector<io::SchemaField> fields{field("simulation"),
                                      {"output", output_schema().optional().doc("what to write (BeamDyn channel names)")}};
  for (io::SchemaField& f : structure) fields.push_back(std::move(f));
  for (const char* name : {"root", "gravity_m_s2", "loads"}) fields.push_back(field(name));
  return Schema::map(std::move(fields));
}

// Runs one beam (or pipe) under the scene keys: root motion, gravity, dead loads, static or dynamic.
RunReport run_one_beam(const io::ValidatedDeck& deck, BeamDynSetup setup, int segments, const std::string& integrator,
                       double spectral_radius, const std::string& scene, const RunRequest& request,
                       const ProgressCallback& progress) {
  SceneKeys keys;
  scene_keys().read_into(deck, keys);
  setup.root_position_m = keys.root.position_m;
  setup.angular_velocity_rad_s = keys.root.angular_velocity_rad_s;
  setup.gravity_m_s2 = keys.gravity_m_s2;
  setup.distributed_load << keys.loads.distributed_force_N_m, keys.loads.distributed_moment_N_m_m;
  setup.tip_load << keys.loads.tip_force_N, keys.loads.tip_moment_N_m;
  setup.dynamic = keys.analysis == "dynamic";
  setup.quasi_static_init = setup.dynamic && keys.static_start;
  setup.t_final_s = keys.t_max_s;
  setup.dt_s = keys.dt_s;
  setup.spectral_radius = spectral_radius;

  SingleBeamRun how;
  how.segments = request.beam_segments.value_or(segments);
  how.integrator = request.beam_integrator.value_or(integrator);
  how.matrix_max_age = request.beam_matrix_max_age.value_or(how.matrix_max_age);
  how.skip_unknown_channels = false;
  how.scene = scene;
  how.deck_hash = deck.hash();
  const OutputKeys output = output_keys(deck);
  how.decimation = output.decimation;
  if (output.channels) {
    how.channels = *output.channels;
    for (std::size_t i = 0; i < how.channels.size(); ++i)
      if (!find_beamdyn_channel(how.channels[i]))
        throw InputError({scene, std::nullopt, how.channels[i], ""},
                         where(deck, fmt::format("output.channels[{}]", i)) + ": unknown beam channel '" + how.channels[i] + "'");
  }
  RunRequest r = request;
  if (!r.output_format) r.output_format = output.format;
  if (!r.output_base) r.output_base = std::filesystem::path("runs") / request.deck_path.stem();
  return run_single_beam(setup, how, r, progress);
}

}  // namespace

Schema beam_scene_schema() {
  return scene_schema({{"beam", beam_keys().schema().doc("the beam: reference line, sections, damping, discretisation")}});
}

RunReport run_beam_scene(const RunRequest& request, const ProgressCallback& progress) {
  const io::ValidatedDeck deck = io::read_deck(beam_scene_schema(), request.deck_path, request.deck_settings);
  BeamKeys beam;
  beam_keys().read_into(deck.section("beam"), beam);
  return run_one_beam(deck, BeamDynSetup{.definition = beam_definition(deck, "beam", beam)}, beam.segments, beam.integrator,
                      beam.spectral_radius, "beam", request, progress);
}

Schema pipe_scene_schema() {
  return scene_schema({{"pipe", pipe_keys().schema().doc("the pipe: straight tube, wall, ends, discretisation")},
                       {"fluid", fluid_keys().schema().optional().doc("the fluid inside; absent = an empty pipe")},
                       {"sea", sea_keys().schema().optional()
                                   .doc("still water around the pipe: buoyancy, Morison added mass and drag; absent = in air")},
                       {"tip_motion", tip_motion_keys().schema().optional()
                                          .doc("prescribed motion of a held tip (seed 000 eqs. 3.66–3.67); absent = at rest")}});
}

RunReport run_pipe_scene(const RunRequest& request, const ProgressCallback& progress) {
  const io::ValidatedDeck deck = io::read_deck(pipe_scene_schema(), request.deck_path, request.deck_settings);
  PipeKeys p;
  pipe_keys().read_into(deck.section("pipe"), p);
  FluidKeys f;
  if (deck.has("fluid")) fluid_keys().read_into(deck.section("fluid"), f);
  // A closed valve: no flow, and the pressure given at the open end.
  const std::string open_end = f.valve == "closed_tip" ? "root" : "tip";
  if (f.valve != "open" && f.velocity_m_s != 0.0)
    throw InputError({"pipe", std::nullopt, "fluid.velocity_m_s", "0 with a closed valve"},
                     where(deck, "fluid.velocity_m_s") + ": a closed valve (fluid.valve: " + f.valve + ") stops the flow; expected 0");
  if (f.valve != "open" && f.pressure_at && *f.pressure_at != open_end)
    throw InputError({"pipe", std::nullopt, "fluid.pressure_at", open_end},
                     where(deck, "fluid.pressure_at") + ": with fluid.valve: " + f.valve + " the pressure is given at the open end (" +
                         open_end + ")");
  const std::string pressure_at = f.pressure_at.value_or(open_end);
  const beam::PipeDefinition def{
      .line = beam::ReferenceLine::straight(Vec3::Zero(), Mat3::Identity(), p.length_m, [](double) { return 0.0; }),
      .outer_diameter_m = p.outer_diameter_m, .inner_diameter_m = p.inner_diameter_m,
      .youngs_modulus_pa = p.youngs_modulus_Pa, .poisson_ratio = p.poisson_ratio, .shear_coefficient = p.shear_coefficient,
      .pipe_density_kg_m3 = p.density_kg_m3, .fluid_density_kg_m3 = f.density_kg_m3, .flow_velocity_m_s = f.velocity_m_s,
      .fluid_viscosity_pa_s = f.viscosity_Pa_s, .wall_roughness_m = f.roughness_m, .stiffness_damping_s = p.damping_mu_s,
      .root_end = end_condition(p.root_end), .tip_end = end_condition(p.tip_end), .boundary_pressure_pa = f.pressure_Pa,
      .pressure_at_tip = pressure_at == "tip", .seed_momentum_flux = f.seed_momentum_flux};
  BeamDynSetup setup = [&] {
    try {  // the pipe's own checks (bore smaller than the tube, a fluid for a flow), located at its key
      return BeamDynSetup{.definition = beam::pipe_beam_definition(def), .flow = beam::pipe_flow(def)};
    } catch (const InputError& e) {
      const std::string key = "pipe." + e.context().variable;
      throw InputError(e.context(), where(deck, deck.has(key) ? key : "pipe") + ": " + e.message());
    }
  }();
  if (deck.has("sea")) {
    SeaKeys w;
    sea_keys().read_into(deck.section("sea"), w);
    SceneKeys scene;
    scene_keys().read_into(deck, scene);
    // The water rests in the global frame; the beam's frame f is the root frame, so it must not turn.
    if (!scene.root.angular_velocity_rad_s.isZero(0.0))
      throw InputError({"pipe", std::nullopt, "sea", "a root that does not rotate"},
                       where(deck, "root.angular_velocity_rad_s") + ": a pipe in the sea cannot rotate with its root (the water "
                                                                     "is at rest in the global frame)");
    setup.water = beam::SurroundingWater{.density_kg_m3 = w.density_kg_m3, .outer_diameter_m = p.outer_diameter_m,
                                         .added_mass_coefficient = w.inertia_coefficient - 1.0,
                                         .drag_coefficient = w.drag_coefficient,
                                         .surface_z_m = w.surface_z_m - scene.root.position_m.z(),  // in the root frame
                                         .current_m_s = w.current_m_s};
  }
  if (deck.has("tip_motion")) {
    TipMotionKeys m;
    tip_motion_keys().read_into(deck.section("tip_motion"), m);
    if (p.tip_end == "free")
      throw InputError({"pipe", std::nullopt, "tip_motion", "a held tip (pipe.tip_end: clamped or pinned)"},
                       where(deck, "tip_motion") + ": only a held tip can be moved; set pipe.tip_end to clamped or pinned");
    if (p.integrator != "generalized_alpha")
      throw InputError({"pipe", std::nullopt, "pipe.integrator", "generalized_alpha"},
                       where(deck, "pipe.integrator") + ": a prescribed tip motion needs the generalized_alpha integrator");
    if (!(m.sway_direction.norm() > 0.0))
      throw InputError({"pipe", std::nullopt, "tip_motion.sway_direction", "a non-zero vector"},
                       where(deck, "tip_motion.sway_direction") + ": expected a non-zero direction");
    setup.tip_motion = beam::RampAndSway{.stretch_m = m.stretch_m, .stretch_time_s = m.stretch_time_s,
                                         .sway_amplitude_m = m.sway_amplitude_m, .sway_period_s = m.sway_period_s,
                                         .sway_start_s = m.sway_start_s, .axis = Vec3::UnitZ(),  // the straight pipe's axis
                                         .sway_direction = m.sway_direction.normalized()};
  }
  return run_one_beam(deck, std::move(setup), p.segments, p.integrator, p.spectral_radius, "pipe", request, progress);
}

}  // namespace fowtsim::driver
