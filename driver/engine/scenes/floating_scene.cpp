#include "scenes/floating_scene.hpp"

#include <array>
#include <numbers>
#include <optional>
#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "decks/aero_deck.hpp"
#include "decks/controller_deck.hpp"
#include "decks/deck_helpers.hpp"
#include "decks/hydro_deck.hpp"
#include "decks/mooring_deck.hpp"
#include "decks/structure_deck.hpp"
#include "decks/waves_deck.hpp"
#include "decks/wind_deck.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "run/channel_selection.hpp"
#include "scenes/scene_runner.hpp"
#include "scenes/rotor_aero.hpp"
#include "scenes/sea_modules.hpp"
#include "scenes/turbine_blades.hpp"

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

// The controller of the deck, built-in or external, behind one interface; it runs at the large
// step (sample and hold) and its demands are held over the step.
class Controller {
 public:
  explicit Controller(ControllerParams params) : params_(std::move(params)) {
    std::visit([&](const auto& p) { state_ = make_state_of(p); }, params_);
  }
  void advance(const control::ControllerInput& u, double t, double dt) {
    std::visit(
        [&](const auto& p) {
          using P = std::decay_t<decltype(p)>;
          if constexpr (std::is_same_v<P, control::BaselineParams>) {
            control::BaselineController::advance(p, u, t, dt, std::get<control::BaselineState>(state_));
            output_ = control::BaselineController::outputs(p, u, std::get<control::BaselineState>(state_));
          } else {
            control::ExternalController::advance(p, u, t, dt, std::get<control::ExternalController::State>(state_));
            output_ = control::ExternalController::outputs(p, u, std::get<control::ExternalController::State>(state_));
          }
        },
        params_);
  }
  const control::ControllerOutput& output() const { return output_; }
  // A DISCON library's state lives in the library: only the built-in law can be checkpointed.
  template <class Archive>
  void checkpoint(Archive& a) {
    a.io(std::get<control::BaselineState>(state_));
    a.io(output_);
  }
  bool can_checkpoint() const { return std::holds_alternative<control::BaselineState>(state_); }
  // The last call a DISCON library gets (status −1: it closes its files); nothing for the built-in law.
  void finish(double t) {
    if (auto* p = std::get_if<control::ExternalController::Params>(&params_))
      control::ExternalController::finish(*p, t, std::get<control::ExternalController::State>(state_));
  }

 private:
  static control::BaselineState make_state_of(const control::BaselineParams& p) { return control::BaselineController::make_state(p); }
  static control::ExternalController::State make_state_of(const control::ExternalController::Params& p) {
    return control::ExternalController::make_state(p);
  }
  ControllerParams params_;
  std::variant<control::BaselineState, control::ExternalController::State> state_;
  control::ControllerOutput output_{};
};

// The loads on the structure at any Runge–Kutta stage: the sea (hydro with its added mass, and
// mooring) at the stage pose, the rotor aerodynamics at the stage configuration (when the deck has
// `aero`), and the generator torque and blade pitch held over the large step.
class StageLoads final : public multibody::LoadProvider {
 public:
  StageLoads(const multibody::Model& model, SeaModules& sea, RotorAero* rotor, const TurbineBlades* blades)
      : model_(model), sea_(sea), rotor_(rotor), blades_(blades) {}
  void hold(double generator_torque_N_m, double pitch_rad) {
    generator_torque_ = generator_torque_N_m;
    pitch_ = pitch_rad;
  }
  double pitch_rad() const { return pitch_; }
  double generator_torque_held_N_m() const { return generator_torque_; }
  void loads(double t, const multibody::State& s, multibody::AppliedLoads& out) override {
    sea_.evaluate(t, platform_motion(s));
    const Vec6 load = sea_.platform_load();
    out.platform_force_N += load.head<3>();
    out.platform_moment_N_m += load.tail<3>();
    out.platform_added_mass = sea_.added_mass();
    out.generator_torque_N_m = generator_torque_;
    if (blades_) {  // flexible blades: their held root loads, aerodynamics included
      multibody::chain_kinematics(model_, s, chain_);
      blades_->add_stage_loads(chain_, out);
    } else if (rotor_) {
      multibody::chain_kinematics(model_, s, chain_);
      rotor_->evaluate(t, chain_, s.rotor_speed_rad_s, pitch_);
      out.rotor_force_N = rotor_->force_N();
      out.rotor_moment_N_m = rotor_->moment_N_m();
    }
  }
  multibody::SpinMotion rotor_spin(double t) override { return blades_ ? blades_->spin(t) : multibody::SpinMotion{}; }
  double generator_torque_N_m() const { return generator_torque_; }

 private:
  const multibody::Model& model_;
  SeaModules& sea_;
  RotorAero* rotor_;
  const TurbineBlades* blades_;
  multibody::ChainKinematics chain_;
  double generator_torque_ = 0.0, pitch_ = 0.0;
};

}  // namespace

Schema floating_scene_schema() {
  return Schema::map({
      {"simulation", simulation_schema("large (coupling) step").doc("time span and step")},
      {"output", output_schema().optional().doc("what to write")},
      {"structure", structure_schema().doc("rigid multibody: platform, tower, nacelle, rotor, drivetrain")},
      {"waves", waves_schema().optional().doc("incident sea; absent = still water")},
      {"hydro", hydro_schema().optional().doc("Morison strips, hydrostatics, linear extras, WAMIT potential flow; absent = none")},
      {"mooring", mooring_schema().optional().doc("mooring lines; absent = none")},
      {"aero", aero_schema().optional().doc("rotor aerodynamics (with `airfoils` and `wind`); absent = none")},
      {"airfoils", airfoils_schema().optional().doc("airfoil polars the aero blade rows name")},
      {"wind", wind_schema().optional().doc("inflow (needed with `aero`)")},
      {"controller", controller_schema().optional().doc("generator torque and blade pitch; absent = parked, no torque")},
      {"blades", blades_schema().optional().doc("flexible MBBT blades (and the coupling); absent = rigid blades")},
  });
}

RunReport run_floating_scene(const RunRequest& request, const ProgressCallback& progress) {
  const io::ValidatedDeck deck = io::read_deck(floating_scene_schema(), request.deck_path);
  multibody::Params structure = structure_params(deck.section("structure"));
  if (deck.has("blades")) TurbineBlades::configure(structure);
  const multibody::Model model = located(deck.section("structure"), [&] { return multibody::make_model(structure); });
  if (deck.has("aero") && (!deck.has("airfoils") || !deck.has("wind")))
    throw InputError({"floating", std::nullopt, "aero", "airfoils and wind sections"},
                     where(deck, "aero") + ": rotor aerodynamics need the `airfoils` and `wind` sections too");
  if (structure.rotor.flexible_blades && !deck.has("blades"))
    throw InputError({"floating", std::nullopt, "structure.rotor.flexible_blades", "a blades section"},
                     where(deck, "structure.rotor.flexible_blades") + ": flexible blades need the `blades` section (their structure)");
  multibody::State state = multibody::Multibody::make_state(model);
  SeaModules sea(deck, platform_motion(state), deck.number("simulation.dt_s"));
  std::optional<RotorAero> rotor;
  if (deck.has("aero")) {
    rotor.emplace(deck, structure);
    // One rotor, two descriptions: the aero blade table and the structure must agree on it.
    const aero::Params& ap = rotor->params();
    if (ap.number_of_blades != structure.rotor.blade_count)
      throw InputError({"floating", std::nullopt, "aero.number_of_blades", "structure.rotor.blade_count"},
                       where(deck, "aero.number_of_blades") + fmt::format(": {} blades, the structure has {}", ap.number_of_blades,
                                                                          structure.rotor.blade_count));
    const double tip = structure.rotor.hub_radius_m + ap.blade.back().span_m;
    if (std::abs(tip / structure.rotor.tip_radius_m - 1.0) > 1e-3)
      throw InputError({"floating", std::nullopt, "aero.blade.nodes", "the structure's tip radius"},
                       where(deck, "aero.blade.nodes") + fmt::format(": hub radius + last span = {:.4g} m, the structure's tip radius is {:.4g} m",
                                                                     tip, structure.rotor.tip_radius_m));
  }
  std::optional<Controller> controller;
  double overspeed_rad_s = 0.0;  // 30 % above the built-in law's rated rotor speed (0: unknown)
  if (deck.has("controller")) {
    ControllerParams cp = controller_params(deck.section("controller"));
    if (const auto* b = std::get_if<control::BaselineParams>(&cp))
      overspeed_rad_s = 1.3 * b->rated_generator_speed_rad_s / structure.drivetrain.gearbox_ratio;
    controller.emplace(std::move(cp));
  }
  std::optional<TurbineBlades> blades;
  if (deck.has("blades")) blades.emplace(deck, model, rotor ? &*rotor : nullptr);
  StageLoads stage_loads(model, sea, rotor ? &*rotor : nullptr, blades ? &*blades : nullptr);
  const double initial_pitch = deck.has("structure.initial_conditions")
                                   ? deck.number("structure.initial_conditions.blade_pitch_deg") * std::numbers::pi / 180.0
                                   : 0.0;
  stage_loads.hold(0.0, initial_pitch);
  // The shaft motion (non-rotating) of a multibody state at time t, under the stage loads.
  multibody::Evaluation evaluation;
  auto shaft_at = [&](double t, const multibody::State& s) {
    multibody::AppliedLoads loads;
    stage_loads.loads(t, s, loads);
    multibody::evaluate(model, s, loads, t, evaluation);
    return shaft_motion(evaluation.kinematics, evaluation.acceleration);
  };
  auto demands = [&] {
    RotorDemands d;
    d.generator_torque_N_m = stage_loads.generator_torque_N_m();
    d.pitch_command_rad = stage_loads.pitch_rad();
    return d;
  };
  if (blades) blades->start(shaft_at(0.0, state), state, initial_pitch, demands());

  std::vector<ChannelInfo> all = multibody::Multibody::channels(model);
  const std::size_t sea_first = all.size();
  for (const ChannelInfo& c : sea.channels()) all.push_back(c);
  const std::size_t rotor_first = all.size();
  if (rotor)
    for (const ChannelInfo& c : rotor->channels()) all.push_back(c);
  const std::size_t blades_first = all.size();
  if (blades)
    for (const ChannelInfo& c : blades->channels()) all.push_back(c);
  const std::size_t controller_first = all.size();
  if (controller)  // GenTq, GenPwr, BldPitch1–3; GenSpeed comes from the multibody
    for (const ChannelInfo& c : control::controller_channels("control"))
      if (c.name != "GenSpeed") all.push_back(c);
  const std::vector<std::size_t> picked = select_channels(deck, all, "floating");

  std::vector<std::string> input_warnings = sea.warnings();
  if (rotor && rotor->params().number_of_blades > 0) {
    const wind::WindParams& w = rotor->wind().params();
    // NREL 5MW cut-out 25 m/s (the controller has no shutdown): a spinning rotor above it.
    if (w.speed_m_s > 25.0 && structure.initial_conditions.rotor_speed_rpm != 0.0)
      input_warnings.push_back(fmt::format("wind {:.3g} m/s beyond the 25 m/s cut-out with the rotor spinning (the controller "
                                           "does not shut the turbine down)", w.speed_m_s));
  }
  double max_rotor_speed = std::abs(state.rotor_speed_rad_s);
  FixedStepScene scene;
  for (std::size_t i : picked) scene.written.push_back(all[i]);
  scene.metadata.seeds = sea.seeds();
  if (rotor && rotor->wind().params().model == wind::WindModel::turbulent)
    scene.metadata.seeds.push_back(rotor->wind().params().turbulence.seed);
  scene.metadata.extra = {{"scene", "floating"}};
  std::vector<double> values(all.size());
  const double gearbox = structure.drivetrain.gearbox_ratio;
  scene.step = [&](double t, double dt) {
    if (controller) {
      control::ControllerInput u;
      u.generator_speed_rad_s = gearbox * state.generator_speed_rad_s;
      u.rotor_speed_rad_s = state.rotor_speed_rad_s;
      u.blade_pitch_rad.fill(stage_loads.pitch_rad());
      if (rotor) u.hub_wind_speed_m_s = rotor->probe_wind(t).x();
      controller->advance(u, t, dt);
      stage_loads.hold(controller->output().generator_torque_N_m, controller->output().blade_pitch_rad[0]);
    }
    if (!blades) {
      multibody::Multibody::advance(model, stage_loads, t, dt, state);
      if (rotor) rotor->advance_states(model, state, t + dt, stage_loads.pitch_rad());  // UA/DBEMT, if on
    } else {
      blades->advance(stage_loads, shaft_at, demands(), t, dt, state);
    }
    sea.advance(t + dt, platform_motion(state));
    max_rotor_speed = std::max(max_rotor_speed, std::abs(state.rotor_speed_rad_s));
  };
  SeaModules::Memory sea_memory;
  std::vector<aero::NodeResult> aero_memory;
  scene.row = [&](double t, std::span<double> row) {
    // The row's own evaluation must leave the solvers' warm starts as the step left them.
    sea_memory = sea.memory();
    if (rotor) rotor->save_memory(aero_memory);
    multibody::AppliedLoads loads;
    stage_loads.loads(t, state, loads);
    const multibody::Output mo = multibody::Multibody::outputs(model, loads, state, t);
    std::copy(mo.channels.begin(), mo.channels.end(), values.begin());
    const std::span<double> v(values);
    sea.channel_values(t, v.subspan(sea_first));
    if (rotor) rotor->channel_values(t, v.subspan(rotor_first));
    if (blades) blades->channel_values(v.subspan(blades_first));
    if (controller) {
      std::array<double, 6> c{};
      control::controller_channel_values(controller->output(), c);
      std::copy(c.begin(), c.begin() + 5, v.begin() + static_cast<long>(controller_first));
    }
    for (std::size_t k = 0; k < picked.size(); ++k) row[k] = values[picked[k]];
    sea.restore(sea_memory);
    if (rotor) rotor->restore_memory(aero_memory);
  };
  // Checkpoints: the scene's whole changing state (the wind field and the sea are rebuilt from the
  // deck, identically).
  if (!controller || controller->can_checkpoint()) {
    // One list of fields for saving and loading (run/checkpoint.hpp); setters run on save too,
    // with the values they already hold.
    const auto transfer = [&](auto& a) {
      a.io(state.position_m);
      a.io(state.orientation);
      a.io(state.velocity_m_s);
      a.io(state.angular_velocity_rad_s);
      for (double* x : {&state.rotor_azimuth_rad, &state.rotor_speed_rad_s, &state.generator_azimuth_rad,
                        &state.generator_speed_rad_s, &state.rotor_acceleration_rad_s2, &state.generator_acceleration_rad_s2,
                        &state.nacelle_yaw_rad, &state.nacelle_yaw_rate_rad_s, &state.nacelle_yaw_acceleration_rad_s2})
        a.io(*x);
      double torque = stage_loads.generator_torque_held_N_m(), pitch = stage_loads.pitch_rad();
      a.io(torque);
      a.io(pitch);
      stage_loads.hold(torque, pitch);
      if (controller) controller->checkpoint(a);
      sea.checkpoint(a);
      if (rotor) rotor->checkpoint(a);
      if (blades) blades->checkpoint(a);
    };
    scene.save = [transfer](CheckpointWriter& w) { transfer(w); };
    scene.load = [transfer](CheckpointReader& r) { transfer(r); };
  }
  scene.warnings = [&](std::vector<std::string>& warnings) {
    for (const std::string& w : input_warnings) warnings.push_back(w);
    if (overspeed_rad_s > 0.0 && max_rotor_speed > overspeed_rad_s)
      warnings.push_back(fmt::format("rotor overspeed: {:.3g} rpm, more than 30 % above the controller's rated {:.3g} rpm",
                                     max_rotor_speed * 30.0 / std::numbers::pi, overspeed_rad_s / 1.3 * 30.0 / std::numbers::pi));
    if (rotor && rotor->wind().outside_queries() > 0)
      warnings.push_back(fmt::format("{} wind queries fell outside the turbulence grid (deflected tips or a displaced "
                                     "rotor beyond its edge) and took the mean wind profile there",
                                     rotor->wind().outside_queries()));
  };
  RunReport report = [&] {
    try {
      return run_fixed_steps(request, deck, std::move(scene), progress);
    } catch (...) {
      if (controller) controller->finish(0.0);
      throw;
    }
  }();
  if (controller) controller->finish(report.simulated_s);
  if (blades) report.substeps = blades->substeps();
  // What this scene coupled, from what the deck holds.
  std::vector<std::string> parts{"rigid multibody"};
  if (deck.has("hydro") || deck.has("mooring"))
    parts.push_back(std::string(deck.has("hydro") ? "hydro" : "") + (deck.has("hydro") && deck.has("mooring") ? " + " : "") +
                    (deck.has("mooring") ? "mooring" : "") + (deck.has("waves") ? " in waves" : " in still water") +
                    " at every RK4 stage");
  if (blades) parts.push_back(blades->description() + (rotor ? ", BEM on the deflected blades" : ", no aerodynamics"));
  else if (rotor) parts.push_back("rigid blades with BEM at every RK4 stage");
  else parts.push_back("rigid blades, no aerodynamics");
  parts.push_back(controller ? "controller at the large step" : "no controller (generator torque 0, pitch held)");
  report.coupling.clear();
  for (const std::string& p : parts) report.coupling += (report.coupling.empty() ? "" : "; ") + p;
  return report;
}

}  // namespace fowtsim::driver
