#include "scenes/floating_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

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
#include "fowtsim/multibody/coordinates.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "run/channel_selection.hpp"
#include "scenes/record_length_warnings.hpp"
#include "scenes/scene_runner.hpp"

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

}  // namespace

// The loads on the structure at any Runge–Kutta stage: the sea (hydro with its added mass, and
// mooring) at the stage pose, the rotor aerodynamics at the stage configuration (when the deck has
// `aero`), and the generator torque and blade pitch held over the large step. It acts on the parts
// of one state that act_on() names (a step's state, or a row's copies).
class FloatingScene::StageLoads final : public multibody::LoadProvider {
 public:
  StageLoads(const multibody::Model& model, const SeaModules& sea, const RotorAero* rotor, const TurbineBlades* blades,
             const TurbineRiser* riser, const control::BrakeParams* brake)
      : model_(model), sea_(sea), rotor_(rotor), blades_(blades), riser_(riser), brake_(brake) {
    if (rotor_) tower_ = rotor_->make_tower_workspace();
  }
  void act_on(const HeldDemands& held, SeaModules::Data& sea, RotorAero::Data* aero, const TurbineBlades::Data* blades,
              const InputOffsets& offsets = {}) {
    offsets_ = offsets;
    held_ = &held;
    sea_data_ = &sea;
    aero_data_ = aero;
    blades_data_ = blades;
    riser_data_ = nullptr;
  }
  // The riser's held top load on the platform (after act_on, which drops it: a linearisation's
  // evaluations leave the riser out, and say so).
  void with_riser(const TurbineRiser::Data* riser) { riser_data_ = riser; }
  void loads(double t, const multibody::State& s, multibody::AppliedLoads& out) override {
    sea_.evaluate(t, platform_motion(s), *sea_data_);
    const Vec6 load = sea_.platform_load(*sea_data_);
    out.platform_force_N += load.head<3>();
    out.platform_moment_N_m += load.tail<3>();
    if (!offsets_.platform_load.isZero(0.0)) {  // a linearisation's input (a run's sums stay as they were)
      out.platform_force_N += offsets_.platform_load.head<3>();
      out.platform_moment_N_m += offsets_.platform_load.tail<3>();
    }
    out.platform_added_mass = sea_.added_mass(*sea_data_);
    out.generator_torque_N_m = held_->generator_torque_N_m;
    if (brake_) {  // the HSS brake at this instant of its ramp: holding the shaft, or slipping against it
      out.drivetrain_locked = held_->drivetrain_locked;
      if (!held_->drivetrain_locked)
        out.generator_torque_N_m += held_->brake_direction * control::brake_torque_N_m(*brake_, held_->brake_engaged_at_s, t);
    }
    if (blades_ || rotor_) multibody::chain_kinematics(model_, s, chain_);
    if (blades_) {  // flexible blades: their held root loads, aerodynamics included
      blades_->add_stage_loads(chain_, *blades_data_, out);
    } else if (rotor_) {
      // aero.induction: step — solved at the large step's start, held over its later stages.
      const bool held = rotor_->params().induction_held_over_step && step_start_ && t != *step_start_;
      const aero::Induction induction = held ? aero::Induction::held : aero::Induction::solve;
      if (model_.rr_blades.mode_count > 0) {  // Rayleigh–Ritz blades: loads at their stations
        rotor_->evaluate_rayleigh_ritz(t, model_, s, chain_, *aero_data_, &out, induction);
      } else {
        // A uniform wind offset δU is, to the rigid rotor's blade elements, the apex moving at −δU
        // along the mean inflow (node velocities are the apex's plus Ω × r).
        const Vec3 apex_velocity = chain_.apex.velocity_m_s;
        if (offsets_.wind_speed_m_s != 0.0) chain_.apex.velocity_m_s -= offsets_.wind_speed_m_s * inflow_direction();
        rotor_->evaluate(t, chain_, s.rotor_speed_rad_s, held_->pitch_rad, *aero_data_, induction);
        chain_.apex.velocity_m_s = apex_velocity;
        out.rotor_force_N = aero_data_->force_N;
        out.rotor_moment_N_m = aero_data_->moment_N_m;
      }
    }
    if (rotor_ && rotor_->tower_drag_on()) rotor_->tower_drag(t, model_, s, chain_, tower_, out);
    if (riser_data_) riser_->add_stage_loads(s, *riser_data_, out);
  }
  // The horizontal direction of the mean inflow at the hub probe (a linearisation's wind offset).
  Vec3 inflow_direction() const {
    Vec3 d = rotor_->probe_wind(0.0);
    d.z() = 0.0;
    return d.norm() > 0.0 ? Vec3(d.normalized()) : Vec3::UnitX();
  }
  // The large step the next stages belong to (its start time), and its end: outside a step (rows,
  // linearisation) every evaluation solves its inductions.
  void begin_step(double t) { step_start_ = t; }
  void end_step() { step_start_.reset(); }
  multibody::SpinMotion rotor_spin(double t) override {
    return blades_ ? blades_->spin(t, *blades_data_) : multibody::SpinMotion{};
  }

 private:
  const multibody::Model& model_;
  const SeaModules& sea_;
  const RotorAero* rotor_;
  const TurbineBlades* blades_;
  const TurbineRiser* riser_;          // null without a `riser` section
  const control::BrakeParams* brake_;  // null without a controller
  const HeldDemands* held_ = nullptr;
  SeaModules::Data* sea_data_ = nullptr;
  RotorAero::Data* aero_data_ = nullptr;
  const TurbineBlades::Data* blades_data_ = nullptr;
  const TurbineRiser::Data* riser_data_ = nullptr;
  InputOffsets offsets_;              // zero but within a linearisation's evaluations
  std::optional<double> step_start_;  // set while a large step's stages run (begin_step)
  multibody::ChainKinematics chain_;  // workspace
  RotorAero::TowerWorkspace tower_;    // workspace
};

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
      {"riser", riser_schema().optional().doc("a riser or power cable (MBBT pipe) hung from the platform; absent = none")},
  });
}

FloatingScene::FloatingScene(const io::ValidatedDeck& deck, SetUp setup, std::optional<double> run_until_s,
                             const std::optional<std::filesystem::path>& turbulence_cache)
    : structure_(structure_params(deck.section("structure"))) {
  if (deck.has("blades")) TurbineBlades::configure(structure_);
  std::optional<aero::Params> aero;
  if (deck.has("aero")) aero = aero_params(deck);
  // Rayleigh–Ritz blades carry the aerodynamic loads at the aero nodes' spans (stations of the model).
  if (structure_.rotor.rayleigh_ritz_blade && aero)
    for (const aero::BladeNodeParams& node : aero->blade) structure_.rotor.blade_station_spans_m.push_back(node.span_m);
  model_ = located(deck.section("structure"), [&] { return multibody::make_model(structure_); });
  if (deck.has("aero") && (!deck.has("airfoils") || !deck.has("wind")))
    throw InputError({"floating", std::nullopt, "aero", "airfoils and wind sections"},
                     where(deck, "aero") + ": rotor aerodynamics need the `airfoils` and `wind` sections too");
  if (structure_.rotor.flexible_blades && !deck.has("blades"))
    throw InputError({"floating", std::nullopt, "structure.rotor.flexible_blades", "a blades section"},
                     where(deck, "structure.rotor.flexible_blades") + ": flexible blades need the `blades` section (their structure)");
  const multibody::State initial = multibody::Multibody::make_state(model_);
  dt_s_ = simulation_keys(deck).dt_s;
  sea_.emplace(deck, platform_motion(initial), dt_s_);
  if (deck.has("aero")) {
    rotor_.emplace(std::move(*aero), wind_params(deck.section("wind")), structure_,
                   setup == SetUp::check ? RotorAero::WindSetUp::check : RotorAero::WindSetUp::run, run_until_s,
                   turbulence_cache);
    // One rotor, two descriptions: the aero blade table and the structure must agree on it.
    const aero::Params& ap = rotor_->params();
    if (ap.number_of_blades != structure_.rotor.blade_count)
      throw InputError({"floating", std::nullopt, "aero.number_of_blades", "structure.rotor.blade_count"},
                       where(deck, "aero.number_of_blades") + fmt::format(": {} blades, the structure has {}", ap.number_of_blades,
                                                                          structure_.rotor.blade_count));
    // The tower drag's nodal loads go to the multibody in a fixed-capacity array (no allocation per stage).
    if (ap.tower_drag && ap.tower.size() > static_cast<std::size_t>(multibody::kMaxTowerLoads))
      throw InputError({"floating", std::nullopt, "aero.tower.nodes", "at most " + std::to_string(multibody::kMaxTowerLoads)},
                       where(deck, "aero.tower.nodes") +
                           fmt::format(": {} tower stations with aero.tower_drag; expected at most {} (multibody::kMaxTowerLoads, "
                                       "the tower point loads the structure takes)",
                                       ap.tower.size(), multibody::kMaxTowerLoads));
    const double tip = structure_.rotor.hub_radius_m + ap.blade.back().span_m;
    if (std::abs(tip / structure_.rotor.tip_radius_m - 1.0) > 1e-3)
      throw InputError({"floating", std::nullopt, "aero.blade.nodes", "the structure's tip radius"},
                       where(deck, "aero.blade.nodes") + fmt::format(": hub radius + last span = {:.4g} m, the structure's tip radius is {:.4g} m",
                                                                     tip, structure_.rotor.tip_radius_m));
  }
  if (deck.has("controller")) {
    ControllerSetup cs = controller_setup(deck.section("controller"));
    if (const auto* b = std::get_if<control::BaselineParams>(&cs.law))
      overspeed_rad_s_ = 1.3 * control::rated_speed_of_law_rad_s(*b) / structure_.drivetrain.gearbox_ratio;
    controller_.emplace(std::move(cs));
  }
  if (deck.has("blades")) blades_.emplace(deck, model_, rotor_ ? &*rotor_ : nullptr);
  // The blades' interface mass is matched to one RK4 step of the multibody per large step (h = 0.586 ΔT,
  // the held remainder sampled at the step's end): RK4 substeps inside the large step break that match
  // (measured on the default deck: ΔT 40 ms in 20-ms substeps diverged at 488 s; in one step every ΔT
  // from 25 to 100 ms runs the 600 s, `fowtsim bench stability`).
  if (blades_ && blades_->interface_mass() && structure_.max_step_s < dt_s_ * (1.0 - 1e-9))
    throw InputError({"floating", std::nullopt, "structure.max_step_s", fmt::format("≥ simulation.dt_s = {:.6g} s", dt_s_)},
                     where(deck, "structure.max_step_s") +
                         fmt::format(": {:.6g} s splits each large step of {:.6g} s; with MBBT blades on the flexible tower "
                                     "(blades.interface_mass) the multibody takes one RK4 step per large step",
                                     structure_.max_step_s, dt_s_));
  // A held rotor speed hands the blades' whole root torque about the shaft (their edgewise vibration
  // included) to the light tower top explicitly, where the free spin absorbs it inside the blades'
  // step: measured, the seed's validation deck on the flexible tower diverged at 16 s (20 ms), 20 s
  // (10 ms) and 15 s (predictor–corrector), the default deck with the speed held at 8 s, the tower's
  // second side-side mode (4.7 Hz) and the edgewise 1 Hz growing.
  if (blades_ && blades_->interface_mass() && structure_.dofs.rotor == multibody::RotorSpin::held)
    throw InputError({"floating", std::nullopt, "structure.degrees_of_freedom.rotor_speed", "free with MBBT blades on the flexible tower"},
                     where(deck, "structure.degrees_of_freedom.rotor_speed") +
                         ": a held rotor speed with MBBT blades on the flexible tower is not supported (the blades' torque about "
                         "the shaft then reaches the tower top explicitly and the exchange diverges); hold it on the rigid tower "
                         "(structure.tower.flexible: false) or with Rayleigh-Ritz or rigid blades");
  if (deck.has("riser")) riser_.emplace(deck, model_, *sea_);
  stage_loads_ = std::make_unique<StageLoads>(model_, *sea_, rotor_ ? &*rotor_ : nullptr, blades_ ? &*blades_ : nullptr,
                                              riser_ ? &*riser_ : nullptr,
                                              controller_ ? &controller_->events().brake : nullptr);
  initial_pitch_rad_ = structure_.initial_conditions.blade_pitch_deg * std::numbers::pi / 180.0;
  // An idling or parked rotor starts with its blades at feather.
  if (controller_ && controller_->events().mode != control::OperatingMode::operating)
    initial_pitch_rad_ = controller_->events().feather_pitch_rad;

  // Channels in module order; the controller's GenSpeed comes from the multibody.
  auto add_block = [&](Block& block, const std::vector<ChannelInfo>& channels) {
    block.first = all_.size();
    block.count = channels.size();
    all_.insert(all_.end(), channels.begin(), channels.end());
  };
  add_block(body_block_, multibody::Multibody::channels(model_));
  add_block(sea_block_, sea_->channels());
  if (rotor_) add_block(rotor_block_, rotor_->channels());
  if (blades_) add_block(blades_block_, blades_->channels());
  if (riser_) add_block(riser_block_, riser_->channels());
  if (!blades_ && (rotor_ || controller_)) {  // rigid blades turn to the held pitch at once (flexible ones: their actuator's)
    std::vector<ChannelInfo> pitch;
    for (int b = 1; b <= model_.blade_count; ++b)
      pitch.push_back({fmt::format("BldPitch{}", b), "deg",
                       fmt::format("blade {} pitch angle (ElastoDyn's BldPitch): the demand held over the step", b), "structure"});
    add_block(pitch_block_, pitch);
  }
  if (controller_) {
    const std::vector<ChannelInfo> c = control::controller_channels("control");
    std::vector<ChannelInfo> kept;
    for (std::size_t k = 0; k < c.size(); ++k) {
      if (c[k].name == "GenSpeed") continue;
      kept.push_back(c[k]);
      controller_source_.push_back(k);
    }
    add_block(controller_block_, kept);
    add_block(brake_block_, {{"HSSBrTq", "kN-m",
                              "high-speed-shaft brake torque (ServoDyn's HSSBrTq): the brake's ramp, its capacity while it holds the shaft",
                              "control"}});
  }
  picked_ = select_channels(deck, all_, "floating");
  for (std::size_t i : picked_) {
    written_.push_back(all_[i]);
    for (Block* b : {&body_block_, &sea_block_, &rotor_block_, &blades_block_, &riser_block_, &pitch_block_, &controller_block_, &brake_block_})
      if (i >= b->first && i < b->first + b->count) b->written = true;
  }
  values_.assign(all_.size(), 0.0);

  input_warnings_ = sea_->warnings();
  if (rotor_ && rotor_->params().number_of_blades > 0) {
    const wind::WindParams& w = rotor_->wind_params();
    // NREL 5MW cut-out 25 m/s: a rotor spinning above it in operation (idling or parked is the
    // deck saying it knows).
    const bool operating = !controller_ || controller_->events().mode == control::OperatingMode::operating;
    if (w.speed_m_s > 25.0 && structure_.initial_conditions.rotor_speed_rpm != 0.0 && operating)
      input_warnings_.push_back(fmt::format("wind {:.3g} m/s beyond the 25 m/s cut-out with the rotor spinning (the controller "
                                            "does not shut the turbine down)", w.speed_m_s));
    // Feathered blades stand in deep stall, where the static polar's falling lift gives negative
    // aerodynamic damping: flexible blades then vibrate edgewise without bound (an idling OC3 rotor
    // at 50 m/s, 30° yaw: tip edge std 5.8 m quasi-steady, 0.10 m with HGM). AeroDyn runs such cases
    // with its unsteady airfoil model for this reason.
    const bool flexible = blades_ || model_.rr_blades.mode_count > 0;
    if (!operating && flexible && rotor_->params().unsteady_airfoil == aero::UnsteadyAirfoilModel::none)
      input_warnings_.push_back("an idling or parked rotor with flexible blades on the static polars (aero.unsteady_airfoil: none): "
                                "in deep stall they can vibrate edgewise without bound; set aero.unsteady_airfoil: hgm");
  }
  if (deck.has("hydro") || deck.has("mooring"))
    sea_description_ = std::string(deck.has("hydro") ? "hydro" : "") + (deck.has("hydro") && deck.has("mooring") ? " + " : "") +
                       (deck.has("mooring") ? "mooring" : "") + (deck.has("waves") ? " in waves" : " in still water") +
                       " at every RK4 stage";
}

FloatingScene::~FloatingScene() = default;

// The shaft motion (non-rotating) of a multibody state at time t, under the stage loads of the
// state stage_loads_ acts on.
ShaftMotion FloatingScene::shaft_at(double t, const multibody::State& body) {
  multibody::AppliedLoads loads;
  stage_loads_->loads(t, body, loads);
  multibody::evaluate(model_, body, loads, t, evaluation_);
  return shaft_motion(evaluation_.kinematics, evaluation_.acceleration);
}

void FloatingScene::evaluate_on_copy(double t, const FloatingState& s, const multibody::State& body, FloatingState& work,
                                     const InputOffsets& offsets) {
  work.sea = s.sea;
  if (work.aero) *work.aero = *s.aero;
  stage_loads_->act_on(work.held, work.sea, work.aero ? &*work.aero : nullptr, nullptr, offsets);
  multibody::AppliedLoads loads;
  stage_loads_->loads(t, body, loads);
  multibody::evaluate(model_, body, loads, t, evaluation_);
  stage_loads_->act_on(work.held, work.sea, work.aero ? &*work.aero : nullptr, nullptr);  // offsets back to zero
}

Eigen::VectorXd FloatingScene::accelerations(double t, const FloatingState& s, const InputOffsets& offsets) {
  if (blades_ || (offsets.wind_speed_m_s != 0.0 && model_.rr_blades.mode_count > 0))
    throw InputError({"screen", std::nullopt, "blades", "rigid blades"},
                     "the flexible and Rayleigh-Ritz blades are not linearised in their inputs yet: rigid blades only");
  if (riser_)
    throw InputError({"screen", std::nullopt, "riser", "a deck without the `riser` section"},
                     "the riser's states are not linearised yet: drop the `riser` section");
  FloatingState work = s;
  evaluate_on_copy(t, s, s.body, work, offsets);
  const std::vector<int> dofs = coordinates();
  Eigen::VectorXd a(static_cast<Eigen::Index>(dofs.size()));
  for (std::size_t i = 0; i < dofs.size(); ++i) a[static_cast<Eigen::Index>(i)] = evaluation_.acceleration[dofs[i]];
  return a;
}

// The MBBT blades' states are not in the linearisation (nor in the static settling before it).
void FloatingScene::refuse_flexible_blades_in_modes() const {
  if (blades_)
    throw InputError({"modes", std::nullopt, "blades", "rigid blades (drop the `blades` section)"},
                     "the flexible blades' states are not linearised yet: modes of the rigid-blade structure only");
}

Eigen::MatrixXd FloatingScene::linearised_system(double t, const FloatingState& s) {
  refuse_flexible_blades_in_modes();
  if (riser_)
    throw InputError({"modes", std::nullopt, "riser", "a deck without the `riser` section"},
                     "the riser's states are not linearised yet: drop the `riser` section");
  const std::vector<int> dofs = coordinates();
  const int n = static_cast<int>(dofs.size());
  FloatingState work = s;  // the loads' warm starts and memories change on a copy only
  auto accelerations = [&](const multibody::State& body) {
    evaluate_on_copy(t, s, body, work);
    Eigen::VectorXd a(n);
    for (int i = 0; i < n; ++i) a[i] = evaluation_.acceleration[dofs[static_cast<std::size_t>(i)]];
    return a;
  };
  // Coordinate k displaced, or its rate changed, by h (multibody/coordinates.hpp).
  const bool rigid_shaft = model_.generator_dof == multibody::kRotor;
  auto displaced = [&](int k, double h) {
    multibody::State b = s.body;
    multibody::displace_coordinate(b, k, h);
    return b;
  };
  auto sped_up = [&](int k, double h) {
    multibody::State b = s.body;
    multibody::change_coordinate_rate(b, k, h, rigid_shaft);
    return b;
  };
  // Steps of 1e-4 m (rad) and 1e-4 m/s (rad/s): central differences are then accurate to ~1e-8 of
  // the stiffness (curvatures over metres) and far above the solvers' tolerances (mooring 1e-10).
  constexpr double h = 1e-4;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  a.topRightCorner(n, n).setIdentity();
  for (int i = 0; i < n; ++i) {
    const int k = dofs[static_cast<std::size_t>(i)];
    a.block(n, i, n, 1) = (accelerations(displaced(k, h)) - accelerations(displaced(k, -h))) / (2.0 * h);
    a.block(n, n + i, n, 1) = (accelerations(sped_up(k, h)) - accelerations(sped_up(k, -h))) / (2.0 * h);
  }
  return a;
}

void FloatingScene::settle_elastic(double t, FloatingState& s, Settle how) {
  const int first_elastic = how == Settle::blades_in_motion ? multibody::kBlade : multibody::kTower;
  if (how == Settle::tower_and_blades_at_rest) refuse_flexible_blades_in_modes();  // (the flexible tower with MBBT blades reaches here)
  std::vector<int> elastic;
  for (const int k : coordinates())
    if (k >= first_elastic) elastic.push_back(k);
  if (elastic.empty()) return;
  const auto n = static_cast<Eigen::Index>(elastic.size());
  auto coordinate = [&](multibody::State& b, int k) -> double& {
    if (k < multibody::kBlade) return b.tower_deflection_m[k - multibody::kTower];
    return b.blade_deflection_m[(k - multibody::kBlade) / multibody::kMaxBladeModes][(k - multibody::kBlade) % multibody::kMaxBladeModes];
  };
  FloatingState work = s;
  auto forces = [&](const multibody::State& body) {
    evaluate_on_copy(t, s, body, work);
    Eigen::VectorXd f(n);
    for (Eigen::Index i = 0; i < n; ++i) f[i] = evaluation_.force[elastic[static_cast<std::size_t>(i)]];
    return f;
  };
  multibody::State body = s.body;
  if (how == Settle::tower_and_blades_at_rest) {
    body.velocity_m_s.setZero();
    body.angular_velocity_rad_s.setZero();
    body.rotor_speed_rad_s = body.generator_speed_rad_s = 0.0;
  }
  for (const int k : elastic) {
    coordinate(body, k) = 0.0;
    if (k < multibody::kBlade) body.tower_deflection_rate_m_s[k - multibody::kTower] = 0.0;
    else body.blade_deflection_rate_m_s[(k - multibody::kBlade) / multibody::kMaxBladeModes][(k - multibody::kBlade) % multibody::kMaxBladeModes] = 0.0;
  }
  // The elastic forces are linear in q but for the inertia's q² terms and the loads' dependence on
  // the deflection: a few Newton steps; converged when the step is below 1e-9 m.
  constexpr double h = 1e-4;  // [m], as the linearisation
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Eigen::VectorXd f = forces(body);
    Eigen::MatrixXd jacobian(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
      multibody::State plus = body, minus = body;
      coordinate(plus, elastic[static_cast<std::size_t>(j)]) += h;
      coordinate(minus, elastic[static_cast<std::size_t>(j)]) -= h;
      jacobian.col(j) = (forces(plus) - forces(minus)) / (2.0 * h);
    }
    const Eigen::VectorXd step = jacobian.partialPivLu().solve(-f);
    for (Eigen::Index j = 0; j < n; ++j) coordinate(body, elastic[static_cast<std::size_t>(j)]) += step[j];
    if (step.cwiseAbs().maxCoeff() < 1e-9) {
      for (const int k : elastic) coordinate(s.body, k) = coordinate(body, k);
      return;
    }
  }
  throw NumericalError({how == Settle::blades_in_motion ? "floating" : "modes", t,
                        how == Settle::blades_in_motion ? "static deflection of the blades" : "static deflection of the tower and blades",
                        "check the deck's stiffness and loads"},
                       "Newton's method did not converge in 20 iterations");
}

std::vector<int> FloatingScene::coordinates() const {
  std::vector<int> dofs;
  for (int k = 0; k < model_.dof_count; ++k)  // held DOFs are not coordinates: they do not move
    if (multibody::dof_active(model_, k) && !model_.acceleration_given[k]) dofs.push_back(k);
  return dofs;
}

RotorDemands FloatingScene::demands(const FloatingState& s) const {
  RotorDemands d;
  d.generator_torque_N_m = s.held.generator_torque_N_m;
  d.pitch_command_rad = s.held.pitch_rad;
  return d;
}

FloatingState FloatingScene::make_state() {
  FloatingState s;
  s.body = multibody::Multibody::make_state(model_);
  s.held.pitch_rad.fill(initial_pitch_rad_);
  s.body.blade_pitch_rad.fill(initial_pitch_rad_);
  if (controller_) s.controller = controller_->make_data();
  s.sea = sea_->initial_data();
  if (rotor_) s.aero = rotor_->make_data();
  if (riser_) s.riser = riser_->make_data(s.body);
  if (structure_.initial_conditions.rayleigh_ritz_blades_static && model_.rr_blades.mode_count > 0)
    settle_elastic(0.0, s, Settle::blades_in_motion);
  if (blades_) {
    s.blades = blades_->make_data();
    stage_loads_->act_on(s.held, s.sea, s.aero ? &*s.aero : nullptr, &*s.blades);
    stage_loads_->with_riser(s.riser ? &*s.riser : nullptr);
    blades_->start(shaft_at(0.0, s.body), s.body, initial_pitch_rad_, demands(s), *s.blades, s.aero ? &*s.aero : nullptr);
  }
  sample_controller(0.0, dt_s_, s);  // the demands of t = 0: held over the first step, in the first row
  s.max_rotor_speed_rad_s = std::abs(s.body.rotor_speed_rad_s);
  row_sea_ = s.sea;  // sized once: a row copies into them without allocating
  row_aero_ = s.aero;
  return s;
}

// The controller samples the state at t and holds its demands over [t, t + dt]. It runs at the
// end of a step (and once in make_state, at t = 0), so the row at t shows the demands made at t, as
// ServoDyn's GenTq and BldPitch do; the demands each step holds are those of its start either way.
void FloatingScene::sample_controller(double t, double dt, FloatingState& s) const {
  if (!controller_) return;
  control::ControllerInput u;
  u.generator_speed_rad_s = structure_.drivetrain.gearbox_ratio * s.body.generator_speed_rad_s;
  u.rotor_speed_rad_s = s.body.rotor_speed_rad_s;
  u.blade_pitch_rad = s.held.pitch_rad;  // each blade's held demand (the measured pitch of a rigid actuator)
  if (rotor_) u.hub_wind_speed_m_s = rotor_->probe_wind(t).x();
  controller_->advance(u, t, dt, *s.controller);
  s.held.generator_torque_N_m = s.controller->output.generator_torque_N_m;
  s.held.pitch_rad = s.controller->output.blade_pitch_rad;
  s.held.brake_engaged_at_s = s.controller->events.brake_engaged_at_s;
  for (std::size_t b = 0; b < s.held.pitch_rad.size(); ++b)
    s.body.blade_pitch_rad[b] = s.held.pitch_rad[b];  // the structure's blades turn to it at once (rigid pitch actuator)
}

double& FloatingScene::drivetrain_speed(multibody::State& body) const {
  return model_.generator_dof == multibody::kGenerator ? body.generator_speed_rad_s : body.rotor_speed_rad_s;
}

void FloatingScene::brake_before_step(double t, double dt, FloatingState& s) const {
  HeldDemands& h = s.held;
  if (!controller_ || controller_->brake_torque_N_m(*s.controller, t + dt) <= 0.0) {  // released, or not yet acting
    h.drivetrain_locked = false;
    h.brake_direction = 0.0;
    return;
  }
  if (h.drivetrain_locked) return;
  const double w = drivetrain_speed(s.body);
  if (w != 0.0) h.brake_direction = w > 0.0 ? 1.0 : -1.0;
  else if (h.brake_direction == 0.0) h.drivetrain_locked = true;  // at rest: held, unless the check after the step frees it
}

void FloatingScene::brake_after_step(double t_end, FloatingState& s) {
  HeldDemands& h = s.held;
  if (!controller_) return;
  const double brake = controller_->brake_torque_N_m(*s.controller, t_end);
  if (h.drivetrain_locked && blades_) {
    // Flexible blades: the lock's torque from the spin's balance in the blades' last small step.
    const double lock_torque = TurbineBlades::lock_torque_N_m(*s.blades);
    if (std::abs(lock_torque) > structure_.drivetrain.gearbox_ratio * brake) {
      h.drivetrain_locked = false;
      h.brake_direction = lock_torque > 0.0 ? -1.0 : 1.0;
    }
  } else if (h.drivetrain_locked) {
    // Stick holds while the torque the lock takes, on the HSS, is within the brake's: evaluated on
    // the row's copies of the sea and rotor data, so the state's warm starts stay as the step left them.
    row_sea_ = s.sea;
    if (rotor_ && !blades_) *row_aero_ = *s.aero;
    stage_loads_->act_on(h, row_sea_, row_aero_ ? &*row_aero_ : nullptr, s.blades ? &*s.blades : nullptr);
    stage_loads_->with_riser(s.riser ? &*s.riser : nullptr);
    multibody::AppliedLoads loads;
    stage_loads_->loads(t_end, s.body, loads);
    multibody::evaluate(model_, s.body, loads, t_end, evaluation_);
    const double lock_torque = evaluation_.drivetrain_lock_torque_N_m;  // LSS side of the generator's DOF
    if (std::abs(lock_torque) > structure_.drivetrain.gearbox_ratio * brake) {
      h.drivetrain_locked = false;
      h.brake_direction = lock_torque > 0.0 ? -1.0 : 1.0;  // it slips the way the drive turns it; the brake opposes that
    }
  } else if (h.brake_direction != 0.0 && drivetrain_speed(s.body) * h.brake_direction <= 0.0) {
    // The brake took the shaft through zero within the step: stopped there and held from here.
    if (blades_) {
      blades_->stop_spin(*s.blades, s.body);
    } else {
      s.body.generator_speed_rad_s = 0.0;
      if (model_.generator_dof != multibody::kGenerator) s.body.rotor_speed_rad_s = 0.0;
    }
    h.drivetrain_locked = true;
    h.brake_direction = 0.0;
  }
}

void FloatingScene::step(double t, double dt, FloatingState& s) {
  RotorAero::Data* aero = s.aero ? &*s.aero : nullptr;
  brake_before_step(t, dt, s);
  stage_loads_->act_on(s.held, s.sea, aero, s.blades ? &*s.blades : nullptr);
  stage_loads_->with_riser(s.riser ? &*s.riser : nullptr);
  const HangOffMotion top_before = riser_ ? riser_->hang_off(s.body) : HangOffMotion{};
  if (!blades_) {
    stage_loads_->begin_step(t);
    multibody::Multibody::advance(model_, *stage_loads_, t, dt, s.body);
    stage_loads_->end_step();
    if (rotor_) rotor_->advance_states(model_, s.body, t + dt, *aero);  // UA/DBEMT, if on
  } else {
    // The blades' spin takes the brake as a generator torque held over the large step (its ramp at
    // the step's middle: the mean of a linear ramp) while it slips, or as a lock.
    RotorDemands d = demands(s);
    d.drivetrain_locked = s.held.drivetrain_locked;
    if (controller_ && !s.held.drivetrain_locked)
      d.generator_torque_N_m += s.held.brake_direction * controller_->brake_torque_N_m(*s.controller, t + 0.5 * dt);
    blades_->advance(*stage_loads_, [this](double tt, const multibody::State& b) { return shaft_at(tt, b); }, d, t, dt,
                     s.body, *s.blades, aero);
  }
  // The riser's small steps through the platform's motion over the step (staggered, turbine_riser.hpp).
  if (riser_) riser_->advance(t, dt, top_before, s.body, *s.riser);
  sea_->advance(t + dt, platform_motion(s.body), s.sea);
  brake_after_step(t + dt, s);
  s.max_rotor_speed_rad_s = std::max(s.max_rotor_speed_rad_s, std::abs(s.body.rotor_speed_rad_s));
  sample_controller(t + dt, dt, s);
}

void FloatingScene::row(double t, const FloatingState& s, std::span<double> out, const InputOffsets& offsets) {
  // The row's own evaluation of the sea (and of a rigid rotor) works on copies: the state's warm
  // starts stay as the step left them.
  row_sea_ = s.sea;
  if (rotor_ && !blades_) *row_aero_ = *s.aero;
  const RotorAero::Data* aero = blades_ ? (s.aero ? &*s.aero : nullptr) : (row_aero_ ? &*row_aero_ : nullptr);
  stage_loads_->act_on(s.held, row_sea_, row_aero_ ? &*row_aero_ : nullptr, s.blades ? &*s.blades : nullptr, offsets);
  stage_loads_->with_riser(s.riser ? &*s.riser : nullptr);
  multibody::AppliedLoads loads;
  stage_loads_->loads(t, s.body, loads);
  stage_loads_->act_on(s.held, row_sea_, row_aero_ ? &*row_aero_ : nullptr, s.blades ? &*s.blades : nullptr);
  const std::span<double> v(values_);
  if (body_block_.written || sea_block_.written) {  // the hydro channels take the platform's acceleration
    const multibody::Output mo = multibody::Multibody::outputs(model_, loads, s.body, t);
    std::copy(mo.channels.begin(), mo.channels.begin() + body_block_.count, v.begin());
    Vec6 acceleration;
    acceleration << mo.platform_acceleration_m_s2, mo.platform_angular_acceleration_rad_s2;
    if (sea_block_.written) sea_->channel_values(t, row_sea_, acceleration, v.subspan(sea_block_.first, sea_block_.count));
  }
  if (rotor_block_.written) rotor_->channel_values(t, *aero, v.subspan(rotor_block_.first, rotor_block_.count));
  if (blades_block_.written) blades_->channel_values(*s.blades, v.subspan(blades_block_.first, blades_block_.count));
  if (riser_block_.written) riser_->channel_values(s.body, *s.riser, v.subspan(riser_block_.first, riser_block_.count));
  if (pitch_block_.written)
    for (std::size_t b = 0; b < pitch_block_.count; ++b) v[pitch_block_.first + b] = s.held.pitch_rad[b] * 180.0 / std::numbers::pi;
  if (controller_block_.written) {
    std::array<double, 6> c{};
    control::controller_channel_values(s.controller->output, c);
    for (std::size_t k = 0; k < controller_source_.size(); ++k) v[controller_block_.first + k] = c[controller_source_[k]];
  }
  if (brake_block_.written) v[brake_block_.first] = 1e-3 * controller_->brake_torque_N_m(*s.controller, t);
  for (std::size_t k = 0; k < picked_.size(); ++k) out[k] = values_[picked_[k]];
}

std::vector<std::uint64_t> FloatingScene::seeds() const {
  std::vector<std::uint64_t> seeds = sea_->seeds();
  if (rotor_ && rotor_->wind().params().model == wind::WindModel::turbulent) seeds.push_back(rotor_->wind().params().turbulence.seed);
  return seeds;
}

std::vector<std::string> FloatingScene::warnings(const FloatingState& s) const {
  std::vector<std::string> warnings = input_warnings_;
  if (overspeed_rad_s_ > 0.0 && s.max_rotor_speed_rad_s > overspeed_rad_s_)
    warnings.push_back(fmt::format("rotor overspeed: {:.3g} rpm, more than 30 % above the controller's rated {:.3g} rpm",
                                   s.max_rotor_speed_rad_s * 30.0 / std::numbers::pi, overspeed_rad_s_ / 1.3 * 30.0 / std::numbers::pi));
  if (rotor_ && rotor_->wind().outside_queries() > 0)
    warnings.push_back(fmt::format("{} wind queries fell outside the turbulence grid (deflected tips or a displaced "
                                   "rotor beyond its edge) and took the mean wind profile there",
                                   rotor_->wind().outside_queries()));
  return warnings;
}

void FloatingScene::finish(double t, FloatingState& s) const {
  if (controller_) controller_->finish(t, *s.controller);
}

std::string FloatingScene::coupling_description() const {
  std::vector<std::string> parts{model_.flexible_tower.mode_count > 0 ? "multibody with the flexible tower" : "multibody, rigid tower"};
  if (!sea_description_.empty()) parts.push_back(sea_description_);
  if (blades_) parts.push_back(blades_->description() + (rotor_ ? ", BEM on the deflected blades" : ", no aerodynamics"));
  else if (rotor_) {
    // aero.induction: the inductions solved at every stage, or once per large step and held.
    const std::string bem = rotor_->params().induction_held_over_step ? "BEM inductions solved once per large step, held over its stages"
                                                                      : "BEM at every RK4 stage";
    parts.push_back(model_.rr_blades.mode_count > 0 ? "Rayleigh-Ritz blades with " + bem + " on the deflected blades"
                                                    : "rigid blades with " + bem);
  }
  else parts.push_back("rigid blades, no aerodynamics");
  if (riser_) parts.push_back(riser_->description());
  parts.push_back(controller_ ? "controller at the large step" : "no controller (generator torque 0, pitch held)");
  std::string text;
  for (const std::string& p : parts) text += (text.empty() ? "" : "; ") + p;
  return text;
}

RunReport run_floating_scene(const RunRequest& request, const ProgressCallback& progress) {
  const io::ValidatedDeck deck = io::read_deck(floating_scene_schema(), request.deck_path, request.deck_settings);
  const double t_end_s = request.t_max_s.value_or(simulation_keys(deck).t_max_s);
  FloatingScene scene(deck, FloatingScene::SetUp::run, t_end_s, request.turbulence_cache);
  FloatingState state = scene.make_state();
  FixedStepScene run;
  run.written = scene.written();
  run.metadata.seeds = scene.seeds();
  run.metadata.extra = {{"scene", "floating"}};
  // A blade tip reaches about one tip radius (plus the overhang) upwind of the tower axis.
  const double upwind_reach_m = deck.number("structure.rotor.tip_radius_m") + std::abs(deck.number("structure.nacelle.overhang_m"));
  run.input_warnings = record_length_warnings(scene.wind(), upwind_reach_m, scene.sea().incident_waves(), t_end_s);
  run.step = [&](double t, double dt) { scene.step(t, dt, state); };
  run.row = [&](double t, std::span<double> row) { scene.row(t, state, row); };
  if (scene.can_checkpoint()) {  // the scene state whole, through its field lists
    run.save = [&](CheckpointWriter& w) { w.io(state); };
    run.load = [&](CheckpointReader& r) { r.io(state); };
  }
  run.warnings = [&](std::vector<std::string>& warnings) {
    for (const std::string& w : scene.warnings(state)) warnings.push_back(w);
  };
  RunReport report = [&] {
    try {
      return run_fixed_steps(request, deck, std::move(run), progress);
    } catch (...) {
      scene.finish(0.0, state);
      throw;
    }
  }();
  scene.finish(report.simulated_s, state);
  report.substeps = scene.substeps();
  report.coupling = scene.coupling_description();
  return report;
}

}  // namespace fowtsim::driver
