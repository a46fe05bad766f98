#pragma once
// The floating-turbine scene: the rigid multibody (platform + tower, nacelle, hub, drivetrain)
// under gravity, hydrodynamics, hydrostatics and mooring in a sea (evaluated at every Runge–Kutta
// stage of the large step; the hydro added mass on the left-hand side), with rigid blades and BEM
// at every stage, or with three flexible MBBT blades, their aerodynamics and the rotor spin at the
// small step (turbine_blades.hpp); the controller at the large step. The OC3-Hywind decks in
// inputs/oc3_hywind and the seed's cases in inputs/seed_cases are its verification and load cases.
//
// Model and state apart (as Drake's System and Context, MuJoCo's mjModel and mjData): a
// FloatingScene is what the deck says, fixed for the run; everything that changes lives in one
// plain, copyable FloatingState. A step advances a state; a row reads one and changes nothing, so
// output decimation changes nothing; a copy continues bit-identically; a checkpoint writes it
// through its field lists (core/fields.hpp).
#include <array>
#include <limits>
#include <memory>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/multibody/dynamics.hpp"
#include "fowtsim/multibody/model.hpp"
#include "fowtsim/multibody/state.hpp"
#include "run/run_types.hpp"
#include "rotor/rotor_aero.hpp"
#include "scenes/sea_modules.hpp"
#include "scenes/turbine_blades.hpp"
#include "scenes/turbine_controller.hpp"
#include "scenes/turbine_riser.hpp"

namespace fowtsim::driver {

io::Schema floating_scene_schema();
RunReport run_floating_scene(const RunRequest& request, const ProgressCallback& progress);

// The controller's demands, held over the large step, and the HSS brake's contact with the shaft.
struct HeldDemands {
  double generator_torque_N_m = 0.0;           // HSS
  std::array<double, 3> pitch_rad{};           // per blade [rad]
  double brake_engaged_at_s = std::numeric_limits<double>::quiet_NaN();  // the brake's THSSBrDp (NaN: released) [s]
  // Stick: the brake holds the drivetrain at rest (multibody::AppliedLoads::drivetrain_locked).
  bool drivetrain_locked = false;
  // Slip: the sign of the brake torque in GenTq's convention (+1 brakes a positive speed): the
  // shaft's direction of motion at the step's start (or, from rest, the way the drive torque turns it).
  double brake_direction = 0.0;
};

// Small offsets of the scene's inputs about a state, for the input and output matrices of a
// linearisation (fowtsim screen, scenes/floating_screening.hpp); zero in a run.
struct InputOffsets {
  Vec6 platform_load = Vec6::Zero();  // extra [F; M] on the platform about its reference point, g [N, N·m]
  double wind_speed_m_s = 0.0;        // uniform wind along the hub's mean inflow, on the rigid rotor only [m/s]
};

// Everything of a floating scene that changes during a run.
struct FloatingState {
  multibody::State body;
  HeldDemands held;
  std::optional<TurbineController::Data> controller;  // with a `controller` section
  SeaModules::Data sea;
  std::optional<RotorAero::Data> aero;                // with an `aero` section
  std::optional<TurbineBlades::Data> blades;          // with a `blades` section
  std::optional<TurbineRiser::Data> riser;            // with a `riser` section
  double max_rotor_speed_rad_s = 0.0;                 // |Ω| so far (the overspeed warning)
};

template <class Archive>
void fields(Archive& a, HeldDemands& h) {
  a.io(h.generator_torque_N_m, h.pitch_rad, h.brake_engaged_at_s, h.drivetrain_locked, h.brake_direction);
}
template <class Archive>
void fields(Archive& a, FloatingState& s) {
  a.io(s.body, s.held, s.controller, s.sea, s.aero, s.blades, s.riser, s.max_rotor_speed_rad_s);
}

class FloatingScene {
 public:
  // Reads and checks the deck (InputError with file:line before anything runs). `check` sets up
  // all but a turbulent wind field (RotorAero::WindSetUp): a scene to check a deck with, not to run.
  // `run_until_s`: where the run ends, if known; a generated wind field then holds only the part
  // the run reaches (the same values: the record is still the deck's whole duration).
  // `turbulence_cache`: a folder of generated fields runs share (run --turbulence-cache).
  enum class SetUp { run, check };
  explicit FloatingScene(const io::ValidatedDeck& deck, SetUp setup = SetUp::run, std::optional<double> run_until_s = std::nullopt,
                         const std::optional<std::filesystem::path>& turbulence_cache = std::nullopt);
  FloatingScene(const FloatingScene&) = delete;  // the blades and the loads refer to members
  FloatingScene& operator=(const FloatingScene&) = delete;
  ~FloatingScene();

  // The state at t = 0: initial conditions, and the flexible blades at their start solution.
  FloatingState make_state();
  // Advances `s` from t to t + dt (one large step: multibody, blades, sea memory, then the
  // controller's demands for the next step).
  void step(double t, double dt, FloatingState& s);
  // The written channels at t (in written() order) of `s`, which it leaves as it is.
  void row(double t, const FloatingState& s, std::span<double> out) { row(t, s, out, InputOffsets{}); }
  // The same under input offsets (their derivatives: the output matrices of a linearisation).
  void row(double t, const FloatingState& s, std::span<double> out, const InputOffsets& offsets);
  // The accelerations of coordinates() in `s` at t under input offsets (the state's held demands,
  // its sea and aero memories held as linearised_system holds them).
  Eigen::VectorXd accelerations(double t, const FloatingState& s, const InputOffsets& offsets);

  const std::vector<ChannelInfo>& written() const { return written_; }
  bool can_checkpoint() const { return !controller_ || controller_->can_checkpoint(); }
  std::vector<std::uint64_t> seeds() const;
  // Inputs far outside sense, and what the run showed (overspeed, wind outside the grid).
  std::vector<std::string> warnings(const FloatingState& s) const;
  // The last call a DISCON library gets, at the end of the run (or a failure at t = 0).
  void finish(double t, FloatingState& s) const;
  std::string coupling_description() const;
  // The inflow (null without aerodynamics) and the sea, for checks of the records they read.
  // The equations of motion linearised about `s` at time t (fowtsim modes): ẋ = A x for
  // x = [δq; u], q the multibody's coordinates() (platform position in g, rotation in b, rotor and
  // generator angles, tower and Rayleigh–Ritz blade modes) and u their speeds, by central differences of the stage loads and the
  // multibody's accelerations. Open loop: the controller's demands are held; the sea's radiation
  // memory is held (potential flow enters through A(∞)). The flexible blades' own states are not in
  // x: InputError with them.
  Eigen::MatrixXd linearised_system(double t, const FloatingState& s);
  // Static deflection in `s` at time t, by Newton's method on a central-difference Jacobian: the
  // elastic rows of the generalised forces vanish, f_e(q_e) = 0, with the elastic rates zero and the
  // rigid coordinates where they are (gravity, the sea and the aerodynamics of that state).
  //  - tower_and_blades_at_rest (fowtsim modes): the flexible tower and the Rayleigh–Ritz blades,
  //    every speed zero;
  //  - blades_in_motion (structure.initial_conditions.blade_deflection: static): the Rayleigh–Ritz
  //    blades only, the rigid speeds as they are — the spin's centrifugal stiffening and the
  //    aerodynamic loads of the operating rotor; the rigid DOFs' accelerations, small at a trimmed
  //    start, do not enter.
  // NumericalError if it does not converge in 20 iterations; InputError with the flexible (MBBT)
  // blades (their states are not in it).
  enum class Settle { tower_and_blades_at_rest, blades_in_motion };
  void settle_elastic(double t, FloatingState& s, Settle how = Settle::tower_and_blades_at_rest);
  // The multibody DOFs (model.hpp Dof indices) the linearisation's coordinates are, in order: the
  // model's DOFs less the held ones.
  std::vector<int> coordinates() const;
  int tower_fore_aft_modes() const { return model_.flexible_tower.fore_aft_count; }
  const wind::WindField* wind() const { return rotor_ ? &rotor_->wind() : nullptr; }
  const SeaModules& sea() const { return *sea_; }
  int substeps() const { return blades_ ? blades_->substeps() : 1; }  // small steps per large step (the blades')
  const TurbineRiser* riser() const { return riser_ ? &*riser_ : nullptr; }

 private:
  void refuse_flexible_blades_in_modes() const;  // InputError: their states are not linearised
  class StageLoads;
  ShaftMotion shaft_at(double t, const multibody::State& body);
  // The equations of motion at `body` (into evaluation_) under the stage loads of `work`, a copy of
  // `s` whose sea and aero data are reset from `s` first (warm starts and memories stay as s has them).
  void evaluate_on_copy(double t, const FloatingState& s, const multibody::State& body, FloatingState& work,
                        const InputOffsets& offsets = {});
  RotorDemands demands(const FloatingState& s) const;
  void sample_controller(double t, double dt, FloatingState& s) const;
  // The HSS brake over a step from t to t + dt: stick or slip before it (brake_before_step), a
  // stop or a slip from rest after it (brake_after_step). ElastoDyn's FixHSSBrTq (FAST_Subs)
  // limits the brake torque so that it never reverses the shaft; here a shaft whose speed the
  // brake takes through zero within a step is stopped there and held while the brake can hold it.
  void brake_before_step(double t, double dt, FloatingState& s) const;
  void brake_after_step(double t_end, FloatingState& s);
  double& drivetrain_speed(multibody::State& body) const;

  multibody::Params structure_;
  multibody::Model model_;
  std::optional<SeaModules> sea_;
  std::optional<RotorAero> rotor_;
  std::optional<TurbineController> controller_;
  std::optional<TurbineBlades> blades_;
  std::optional<TurbineRiser> riser_;
  std::unique_ptr<StageLoads> stage_loads_;
  double initial_pitch_rad_ = 0.0;
  double dt_s_ = 0.0;             // the large step (simulation.dt_s)
  double overspeed_rad_s_ = 0.0;  // 30 % above the built-in law's rated rotor speed (0: unknown)
  std::vector<std::string> input_warnings_;
  std::string sea_description_;  // what coupling_description() says of hydro and mooring

  // Channels: each module's block is computed only when a written channel is in it.
  struct Block {
    std::size_t first = 0, count = 0;  // in all_
    bool written = false;
  };
  std::vector<ChannelInfo> all_, written_;
  std::vector<std::size_t> picked_;                   // indices into all_, in written order
  Block body_block_, sea_block_, rotor_block_, blades_block_, riser_block_, pitch_block_, controller_block_, brake_block_;
  std::vector<std::size_t> controller_source_;        // controller block channel k ← controller_channels()[source[k]]

  // Workspace (written before it is read; nothing in it crosses a step).
  multibody::Evaluation evaluation_;
  std::vector<double> values_;                        // every channel of the row
  SeaModules::Data row_sea_;                          // a row evaluates the sea and rigid rotor on copies
  std::optional<RotorAero::Data> row_aero_;
};

}  // namespace fowtsim::driver
