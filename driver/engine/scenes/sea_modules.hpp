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
#include "scenes/wave_excitation.hpp"

namespace fowtsim::driver {

class SeaModules {
 public:
  // Reads the deck's `waves`, `hydro` and `mooring` sections (each optional); `large_step_s` is the
  // platform's step (potential-flow radiation keeps its memory at it).
  SeaModules(const io::ValidatedDeck& deck, const FrameMotion& initial_pose, double large_step_s);

  // Hydro and mooring at `pose` and time t ∈ [t_n, t_n + ΔT]; the results stay until the next call.
  void evaluate(double t, const FrameMotion& pose);
  // Ends the step at t_n + ΔT = t with the platform at `pose`: the radiation memory moves on.
  void advance(double t, const FrameMotion& pose);
  // Total load on the platform about its reference point, inertial frame [N; N·m].
  Vec6 platform_load() const;
  // Hydro added mass about the reference point, inertial frame (zero without hydro).
  const Mat6& added_mass() const { return hydro_out_.added_mass; }

  // Wave-probe, hydro and mooring channels, in the order channel_values() fills them.
  std::vector<ChannelInfo> channels() const;
  void channel_values(double t, std::span<double> out) const;
  // Linearised 6×6 mooring stiffness at `pose` (analytic, about the reference point, inertial
  // axes; mooring/stiffness.hpp); zero without mooring.
  Mat6 mooring_stiffness(const FrameMotion& pose) const;
  // Inputs far outside sense, for the run summary: a sea steeper than the breaking limit.
  std::vector<std::string> warnings() const;
  // Random seeds in use (the wave seed, when there is a sea).
  std::vector<std::uint64_t> seeds() const;

  // What an evaluation leaves for the next one (the mooring solver's warm start): an output row
  // evaluates the sea between steps and restores this, so results do not depend on decimation.
  using Memory = mooring::QuasiStaticMooring::State;
  const Memory& memory() const { return mooring_state_; }
  void restore(const Memory& memory) { mooring_state_ = memory; }
  // The whole changing state (warm start and radiation memory), for checkpoints.
  template <class Archive>
  void checkpoint(Archive& a) {
    a.io(mooring_state_);
    hydro_state_.radiation.checkpoint(a);
  }

 private:
  waves::WaveParams wave_params_;
  bool has_waves_ = false;
  waves::Waves::Params sea_;
  std::optional<hydro::Params> hydro_;
  std::optional<mooring::MooringParams> mooring_;
  std::unique_ptr<waves::PrecomputedKinematics> kinematics_;
  std::unique_ptr<waves::PrecomputedKinematics> waterline_elevation_;  // wave_elevation surface only
  std::unique_ptr<WaveExcitation> excitation_;  // potential flow with excitation only
  hydro::Hydro::Input hydro_in_;
  hydro::Hydro::State hydro_state_;
  hydro::Hydro::Output hydro_out_;
  mooring::QuasiStaticMooring::State mooring_state_{};
  mooring::QuasiStaticMooring::Output mooring_out_{};
  std::size_t hydro_channel_count_ = 0;
  std::size_t channel_count_ = 0;
};

}  // namespace fowtsim::driver
