#include "scenes/turbine_blades.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "decks/beam_deck.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "decks/deck_helpers.hpp"
#include "fowtsim/core/rotation_vector.hpp"
#include "rotor/rotor_aero.hpp"

namespace fowtsim::driver {

using io::Schema;

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

// The `blades:` keys: the beam's (decks/beam_deck.hpp), then the coupling, the start, the
// outputs, the step-matrix reuse and the pitch actuator.
struct BladesKeys : BeamKeys {
  FlexibleRotor::Start start = FlexibleRotor::Start::static_loads;
  CouplingMode coupling = CouplingMode::multi_rate;
  int substeps = 4;
  double stiffness_scale = 1.0;
  std::vector<double> gauges_eta;
  bool nodal_deflections = false;
  bool induction_every_small_step = false;
  int step_matrix_max_age = 40;
  double step_matrix_max_rotation_rad = 0.02;
  double pitch_actuator_frequency_hz = 2.0;
  double pitch_actuator_damping_ratio = 0.7;
  std::string interface_mass = "auto";
};

// Each key once: name, schema and the field it fills (decks/deck_section.hpp).
const DeckSection<BladesKeys>& blades_section() {
  static const DeckSection<BladesKeys> section = [] {
    DeckSection<BladesKeys> b;
    // Three blades at every small step: 1000 volumes (6 cm on the 5MW blade) still run at 2.8×
    // real time (seed validation deck); more is a typo, not a model (100,000 ran for minutes).
    b.keys_of(beam_section(23, 1000))
        .key("start", Schema::choice({"static", "centrifugal", "undeformed"}).default_value("static")
                          .doc("static: each blade starts from its static solution under the initial frame motion, "
                               "gravity and aero loads; centrifugal: under the frame motion alone (BeamDyn's "
                               "QuasiStaticInit, as OpenFAST's BeamDyn decks start); undeformed: the unloaded shape"),
             &BladesKeys::start,
             [](const std::string& how) {
               return how == "static"        ? FlexibleRotor::Start::static_loads
                      : how == "centrifugal" ? FlexibleRotor::Start::centrifugal
                                             : FlexibleRotor::Start::undeformed;
             })
        .key("coupling", Schema::choice({"multi_rate", "predictor_corrector", "single_rate"})
                             .default_value("multi_rate").doc("exchange between the multibody (ΔT) and the blades (Δt)"),
             &BladesKeys::coupling, parse_coupling_mode)
        .key("substeps", Schema::integer().at_least(1).at_most(10000).default_value(4)
                             .doc("n = ΔT/Δt: blade steps per large step (single_rate needs 1)"),
             &BladesKeys::substeps)
        .key("stiffness_scale", Schema::number().greater_than(0.0).default_value(1.0)
                                    .doc("factor on every sectional stiffness (1000: the stiff-blade check)"),
             &BladesKeys::stiffness_scale)
        .key("gauges_eta", Schema::sequence(Schema::number().at_least(0.0).at_most(1.0)).max_items(9).optional()
                               .doc("span gauges: arclength fractions for Spn<k>FL/ML{x,y,z}b<b> (internal loads in the local section frame, as ElastoDyn's)"),
             &BladesKeys::gauges_eta)
        .key("nodal_deflections", Schema::boolean().default_value(false)
                                      .doc("write every node's deflection B<b>N<nnn>_TD{x,y,z}r (BeamDyn's nodal names, root "
                                           "frame r, from the undeformed node): the input of proper orthogonal modes (fowtsim post --pom)"),
             &BladesKeys::nodal_deflections)
        .key("induction", Schema::choice({"large_step", "small_step"}).default_value("large_step")
                              .doc("BEM inductions solved once per large step and held over its small steps "
                                   "(loads follow the blade motion at every small step), or solved at every small step"),
             &BladesKeys::induction_every_small_step, [](const std::string& v) { return v == "small_step"; })
        // Reuse of each blade's factored generalized-α step matrix (beam::DynamicOptions: a modified-
        // Newton step, second order in the step). Measured on the default deck, 60 s: rebuilding after
        // 40 steps or 0.02 rad changes root moments, tip deflections, rotor speed and platform pitch by
        // ≤ 2e-5 of their standard deviation against rebuilding at every step, over 200× less than
        // halving Δt changes them (flexible_turbine_tests.cpp checks the same in steady wind). The beam
        // module's tighter defaults (20 steps, 0.002 rad) are set on the seeds' large-deflection
        // benchmarks and cost 30 % more run time here; a rebuild at every step costs 2×.
        .key("step_matrix_max_age", Schema::integer().at_least(1).default_value(40)
                                        .doc("blade steps before the factored step matrix is rebuilt (1: every step, the seed's scheme)"),
             &BladesKeys::step_matrix_max_age)
        .key("step_matrix_max_rotation_rad", Schema::number().greater_than(0.0).default_value(0.02)
                                                 .doc("or once the sum of the largest nodal rotation per step exceeds this"),
             &BladesKeys::step_matrix_max_rotation_rad)
        .key("pitch_actuator_frequency_hz", Schema::number().greater_than(0.0).default_value(2.0)
                                                .doc("natural frequency of the second-order pitch actuator"),
             &BladesKeys::pitch_actuator_frequency_hz)
        .key("pitch_actuator_damping_ratio", Schema::number().greater_than(0.0).default_value(0.7).doc("its damping ratio"),
             &BladesKeys::pitch_actuator_damping_ratio)
        // The interface Jacobian of the exchange (turbine_blades.hpp; modules/multibody/README.md
        // "Flexible tower with MBBT blades": without it the flexible tower's exchange diverges).
        .key("interface_mass", Schema::choice({"auto", "on", "off"}).default_value("auto")
                                   .doc("the multibody takes the rotor's apparent mass on the shaft (the blades' root-load "
                                        "response to the shaft's acceleration over a large step, the free spin condensed out) "
                                        "implicitly and holds only the remainder at the step's end; auto: on with "
                                        "structure.tower.flexible, off on the rigid tower (its results as before)"),
             &BladesKeys::interface_mass);
    return b;
  }();
  return section;
}

BladesKeys blades_keys(const io::ValidatedDeck& deck) {
  return blades_section().read(deck.section("blades"));
}

}  // namespace

Schema blades_schema() { return blades_section().schema(); }

void TurbineBlades::configure(multibody::Params& p) {
  p.rotor.flexible_blades = true;
  if (p.dofs.rotor == multibody::RotorSpin::free) p.dofs.rotor = multibody::RotorSpin::prescribed;
}

namespace {

FlexibleRotorParams rotor_params(const io::ValidatedDeck& deck, const multibody::Model& model) {
  const BladesKeys keys = blades_keys(deck);
  FlexibleRotorParams p;
  beam::BeamDefinition definition = beam_definition(deck, "blades", keys);
  for (beam::Station& station : definition.stations) station.stiffness *= keys.stiffness_scale;
  p.blade = located(deck.section("blades"), [&] { return beam::discretise(definition, keys.segments); });
  p.dynamics.integrator = beam::integrator_from_name(keys.integrator);
  p.dynamics.spectral_radius = keys.spectral_radius;
  p.dynamics.matrix_max_age = keys.step_matrix_max_age;
  p.dynamics.matrix_max_rotation_rad = keys.step_matrix_max_rotation_rad;
  const multibody::Params& s = model.params;
  p.hub_inertia_kg_m2 = s.rotor.hub_inertia_kg_m2;
  p.hub_mass_kg = s.rotor.hub_mass_kg;
  p.hub_cm_m = s.rotor.hub_cm_m;
  p.generator_inertia_kg_m2 = s.drivetrain.generator_inertia_kg_m2;
  p.gearbox_ratio = s.drivetrain.gearbox_ratio;
  p.torsional_flexibility = s.drivetrain.torsional_flexibility;
  p.torsional_stiffness_N_m_rad = s.drivetrain.torsional_stiffness_N_m_rad;
  p.torsional_damping_N_m_s_rad = s.drivetrain.torsional_damping_N_m_s_rad;
  p.spin = s.dofs.rotor == multibody::RotorSpin::held ? SpinMode::held : SpinMode::free;
  for (int i = 0; i < kBlades; ++i) {
    p.root_orientation_h[i] = model.blade_root_orientation_h[i];
    p.root_h[i] = model.blade_root_h[i];
  }
  p.gravity_m_s2 = s.gravity_m_s2;
  p.pitch_natural_frequency_rad_s = 2.0 * std::numbers::pi * keys.pitch_actuator_frequency_hz;
  p.pitch_damping_ratio = keys.pitch_actuator_damping_ratio;
  p.induction_every_small_step = keys.induction_every_small_step;
  if (model.blade_count != kBlades)
    throw InputError({"floating", std::nullopt, "structure.rotor.blade_count", "3"},
                     where(deck, "structure.rotor.blade_count") + ": flexible blades need a three-bladed rotor");
  const double length = s.rotor.tip_radius_m - s.rotor.hub_radius_m;
  if (std::abs(p.blade.length_m / length - 1.0) > 1e-3)
    throw InputError({"floating", std::nullopt, "blades.key_points_m", "the structure's blade length"},
                     where(deck, "blades.key_points_m") +
                         fmt::format(": the blade is {:.4g} m long, tip − hub radius of the structure is {:.4g} m",
                                     p.blade.length_m, length));
  return p;
}

}  // namespace

TurbineBlades::TurbineBlades(const io::ValidatedDeck& deck, const multibody::Model& model, const RotorAero* aero)
    : model_(model),
      params_(rotor_params(deck, model)),
      map_(aero ? std::optional<BladeAeroMap>(std::in_place, aero->params(), params_.blade,
                                              -model.params.rotor.precone_deg / kRadToDeg, model.params.rotor.hub_radius_m)
                : std::nullopt),
      rotor_(params_, aero, map_ ? &*map_ : nullptr) {
  const BladesKeys keys = blades_keys(deck);
  mode_ = keys.coupling;
  substeps_ = keys.substeps;
  if (mode_ == CouplingMode::single_rate && substeps_ != 1)
    throw InputError({"floating", std::nullopt, "blades.substeps", "1 with single_rate"},
                     where(deck, "blades.substeps") + ": single_rate coupling takes one blade step per large step");
  gauges_eta_ = keys.gauges_eta;
  nodal_deflections_ = keys.nodal_deflections;
  start_ = keys.start;
  interface_mass_ = keys.interface_mass == "on" || (keys.interface_mass == "auto" && model.params.tower.flexible);
  for (const beam::NodeModel& n : params_.blade.nodes) {
    blade_mass_kg_ += n.mass_kg;
    blade_first_moment_f_ +=
        n.mass_kg * (n.position_m + n.orientation * n.mass_offset_m - params_.blade.root_position_m);
  }
}

Vec3 TurbineBlades::first_moment_h(const std::array<double, kBlades>& pitch_rad) const {
  Vec3 s = Vec3::Zero();
  for (int b = 0; b < kBlades; ++b)
    s += blade_mass_kg_ * params_.root_h[b] +
         params_.root_orientation_h[b] * (rotation_matrix(Vec3(0.0, 0.0, -pitch_rad[b])) * blade_first_moment_f_);
  return s;
}

FlexibleRotor::HubLoad TurbineBlades::blade_weight_h(const FlexibleRotor::Data& r) const {
  const Mat3 t_gh = r.shaft.orientation * rotation_matrix(Vec3(r.state.spin.rotor_azimuth_rad, 0.0, 0.0));
  const Vec3 g_h = t_gh.transpose() * Vec3(0.0, 0.0, -params_.gravity_m_s2);
  return {kBlades * blade_mass_kg_ * g_h, first_moment_h(r.state.pitch_rad).cross(g_h)};
}

void TurbineBlades::refresh_apparent_mass(Data& d, const RotorDemands& demands, double dt_large) {
  const double h = rotor_.apparent_mass_step(dt_large, substeps_);
  bool refreshed = false;
  for (int b = 0; b < kBlades; ++b) {
    if (d.rotor.state.blades[b].step_matrix.age > substeps_) continue;  // not rebuilt within this large step
    d.blade_apparent_mass_h[b] = rotor_.blade_apparent_mass_h(d.rotor.shaft, d.rotor.state, h, b, demands.gravity);
    refreshed = true;
  }
  if (!refreshed) return;
  Mat6 blades = Mat6::Zero();
  for (const Mat6& m : d.blade_apparent_mass_h) blades += m;
  d.apparent_mass_h = rotor_.with_spin_condensed(blades, h, demands);
}

Vec6 TurbineBlades::shaft_acceleration_h(const Data& d) {
  const ShaftMotion& sh = d.rotor.shaft;
  const Mat3 t_gh = sh.orientation * rotation_matrix(Vec3(d.rotor.state.spin.rotor_azimuth_rad, 0.0, 0.0));
  Vec6 a;
  a << t_gh.transpose() * sh.apex_acceleration_m_s2, t_gh.transpose() * sh.angular_acceleration_rad_s2;
  return a;
}

void TurbineBlades::start(const ShaftMotion& shaft, const multibody::State& state, double pitch_rad,
                          const RotorDemands& demands, Data& d, RotorAero::Data* aero) {
  rotor_.start(shaft, state.rotor_azimuth_rad, state.rotor_speed_rad_s, pitch_rad, demands, start_, d.rotor, aero);
  d.held = d.rotor.last;
  d.held += -1.0 * blade_weight_h(d.rotor);
  use_extrapolated_spin_profile(0.0, d);
}

void TurbineBlades::add_stage_loads(const multibody::ChainKinematics& chain, const Data& d,
                                    multibody::AppliedLoads& out) const {
  const Mat3& t_gh = chain.rotor.orientation;
  // The held load, turned with the hub, and the blades' weight in its place now (header).
  const Vec3 g(0.0, 0.0, -params_.gravity_m_s2);
  out.rotor_force_N += t_gh * d.held.force_h_N + (kBlades * blade_mass_kg_) * g;
  out.rotor_moment_N_m += t_gh * d.held.moment_h_N_m + (t_gh * first_moment_h(d.rotor.state.pitch_rad)).cross(g);
  if (!interface_mass_) return;
  Mat6 turn = Mat6::Zero();
  turn.topLeftCorner<3, 3>() = t_gh;
  turn.bottomRightCorner<3, 3>() = t_gh;
  out.rotor_added_mass += turn * d.apparent_mass_h * turn.transpose();
}

multibody::SpinMotion TurbineBlades::spin(double t, const Data& d) const {
  const double tau = t - d.profile.t0;
  const multibody::SpinMotion& s = d.profile.at_t0;
  multibody::SpinMotion m = s;
  m.rotor_azimuth_rad = s.rotor_azimuth_rad + tau * s.rotor_speed_rad_s + 0.5 * tau * tau * s.rotor_acceleration_rad_s2;
  m.rotor_speed_rad_s = s.rotor_speed_rad_s + tau * s.rotor_acceleration_rad_s2;
  m.generator_azimuth_rad =
      s.generator_azimuth_rad + tau * s.generator_speed_rad_s + 0.5 * tau * tau * s.generator_acceleration_rad_s2;
  m.generator_speed_rad_s = s.generator_speed_rad_s + tau * s.generator_acceleration_rad_s2;
  return m;
}

void TurbineBlades::use_extrapolated_spin_profile(double t, Data& d) const {
  const SpinState& s = d.rotor.state.spin;
  // With the interface mass the hub's and generator's spin accelerations are taken where the held
  // remainder is, at the step's end (their last small step), not centred ΔT/2 before it: M_h
  // linearises both about the same instant.
  const double rotor = interface_mass_ ? s.rotor_mean_acceleration_rad_s2 : d.mean_rotor_acceleration_rad_s2;
  const double generator = interface_mass_ ? s.generator_mean_acceleration_rad_s2 : d.mean_generator_acceleration_rad_s2;
  d.profile.t0 = t;
  d.profile.at_t0 = {s.rotor_azimuth_rad, s.rotor_speed_rad_s, rotor, s.generator_azimuth_rad, s.generator_speed_rad_s, generator};
}

// The turbine as a pair for multi_rate_step: the multibody (slow) and the blades with the spin
// (fast). The blades continue each large step from the shaft motion they ended the previous one
// on (with predictor_corrector, the corrected multibody state is not sampled again at T).
class TurbineBlades::Coupling {
 public:
  using Motion = ShaftMotion;
  using Load = FlexibleRotor::HubLoad;
  using SlowState = multibody::State;
  Coupling(TurbineBlades& blades, multibody::LoadProvider& provider, const ShaftAt& shaft_at, const RotorDemands& demands,
           multibody::State& state, Data& d, RotorAero::Data* aero)
      : b_(blades), provider_(provider), shaft_at_(shaft_at), demands_(demands), state_(state), d_(d), aero_(aero) {}

  const multibody::State& slow_state() const { return state_; }
  void restore_slow_state(const multibody::State& saved) { state_ = saved; }
  ShaftMotion motion_at_step_start() const { return d_.rotor.shaft; }
  // Predictor: the held root loads and the spin extrapolated from the blades'; corrector: the new
  // average and the spin the blades took over the step.
  void advance_slow(double t, double dt, SlowPass pass) {
    if (pass == SlowPass::predictor) {
      b_.use_extrapolated_spin_profile(t, d_);
      d_.spin_before = d_.rotor.state.spin;
    } else {
      use_step_spin_profile(t, d_);
    }
    multibody::Multibody::advance(b_.model_, provider_, t, dt, state_);
  }
  ShaftMotion slow_motion(double t) const { return shaft_at_(t, state_); }
  void advance_fast(double t, double dt, const SubstepMotion<ShaftMotion>& slow) {
    b_.rotor_.advance(t, dt, slow, demands_, d_.rotor, aero_);
  }
  // Without their weight, which the stages add at their own hub orientation (header).
  FlexibleRotor::HubLoad root_loads() const {
    FlexibleRotor::HubLoad l = d_.rotor.last;
    l += -1.0 * b_.blade_weight_h(d_.rotor);
    return l;
  }
  void hold(const FlexibleRotor::HubLoad& average, double dt_large) {
    const SpinState& after = d_.rotor.state.spin;
    d_.mean_rotor_acceleration_rad_s2 = (after.rotor_speed_rad_s - d_.spin_before.rotor_speed_rad_s) / dt_large;
    d_.mean_generator_acceleration_rad_s2 = (after.generator_speed_rad_s - d_.spin_before.generator_speed_rad_s) / dt_large;
    if (!b_.interface_mass_) {
      d_.held = average;
      return;
    }
    b_.refresh_apparent_mass(d_, demands_, dt_large);
    // The remainder at the step's end, R = F + M_h a (header): free of the shaft's acceleration, so
    // what averaging buys a load that follows the fast motion matters less here than the lag — the
    // average is centred ΔT/2 before the next step starts, this sample at its start.
    const Vec6 remainder = d_.apparent_mass_h * shaft_acceleration_h(d_);
    d_.held = root_loads();
    d_.held.force_h_N += remainder.head<3>();
    d_.held.moment_h_N_m += remainder.tail<3>();
  }
  void finish_large_step() { copy_spin(d_, state_); }  // the blades own the spin

 private:
  TurbineBlades& b_;
  multibody::LoadProvider& provider_;
  const ShaftAt& shaft_at_;
  const RotorDemands& demands_;
  multibody::State& state_;
  Data& d_;
  RotorAero::Data* aero_;
};

void TurbineBlades::advance(multibody::LoadProvider& provider, const ShaftAt& shaft_at, const RotorDemands& demands,
                            double t, double dt_large, multibody::State& state, Data& d, RotorAero::Data* aero) {
  Coupling coupling(*this, provider, shaft_at, demands, state, d, aero);
  CouplingSettings settings;
  settings.mode = mode_;
  settings.dt_coupling_s = dt_large;
  settings.substeps = substeps_;
  multi_rate_step(coupling, settings, t);
}

void TurbineBlades::use_step_spin_profile(double t, Data& d) {
  // The corrector pass of the multibody through the spin the fast side took over the step.
  d.profile.t0 = t;
  d.profile.at_t0 = {d.spin_before.rotor_azimuth_rad, d.spin_before.rotor_speed_rad_s, d.mean_rotor_acceleration_rad_s2,
                     d.spin_before.generator_azimuth_rad, d.spin_before.generator_speed_rad_s,
                     d.mean_generator_acceleration_rad_s2};
}

void TurbineBlades::stop_spin(Data& d, multibody::State& state) const {
  SpinState& s = d.rotor.state.spin;
  s.generator_speed_rad_s = s.generator_acceleration_rad_s2 = s.generator_mean_acceleration_rad_s2 = 0.0;
  d.mean_generator_acceleration_rad_s2 = 0.0;
  if (!params_.torsional_flexibility) {
    s.rotor_speed_rad_s = s.rotor_acceleration_rad_s2 = s.rotor_mean_acceleration_rad_s2 = 0.0;
    d.mean_rotor_acceleration_rad_s2 = 0.0;
  }
  copy_spin(d, state);
}

void TurbineBlades::copy_spin(const Data& d, multibody::State& state) {
  const SpinState& s = d.rotor.state.spin;
  multibody::set_spin({s.rotor_azimuth_rad, s.rotor_speed_rad_s, d.mean_rotor_acceleration_rad_s2, s.generator_azimuth_rad,
                       s.generator_speed_rad_s, d.mean_generator_acceleration_rad_s2},
                      state);
}

std::string TurbineBlades::description() const {
  return fmt::format("3 flexible MBBT blades ({} finite volumes, {} start), rotor spin solved with them; {} coupling, "
                     "{} blade steps per large step",
                     rotor_.params().blade.node_count(),
                     start_ == FlexibleRotor::Start::static_loads ? "static"
                     : start_ == FlexibleRotor::Start::centrifugal ? "centrifugal"
                                                                    : "undeformed",
                     to_string(mode_),
                     substeps_);
}

// Channels, OpenFAST names (ElastoDyn for the coned c and blade b frames, BeamDyn's B<b>…r for
// the pitched root frame r = f): root loads are the blade's loads on the hub, tip deflections
// relative to the undeformed blade moving with its root frame.
std::vector<ChannelInfo> TurbineBlades::channels() const {
  std::vector<ChannelInfo> c;
  const char* axes = "xyz";
  for (int b = 1; b <= kBlades; ++b) {
    for (const char* frame : {"c", "b"}) {
      for (int i = 0; i < 3; ++i)
        c.push_back({fmt::format("RootF{}{}{}", axes[i], frame, b), "kN",
                     fmt::format("blade {} root force along {}_{} (blade on hub)", b, axes[i], frame), "blades"});
      for (int i = 0; i < 3; ++i)
        c.push_back({fmt::format("RootM{}{}{}", axes[i], frame, b), "kN-m",
                     fmt::format("blade {} root moment about {}_{} (blade on hub)", b, axes[i], frame), "blades"});
      for (int i = 0; i < 3; ++i)
        c.push_back({fmt::format("TipD{}{}{}", axes[i], frame, b), "m",
                     fmt::format("blade {} tip deflection along {}_{}", b, axes[i], frame), "blades"});
    }
    for (int i = 0; i < 3; ++i)
      c.push_back({fmt::format("TipRD{}b{}", axes[i], b), "deg",
                   fmt::format("blade {} tip rotation about {}_b (rotation vector)", b, axes[i]), "blades"});
    c.push_back({fmt::format("OoPDefl{}", b), "m", fmt::format("blade {} out-of-plane tip deflection (= TipDxc)", b), "blades"});
    c.push_back({fmt::format("IPDefl{}", b), "m", fmt::format("blade {} in-plane tip deflection (= TipDyc)", b), "blades"});
    c.push_back({fmt::format("TwstDefl{}", b), "deg", fmt::format("blade {} tip twist, + toward feather", b), "blades"});
    for (int i = 0; i < 3; ++i)
      c.push_back({fmt::format("B{}RootF{}r", b, axes[i]), "N", fmt::format("BeamDyn: blade {} root force, root frame", b), "blades"});
    for (int i = 0; i < 3; ++i)
      c.push_back({fmt::format("B{}RootM{}r", b, axes[i]), "N-m", fmt::format("BeamDyn: blade {} root moment, root frame", b), "blades"});
    for (int i = 0; i < 3; ++i)
      c.push_back({fmt::format("B{}TipTD{}r", b, axes[i]), "m", fmt::format("BeamDyn: blade {} tip deflection, root frame", b), "blades"});
    c.push_back({fmt::format("BldPitchAct{}", b), "deg", fmt::format("blade {} pitch after the actuator", b), "blades"});
    c.push_back({fmt::format("BldPitch{}", b), "deg",
                 fmt::format("blade {} pitch angle (ElastoDyn's BldPitch: the actuator's output, = BldPitchAct{})", b, b),
                 "blades"});
    if (nodal_deflections_) {
      const beam::BeamModel& model = rotor_.params().blade;
      for (int n = 0; n < model.node_count(); ++n)
        for (int i = 0; i < 3; ++i)
          c.push_back({fmt::format("B{}N{:03d}_TD{}r", b, n + 1, axes[i]), "m",
                       fmt::format("BeamDyn: blade {} node {} (eta {:.4f}) deflection along {}_r", b, n + 1,
                                   model.nodes[n].s_m / model.length_m, axes[i]),
                       "blades"});
    }
    for (std::size_t g = 0; g < gauges_eta_.size(); ++g) {
      for (int i = 0; i < 3; ++i)
        c.push_back({fmt::format("Spn{}FL{}b{}", g + 1, axes[i], b), "kN",
                     fmt::format("blade {} internal force at eta {} along the local {} axis (the section's twisted, deflected "
                                 "frame; outboard on inboard)", b, gauges_eta_[g], axes[i]),
                     "blades"});
      for (int i = 0; i < 3; ++i)
        c.push_back({fmt::format("Spn{}ML{}b{}", g + 1, axes[i], b), "kN-m",
                     fmt::format("blade {} internal moment at eta {} about the local {} axis (the section's frame)", b,
                                 gauges_eta_[g], axes[i]),
                     "blades"});
    }
  }
  c.push_back({"RotThrust", "kN", "low-speed shaft thrust (ElastoDyn's): the rotor's load on the shaft along it, "
                                  "the blades' root loads plus the hub's weight less its inertia", "blades"});
  c.push_back({"RotTorq", "kN-m", "low-speed shaft torque: blades' root torque less the hub's inertia", "blades"});
  c.push_back({"LSShftFxa", "kN", "= RotThrust", "blades"});
  c.push_back({"LSShftMxa", "kN-m", "= RotTorq", "blades"});
  return c;
}

void TurbineBlades::channel_values(const Data& d, std::span<double> out) const {
  std::size_t k = 0;
  const FlexibleRotorState& st = d.rotor.state;
  for (int b = 0; b < kBlades; ++b) {
    const beam::BeamOutputs o = rotor_.blade_outputs(b, st);
    const Vec6& root = o.root_load;
    // f = c R_z(−β): c-components are R_z(−β) times f-components.
    const Mat3 t_cf = rotation_matrix(Vec3(0.0, 0.0, -st.pitch_rad[b]));
    for (const Mat3& t : {t_cf, Mat3(Mat3::Identity())}) {
      const Vec3 f = t * root.head<3>(), m = t * root.tail<3>(), d = t * o.tip_displacement_m;
      for (int i = 0; i < 3; ++i) out[k++] = f[i] / 1e3;
      for (int i = 0; i < 3; ++i) out[k++] = m[i] / 1e3;
      for (int i = 0; i < 3; ++i) out[k++] = d[i];
    }
    const beam::BeamModel& model = rotor_.params().blade;
    const beam::BeamState& s = st.blades[b];
    const Vec3 tip_rotation = rotation_vector(s.orientation.back() * model.nodes.back().orientation.transpose());
    for (int i = 0; i < 3; ++i) out[k++] = tip_rotation[i] * kRadToDeg;
    const Vec3 d_c = t_cf * o.tip_displacement_m;
    out[k++] = d_c.x();
    out[k++] = d_c.y();
    out[k++] = -tip_rotation.z() * kRadToDeg;  // pitch toward feather turns f by −β about z
    for (int i = 0; i < 3; ++i) out[k++] = root[i];
    for (int i = 0; i < 3; ++i) out[k++] = root[3 + i];
    for (int i = 0; i < 3; ++i) out[k++] = o.tip_displacement_m[i];
    out[k++] = st.pitch_rad[b] * kRadToDeg;
    out[k++] = st.pitch_rad[b] * kRadToDeg;
    if (nodal_deflections_) {
      for (int n = 0; n < model.node_count(); ++n) {
        const Vec3 d = s.position_m[n] - model.nodes[n].position_m;
        for (int i = 0; i < 3; ++i) out[k++] = d[i];
      }
    }
    // ElastoDyn's Spn{k}FL/ML{x,y,z}b: in the local blade frame at the gauge — the section's own
    // frame, turned from b by the structural twist and the deflection (as the RR blades' gauges).
    for (const double eta : gauges_eta_) {
      const Vec6 load = beam::section_load_at(model, s, eta);
      const Mat3 local = beam::section_frame_at(model, s, eta);
      const Vec3 force = local.transpose() * load.head<3>(), moment = local.transpose() * load.tail<3>();
      for (int i = 0; i < 3; ++i) out[k++] = force[i] / 1e3;
      for (int i = 0; i < 3; ++i) out[k++] = moment[i] / 1e3;
    }
  }
  const FlexibleRotor::HubLoad& hub = d.rotor.last;
  const ShaftMotion& sh = d.rotor.shaft;
  const double hub_inertia_torque = rotor_.params().hub_inertia_kg_m2 *
                                    (st.spin.rotor_mean_acceleration_rad_s2 +
                                     sh.orientation.col(0).dot(sh.angular_acceleration_rad_s2));
  // ElastoDyn's LSShftFxa (= RotThrust) is the force the whole rotor puts on the shaft along x_s:
  // from the hub's equation of motion, m a = F_blades + m g − F_on_shaft, so the blades' root loads
  // plus the hub's weight less its inertia (m (g − a)), the hub CM on the shaft axis at HubCM.
  const Vec3 x_s = sh.orientation.col(0), arm = rotor_.params().hub_cm_m * x_s;
  const Vec3 hub_cm_acceleration = sh.apex_acceleration_m_s2 + sh.angular_acceleration_rad_s2.cross(arm) +
                                   sh.angular_velocity_rad_s.cross(sh.angular_velocity_rad_s.cross(arm));
  const Vec3 gravity(0.0, 0.0, -rotor_.params().gravity_m_s2);
  const double hub_weight_less_inertia = rotor_.params().hub_mass_kg * (gravity - hub_cm_acceleration).dot(x_s);
  const double thrust = (hub.force_h_N.x() + hub_weight_less_inertia) / 1e3;
  const double torque = (hub.moment_h_N_m.x() - hub_inertia_torque) / 1e3;
  out[k++] = thrust;
  out[k++] = torque;
  out[k++] = thrust;
  out[k++] = torque;
}

}  // namespace fowtsim::driver
