#pragma once
// The glue code of the coupled scheme (seed 000 §4.4, DESIGN.md §4): a slow subsystem advanced
// at the large step ΔT and a fast subsystem advanced at Δt = ΔT/n in the floating frame of its
// attachment point. Weak coupling, no iteration:
//   1. the slow subsystem advances over [T, T+ΔT] with the fast root loads averaged over the
//      previous large step, applied at the averaged root position (zero-order hold);
//   2. the fast subsystem takes n small steps through the slow attachment motion, linearly
//      interpolated between T and T+ΔT, and its root loads are averaged over the large step:
//      the time average of the piecewise-linear load history through the n+1 samples
//      (trapezoidal weights ½, 1, …, 1, ½). A plain mean of the n end-of-substep samples would
//      be biased by Δt/2·dF/dt and cap every mode at first order (measured);
//   predictor_corrector: then the slow step is redone once from T with the new average.
// The modules check their own state inside advance (NumericalError names module and variable).
#include <concepts>

#include "coupling/coupling_mode.hpp"
#include "fowtsim/core/interface.hpp"
#include "fowtsim/core/module.hpp"

namespace fowtsim::driver {

// A slow subsystem takes interface loads and reports the motion of the attachment point.
template <class S>
concept SlowSubsystem = Module<S> && requires(typename S::Input u, typename S::Output y) {
  { u.interface_loads } -> std::convertible_to<RootLoads>;
  { y.attachment } -> std::convertible_to<FrameMotion>;
};

// A fast subsystem takes the frame motion at both ends of its step and reports root loads.
template <class F>
concept FastSubsystem = Module<F> && requires(typename F::Input u, typename F::Output y) {
  { u.frame_begin } -> std::convertible_to<FrameMotion>;
  { u.frame_end } -> std::convertible_to<FrameMotion>;
  { y.root_loads } -> std::convertible_to<RootLoads>;
};

template <SlowSubsystem Slow, FastSubsystem Fast>
class MultiRateScheduler {
 public:
  MultiRateScheduler(const typename Slow::Params& slow_params, const typename Fast::Params& fast_params,
                     const CouplingSettings& settings)
      : slow_params_(slow_params),
        fast_params_(fast_params),
        settings_(settings),
        slow_(Slow::make_state(slow_params)),
        fast_(Fast::make_state(fast_params)) {
    validate(settings_);
    // Initial loads: the fast subsystem's root loads at t = 0 on a frame at rest where the slow
    // subsystem starts (no history to average yet).
    slow_input_.interface_loads = RootLoads{};
    const FrameMotion start = Slow::outputs(slow_params_, slow_input_, slow_).attachment;
    fast_input_.frame_begin = start;
    fast_input_.frame_end = start;
    last_root_loads_ = Fast::outputs(fast_params_, fast_input_, fast_).root_loads;
    slow_input_.interface_loads = last_root_loads_;
  }

  // Advances both subsystems by one large step ΔT.
  void step() {
    const double t = time_s();
    const double dt_large = settings_.dt_coupling_s;
    const FrameMotion motion_begin = Slow::outputs(slow_params_, slow_input_, slow_).attachment;
    if (settings_.mode == CouplingMode::predictor_corrector) slow_before_step_ = slow_;

    Slow::advance(slow_params_, slow_input_, t, dt_large, slow_);
    const FrameMotion motion_end = Slow::outputs(slow_params_, slow_input_, slow_).attachment;
    const RootLoads average = advance_fast(t, motion_begin, motion_end);

    if (settings_.mode == CouplingMode::predictor_corrector) {
      slow_ = slow_before_step_;
      slow_input_.interface_loads = average;
      Slow::advance(slow_params_, slow_input_, t, dt_large, slow_);
    }
    slow_input_.interface_loads = average;  // held over the next large step
    ++large_step_;
  }

  double time_s() const { return static_cast<double>(large_step_) * settings_.dt_coupling_s; }
  long large_step() const { return large_step_; }
  const CouplingSettings& settings() const { return settings_; }
  const typename Slow::State& slow_state() const { return slow_; }
  const typename Fast::State& fast_state() const { return fast_; }
  // Outputs at the current time; the slow side reports the loads it will apply next.
  typename Slow::Output slow_output() const { return Slow::outputs(slow_params_, slow_input_, slow_); }
  typename Fast::Output fast_output() const { return Fast::outputs(fast_params_, fast_input_, fast_); }

 private:
  // n small steps of the fast subsystem through the interpolated frame motion; returns the
  // root loads averaged over the small steps (seed 000 §4.4.2).
  RootLoads advance_fast(double t, const FrameMotion& begin, const FrameMotion& end) {
    const int n = settings_.substeps;
    const double dt_small = settings_.dt_coupling_s / n;
    averager_.reset();
    averager_.add(last_root_loads_, 0.5);
    fast_input_.frame_end = begin;
    for (int i = 0; i < n; ++i) {
      fast_input_.frame_begin = fast_input_.frame_end;
      fast_input_.frame_end = interpolate(begin, end, static_cast<double>(i + 1) / n);
      Fast::advance(fast_params_, fast_input_, t + i * dt_small, dt_small, fast_);
      last_root_loads_ = Fast::outputs(fast_params_, fast_input_, fast_).root_loads;
      averager_.add(last_root_loads_, i + 1 < n ? 1.0 : 0.5);
    }
    return averager_.average();
  }

  typename Slow::Params slow_params_;  // copied once: the scheduler never refers to a caller's object
  typename Fast::Params fast_params_;
  CouplingSettings settings_;
  typename Slow::State slow_;
  typename Slow::State slow_before_step_;  // predictor-corrector rollback point
  typename Fast::State fast_;
  typename Slow::Input slow_input_{};
  typename Fast::Input fast_input_{};
  RootLoadAverager averager_;
  RootLoads last_root_loads_;  // fast root loads at the current time (first sample of a step)
  long large_step_ = 0;
};

}  // namespace fowtsim::driver
