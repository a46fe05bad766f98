#pragma once
// Flexible MBBT blades on the floating turbine (issue 12): the deck's `blades:` section, and the
// glue between the rigid multibody (large step ΔT) and the fast side (FlexibleRotor: blades,
// their aerodynamics and the rotor spin at Δt = ΔT/n), seed 000 §4.4 and DESIGN.md §4.
//
// Per large step [T, T + ΔT]:
//  1. the multibody advances with the blades' root loads averaged over the previous large step,
//     held in the hub frame h and turned with the hub at every RK stage, and with the rotor spin
//     prescribed: extrapolated from the fast side's spin at T with its mean acceleration over the
//     previous large step (the multibody never integrates the spin: DESIGN.md §4);
//  2. the fast side takes n small steps through the shaft motion interpolated between T and
//     T + ΔT and returns its root loads averaged over the step (trapezoidal weights);
//  3. predictor_corrector: the multibody redoes the step from T with the new average and the
//     spin the fast side computed; single_rate: n = 1;
//  4. the multibody's spin is set to the fast side's at T + ΔT.
// Platform translation and tilt carry the light blades on a heavy body: staggered, as the seed.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "coupling/coupling_mode.hpp"
#include "fowtsim/core/channels.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/multibody/loads.hpp"
#include "fowtsim/multibody/model.hpp"
#include "scenes/blade_aero_map.hpp"
#include "scenes/flexible_rotor.hpp"

namespace fowtsim::driver {

io::Schema blades_schema();

class TurbineBlades {
 public:
  // The multibody parameters a deck with `blades` implies: blades out of the rotor body, the spin
  // prescribed (or held when the deck holds the rotor speed).
  static void configure(multibody::Params& structure);
  TurbineBlades(const TurbineBlades&) = delete;  // the aero map and the steppers refer to members
  TurbineBlades& operator=(const TurbineBlades&) = delete;

  TurbineBlades(const io::ValidatedDeck& deck, const multibody::Model& model, RotorAero* aero);

  CouplingMode mode() const { return mode_; }
  int substeps() const { return substeps_; }

  // Blades at t = 0 (static or undeformed, as the deck says) on the multibody's initial state.
  void start(const ShaftMotion& shaft, const multibody::State& state, double pitch_rad, const RotorDemands& demands);

  // At a Runge–Kutta stage of the multibody: the held root loads turned with the stage hub.
  void add_stage_loads(const multibody::ChainKinematics& chain, multibody::AppliedLoads& out) const;
  // The spin the multibody takes at time t (quadratic from the held profile).
  multibody::SpinMotion spin(double t) const;

  // Step 2 of the header: the fast side over [t, t + ΔT]. The new average root load waits in
  // hold_new_average(); the multibody keeps the old one until then.
  void advance_fast(double t, double dt_large, const ShaftMotion& begin, const ShaftMotion& end,
                    const RotorDemands& demands);
  void hold_new_average();
  // The spin the fast side took over the step starting at t (for the corrector pass).
  void use_step_spin_profile(double t);
  // Starts the next step's profile from the fast side's spin at t and its mean acceleration.
  void use_extrapolated_spin_profile(double t);
  // Writes the fast side's spin into the multibody state (step 4).
  void copy_spin(multibody::State& state) const;
  const ShaftMotion& shaft() const { return rotor_.shaft(); }

  std::vector<ChannelInfo> channels() const;
  void channel_values(std::span<double> out) const;
  std::string description() const;

 private:
  struct SpinProfile {
    double t0 = 0.0;
    multibody::SpinMotion at_t0;
  };
  const multibody::Model& model_;
  FlexibleRotorParams params_;
  std::optional<BladeAeroMap> map_;  // refers to params_.blade
  FlexibleRotor rotor_;
  CouplingMode mode_ = CouplingMode::multi_rate;
  int substeps_ = 4;
  FlexibleRotor::Start start_ = FlexibleRotor::Start::static_loads;
  std::vector<double> gauges_eta_;  // span gauges (arclength fractions)
  FlexibleRotor::HubLoad held_, held_next_;
  SpinState spin_before_;                         // fast spin at the start of the last step
  SpinProfile profile_;
  double mean_rotor_acceleration_ = 0.0, mean_generator_acceleration_ = 0.0;  // over the last large step
};

}  // namespace fowtsim::driver
