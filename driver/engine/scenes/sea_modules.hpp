#pragma once
// The sea acting on a platform, as the scenes use it: waves (optional), hydro (optional) and
// mooring (optional), read from their deck sections, evaluated together at a platform pose and
// time. Wave kinematics (and, for hydro's wave_elevation surface, the elevation at each member's
// waterline) are precomputed once at the points of the initial pose (HydroDyn's default:
// kinematics at the undisplaced nodes), so an evaluation does no FFT, no summation over the
// components and no allocation.
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/core/interface.hpp"
#include "fowtsim/hydro/hydro.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/mooring/quasi_static_mooring.hpp"
#include "fowtsim/waves/waves_module.hpp"
#include "sea/wave_excitation.hpp"

namespace fowtsim::driver {

class SeaModules {
 public:
  // What changes during a run (a part of the scene state): the radiation memory and the mooring
  // solver's warm start; the last evaluation (hydro input and outputs, mooring outputs) is
  // workspace that every evaluate() writes before anything reads it.
  struct Data {
    hydro::Hydro::State hydro;                         // radiation memory (empty without potential flow)
    mooring::QuasiStaticMooring::State mooring{};      // each line's warm start
    hydro::Hydro::Input hydro_input;                   // workspace: pose and sea kinematics of the last evaluation
    hydro::Hydro::Output hydro_output;                 // workspace
    mooring::QuasiStaticMooring::Output mooring_output{};  // workspace
  };

  // Reads the deck's `waves`, `hydro` and `mooring` sections (each optional); `large_step_s` is the
  // platform's step (potential-flow radiation keeps its memory at it).
  SeaModules(const io::ValidatedDeck& deck, const FrameMotion& initial_pose, double large_step_s);
  // The data at the start of a run (at the initial pose).
  const Data& initial_data() const { return initial_; }

  // Hydro and mooring at `pose` and time t ∈ [t_n, t_n + ΔT]; the results stay in `d` until the next call.
  void evaluate(double t, const FrameMotion& pose, Data& d) const;
  // Ends the step at t_n + ΔT = t with the platform at `pose`: the radiation memory moves on.
  void advance(double t, const FrameMotion& pose, Data& d) const;
  // Total load on the platform about its reference point, inertial frame [N; N·m], of the last evaluation.
  Vec6 platform_load(const Data& d) const;
  // Hydro added mass about the reference point, inertial frame (zero without hydro).
  const Mat6& added_mass(const Data& d) const { return d.hydro_output.added_mass; }

  // Wave-probe, hydro and mooring channels, in the order channel_values() fills them.
  std::vector<ChannelInfo> channels() const;
  // platform_acceleration: [a_ref; α] in g, for the hydro channels' added-mass reaction.
  void channel_values(double t, const Data& d, const Vec6& platform_acceleration, std::span<double> out) const;
  // Linearised 6×6 mooring stiffness at `pose` (analytic, about the reference point, inertial
  // axes; mooring/stiffness.hpp); zero without mooring.
  Mat6 mooring_stiffness(const FrameMotion& pose) const;
  // Inputs far outside sense, for the run summary: a sea steeper than the breaking limit.
  std::vector<std::string> warnings() const;
  // The incident sea's parameters, or null in still water without a `waves` section.
  const waves::WaveParams* incident_waves() const { return has_waves_ ? &wave_params_ : nullptr; }
  // The incident sea's kinematics precomputed at fixed points of g (a line's undisplaced nodes, as
  // HydroDyn takes them at its members'); null in still water.
  std::unique_ptr<waves::PrecomputedKinematics> kinematics_at(std::span<const Vec3> points_m) const;
  // Random seeds in use (the wave seed, when there is a sea).
  std::vector<std::uint64_t> seeds() const;

 private:
  waves::WaveParams wave_params_;
  bool has_waves_ = false;
  waves::Waves::Params sea_;
  std::optional<hydro::Params> hydro_;
  std::optional<mooring::MooringParams> mooring_;
  std::unique_ptr<waves::PrecomputedKinematics> kinematics_;
  std::unique_ptr<waves::PrecomputedKinematics> waterline_elevation_;  // wave_elevation surface only
  std::unique_ptr<WaveExcitation> excitation_;  // potential flow with excitation only
  Data initial_;
  std::size_t hydro_channel_count_ = 0;
  std::size_t channel_count_ = 0;
};

// Field list of the sea's data (core/fields.hpp).
template <class Archive>
void fields(Archive& a, SeaModules::Data& d) {
  a.io(d.hydro, d.mooring);
  a.scratch(d.hydro_input, d.hydro_output, d.mooring_output);
}

}  // namespace fowtsim::driver
