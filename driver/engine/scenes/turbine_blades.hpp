#pragma once
// Flexible MBBT blades on the floating turbine (issue 12): the deck's `blades:` section, and the
// glue between the rigid multibody (large step ΔT) and the fast side (FlexibleRotor: blades,
// their aerodynamics and the rotor spin at Δt = ΔT/n), seed 000 §4.4 and DESIGN.md §4.
//
// Per large step [T, T + ΔT], the one multi-rate exchange (coupling/multi_rate_scheduler.hpp):
//  1. the multibody advances with the blades' root loads held from the previous large step, in
//     the hub frame h and turned with the hub at every RK stage (less the blades' weight, which
//     each stage adds at its own orientation: below), and with the rotor spin
//     prescribed: extrapolated from the fast side's spin at T with its mean acceleration over the
//     previous large step (the multibody never integrates the spin: DESIGN.md §4). With the
//     interface mass (below) the held part is only the remainder R and the rotor's apparent mass
//     M_h is in the multibody's equations: root load = R − M_h [a_apex; α_s];
//  2. the fast side takes n small steps through the shaft motion interpolated between T and
//     T + ΔT; the scheduler averages its root loads over the step (trapezoidal weights);
//  3. predictor_corrector: the multibody redoes the step from T with the new average and the
//     spin the fast side computed; single_rate: n = 1;
//  4. the multibody's spin is set to the fast side's at T + ΔT.
// Platform translation and tilt carry the light blades on a heavy body: staggered, as the seed.
//
// Interface mass (issue 24; `blades.interface_mass`, on with the flexible tower). Exchanging the
// whole root load explicitly is an added-mass partition: its inertial part −M a lags a large step,
// which is unstable when the blades are heavy against what they hang on at the frequency that
// matters (the flexible tower's top at its second modes: modules/multibody/README.md). The rotor's
// load on the shaft is affine in the shaft's acceleration over a step, F ≈ F_0 − M_h [a_apex; α_s]
// (FlexibleRotor::apparent_mass_h: each blade's linearised generalized-α step — their dynamic
// stiffness at the time scale of the large step, rigid where their modes are fast against ΔT,
// light where they are slow — with the free spin condensed out). The multibody takes M_h on its
// left-hand side at every stage (multibody::AppliedLoads::rotor_added_mass) and holds only the
// remainder R = F(T) + M_h a(T), taken at the step's end (not averaged: R no longer follows the
// shaft's acceleration, and the sample lags half as much as the average; with the average the
// 1000×-stiff blades' roll–drivetrain oscillation at 4.2 Hz grew, with the sample it decays).
// A blade's share of M_h is refreshed after a large step in which its step matrix was rebuilt (the
// same ageing: its deflection and spin; the first large step builds them all and is exchanged as
// before), then the spin is condensed out of their sum again.
//
// The blades' weight is not held. Turned with the hub, a held load keeps its direction in the
// rotating frame, which is right for what turns with the blades (aerodynamics, centrifugal and
// elastic loads) but turns their weight with the hub by Ω times the sample's age: the held average
// lags a whole large step, so the 522 kN of the NREL 5MW blades pushed sideways by ΩΔT = 1.5° at
// ΔT = 20 ms (measured: the seed's validation deck, no wind, rotor held at 12.1 rpm — TwrBsMxt's
// mean −1128 / −572 / −294 kN·m at ΔT = 20 / 10 / 5 ms, first order in ΔT; −16 at all three now). The
// held load is the root load less the weight of the undeflected blades (mass and first moment,
// pitched) at its sample's hub orientation, and every stage adds that weight at its own
// orientation; the deflection's share of the weight's moment is left in the held part (second order:
// the deflection times the lag).
#include <array>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "coupling/coupling_mode.hpp"
#include "fowtsim/core/channels.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/multibody/loads.hpp"
#include "fowtsim/multibody/model.hpp"
#include "rotor/blade_aero_map.hpp"
#include "rotor/flexible_rotor.hpp"

namespace fowtsim::driver {

io::Schema blades_schema();

class TurbineBlades {
 public:
  // The multibody parameters a deck with `blades` implies: blades out of the rotor body, the spin
  // prescribed (or held when the deck holds the rotor speed).
  static void configure(multibody::Params& structure);
  TurbineBlades(const TurbineBlades&) = delete;  // the aero map and the steppers refer to members
  TurbineBlades& operator=(const TurbineBlades&) = delete;

  TurbineBlades(const io::ValidatedDeck& deck, const multibody::Model& model, const RotorAero* aero);

  // Whether the multibody takes the blades' apparent mass (interface mass, header).
  bool interface_mass() const { return interface_mass_; }

  // The spin the multibody takes over a large step: quadratic from (t0, at_t0).
  struct SpinProfile {
    double t0 = 0.0;
    multibody::SpinMotion at_t0;
  };
  // What changes (a part of the scene state): the fast side, the root loads held over the large
  // step and the spin handed to the multibody.
  struct Data {
    FlexibleRotor::Data rotor;
    FlexibleRotor::HubLoad held;    // root loads less the blades' weight, averaged over the last large step (with
                                    // the interface mass: the remainder R at its end), hub frame h, force at /
                                    // moment about the apex
    std::array<Mat6, kBlades> blade_apparent_mass_h{};  // each blade's share of M_b (spin held), h, apex
    Mat6 apparent_mass_h = Mat6::Zero();  // M_h: the rotor's apparent mass on the shaft at the apex in h, the
                                          // spin condensed out (zero without the interface mass) [kg, kg·m, kg·m²]
    SpinState spin_before;          // fast spin at the start of the last large step
    SpinProfile profile;
    double mean_rotor_acceleration_rad_s2 = 0.0;      // over the last large step
    double mean_generator_acceleration_rad_s2 = 0.0;
  };
  Data make_data() const {
    Data d{rotor_.make_data(), {}, {}, Mat6::Zero(), {}, {}, 0.0, 0.0};
    for (Mat6& m : d.blade_apparent_mass_h) m.setZero();
    return d;
  }

  CouplingMode mode() const { return mode_; }
  int substeps() const { return substeps_; }

  // Blades at t = 0 (static or undeformed, as the deck says) on the multibody's initial state.
  void start(const ShaftMotion& shaft, const multibody::State& state, double pitch_rad, const RotorDemands& demands,
             Data& d, RotorAero::Data* aero);

  // At a Runge–Kutta stage of the multibody: the held root loads turned with the stage hub (and the
  // blades' apparent mass, turned likewise).
  void add_stage_loads(const multibody::ChainKinematics& chain, const Data& d, multibody::AppliedLoads& out) const;
  // The spin the multibody takes at time t (quadratic from the held profile).
  multibody::SpinMotion spin(double t, const Data& d) const;

  // One large step, steps 1–4 of the header (multi_rate_step). `provider` must apply
  // add_stage_loads() and answer rotor_spin() with spin() of `d`; `shaft_at(t, state)` gives the
  // shaft motion of a multibody state under the provider's loads.
  using ShaftAt = std::function<ShaftMotion(double t, const multibody::State& state)>;
  void advance(multibody::LoadProvider& provider, const ShaftAt& shaft_at, const RotorDemands& demands, double t,
               double dt_large, multibody::State& state, Data& d, RotorAero::Data* aero);

  const FlexibleRotor& rotor() const { return rotor_; }
  // The HSS brake on the blades' spin (the scene's stick and slip, floating_scene.hpp): the torque
  // the lock took in the last small step (LSS, SpinState::lock_torque_N_m), and a stop — the
  // generator (with a rigid shaft the rotor too) at rest, its accelerations zero — copied to `state`.
  static double lock_torque_N_m(const Data& d) { return d.rotor.state.spin.lock_torque_N_m; }
  void stop_spin(Data& d, multibody::State& state) const;

  std::vector<ChannelInfo> channels() const;
  void channel_values(const Data& d, std::span<double> out) const;
  std::string description() const;

 private:
  class Coupling;  // this turbine as a MultiRateCoupling
  // M_h after the large step of dt_large: the shares of the blades whose step matrix was rebuilt in it.
  void refresh_apparent_mass(Data& d, const RotorDemands& demands, double dt_large);
  static void use_step_spin_profile(double t, Data& d);          // the spin the blades took over the step from t
  void use_extrapolated_spin_profile(double t, Data& d) const;  // from the blades' spin at t, last step's mean acceleration
  static void copy_spin(const Data& d, multibody::State& state);
  // The undeflected blades' weight on the hub at the fast side's state (hub frame at its azimuth,
  // its pitch): force at the apex and moment about it, in h, under the structure's gravity (the
  // scene's demands always carry gravity; the blades' own steps take the same value).
  FlexibleRotor::HubLoad blade_weight_h(const FlexibleRotor::Data& r) const;
  // Σ over the blades of their first mass moment about the apex, in h, at pitch `pitch_rad` [kg·m].
  Vec3 first_moment_h(const std::array<double, kBlades>& pitch_rad) const;
  // The shaft's acceleration the blades see now, [a_apex; α_s] in h.
  static Vec6 shaft_acceleration_h(const Data& d);

  const multibody::Model& model_;
  FlexibleRotorParams params_;
  std::optional<BladeAeroMap> map_;  // refers to params_.blade
  FlexibleRotor rotor_;
  CouplingMode mode_ = CouplingMode::multi_rate;
  int substeps_ = 4;
  FlexibleRotor::Start start_ = FlexibleRotor::Start::static_loads;
  std::vector<double> gauges_eta_;  // span gauges (arclength fractions)
  bool nodal_deflections_ = false;  // B<b>N<nnn>_TD{x,y,z}r channels
  bool interface_mass_ = false;     // the multibody takes the blades' apparent mass (header)
  double blade_mass_kg_ = 0.0;      // one undeflected blade: mass [kg]
  Vec3 blade_first_moment_f_ = Vec3::Zero();  // and first mass moment about its root, in f [kg·m]
};

// Field lists (core/fields.hpp).
template <class Archive>
void fields(Archive& a, TurbineBlades::SpinProfile& p) {
  a.io(p.t0, p.at_t0);
}
template <class Archive>
void fields(Archive& a, TurbineBlades::Data& d) {
  a.io(d.rotor, d.held, d.blade_apparent_mass_h, d.apparent_mass_h, d.spin_before, d.profile, d.mean_rotor_acceleration_rad_s2,
       d.mean_generator_acceleration_rad_s2);
}

}  // namespace fowtsim::driver
