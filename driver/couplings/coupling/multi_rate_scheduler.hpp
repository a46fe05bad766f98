#pragma once
// The glue code of the coupled scheme (seed 000 §4.4, DESIGN.md §4), written once for every
// scene: a slow subsystem advanced at the large step ΔT and a fast subsystem (or a group of fast
// bodies) advanced at Δt = ΔT/n in the floating frame of its attachment. Weak coupling, no
// iteration. Per large step [T, T + ΔT]:
//   1. the slow subsystem advances with the fast root loads averaged over the previous large
//      step, held over this one (zero-order hold);
//   2. the fast subsystem takes n small steps through the slow attachment motion, interpolated
//      between T and T + ΔT, and its root loads are averaged over the large step: the time average
//      of the piecewise-linear load history through the n + 1 samples (trapezoidal weights
//      ½, 1, …, 1, ½). A plain mean of the n end-of-substep samples would be biased by Δt/2·dF/dt
//      and cap every mode at first order (measured, coupling_tests.cpp);
//   3. predictor_corrector: the slow step is redone once from T with the new average;
//      single_rate: n = 1.
// The toy oscillators (`MultiRateScheduler`, verified against their exact solution) and the
// floating turbine with flexible blades (scenes/turbine_blades.cpp) both run `multi_rate_step`,
// so the toy's verification covers the turbine's exchange.
// The modules check their own state inside advance (NumericalError names module and variable).
#include <concepts>
#include <optional>

#include "coupling/coupling_mode.hpp"
#include "fowtsim/core/interface.hpp"
#include "fowtsim/core/module.hpp"

namespace fowtsim::driver {

enum class SlowPass { predictor, corrector };

// The slow attachment motion over one large step, as small step i of n sees it.
template <class Motion>
struct SubstepMotion {
  const Motion& begin;  // at T
  const Motion& end;    // at T + ΔT
  int i = 0, n = 1;
  // At fraction x ∈ [0, 1] of small step i, i.e. (i + x)/n of the large step.
  Motion at(double x) const { return interpolate(begin, end, (i + x) / n); }
};

// What a coupled pair gives the scheduler. `Load` averages as a vector (LoadAverager).
template <class C>
concept MultiRateCoupling =
    requires(C& c, const C& cc, double t, double dt, const typename C::Load& load,
             const SubstepMotion<typename C::Motion>& motion, const typename C::SlowState& saved) {
      { c.slow_state() } -> std::convertible_to<typename C::SlowState>;  // copied for the corrector
      c.restore_slow_state(saved);
      { c.motion_at_step_start() } -> std::convertible_to<typename C::Motion>;
      c.advance_slow(t, dt, SlowPass::predictor);  // with the held loads
      { c.slow_motion(t) } -> std::convertible_to<typename C::Motion>;  // after advance_slow to t
      c.advance_fast(t, dt, motion);               // one small step
      { cc.root_loads() } -> std::convertible_to<typename C::Load>;  // of the fast side now
      c.hold(load, dt);                            // the average over the large step dt
      c.finish_large_step();
    };

// Advances a coupled pair by one large step from t (steps 1–3 of the header).
template <MultiRateCoupling C>
void multi_rate_step(C& c, const CouplingSettings& settings, double t) {
  const double dt_large = settings.dt_coupling_s;
  const int n = settings.substeps;
  const double dt_small = dt_large / n;
  const typename C::Motion begin = c.motion_at_step_start();
  std::optional<typename C::SlowState> before;
  if (settings.mode == CouplingMode::predictor_corrector) before.emplace(c.slow_state());

  c.advance_slow(t, dt_large, SlowPass::predictor);
  const typename C::Motion end = c.slow_motion(t + dt_large);
  LoadAverager<typename C::Load> averager;
  averager.add(c.root_loads(), 0.5);
  for (int i = 0; i < n; ++i) {
    c.advance_fast(t + i * dt_small, dt_small, SubstepMotion<typename C::Motion>{begin, end, i, n});
    averager.add(c.root_loads(), i + 1 < n ? 1.0 : 0.5);
  }
  c.hold(averager.average(), dt_large);  // held over the next large step

  if (before) {
    c.restore_slow_state(*before);
    c.advance_slow(t, dt_large, SlowPass::corrector);
  }
  c.finish_large_step();
}

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

// Two modules of the module contract coupled by multi_rate_step (the toy oscillators).
template <SlowSubsystem Slow, FastSubsystem Fast>
class ModulePair {
 public:
  using Motion = FrameMotion;
  using Load = RootLoads;
  using SlowState = typename Slow::State;
  // Everything of the pair that changes: plain, copyable, with its field list (core/fields.hpp).
  struct State {
    typename Slow::State slow;
    typename Fast::State fast;
    typename Slow::Input slow_input{};  // the fast loads held over the large step
    typename Fast::Input fast_input{};  // the frame motion of the last small step
    RootLoads root_loads;               // fast root loads at the current time (first sample of a step)
    long large_steps = 0;               // taken so far (MultiRateScheduler counts them)
    template <class Archive>
    friend void fields(Archive& a, State& s) {
      a.io(s.slow, s.fast, s.slow_input, s.fast_input, s.root_loads, s.large_steps);
    }
  };

  ModulePair(const typename Slow::Params& slow_params, const typename Fast::Params& fast_params)
      : slow_params_(slow_params), fast_params_(fast_params) {
    s_.slow = Slow::make_state(slow_params);
    s_.fast = Fast::make_state(fast_params);
    // Initial loads: the fast subsystem's root loads at t = 0 on a frame at rest where the slow
    // subsystem starts (no history to average yet).
    const FrameMotion start = motion_at_step_start();
    s_.fast_input.frame_begin = start;
    s_.fast_input.frame_end = start;
    s_.root_loads = Fast::outputs(fast_params_, s_.fast_input, s_.fast).root_loads;
    s_.slow_input.interface_loads = s_.root_loads;
  }

  const SlowState& slow_state() const { return s_.slow; }
  void restore_slow_state(const SlowState& saved) { s_.slow = saved; }
  FrameMotion motion_at_step_start() const { return slow_output().attachment; }
  void advance_slow(double t, double dt, SlowPass) { Slow::advance(slow_params_, s_.slow_input, t, dt, s_.slow); }
  FrameMotion slow_motion(double) const { return slow_output().attachment; }
  void advance_fast(double t, double dt, const SubstepMotion<FrameMotion>& slow) {
    s_.fast_input.frame_begin = slow.i == 0 ? slow.begin : s_.fast_input.frame_end;
    s_.fast_input.frame_end = slow.at(1.0);
    Fast::advance(fast_params_, s_.fast_input, t, dt, s_.fast);
    s_.root_loads = Fast::outputs(fast_params_, s_.fast_input, s_.fast).root_loads;
  }
  const RootLoads& root_loads() const { return s_.root_loads; }
  void hold(const RootLoads& average, double) { s_.slow_input.interface_loads = average; }
  void finish_large_step() { ++s_.large_steps; }

  State& state() { return s_; }
  const State& state() const { return s_; }
  // Outputs at the current time; the slow side reports the loads it will apply next.
  typename Slow::Output slow_output() const { return Slow::outputs(slow_params_, s_.slow_input, s_.slow); }
  typename Fast::Output fast_output() const { return Fast::outputs(fast_params_, s_.fast_input, s_.fast); }

 private:
  typename Slow::Params slow_params_;  // copied once: never refers to a caller's object
  typename Fast::Params fast_params_;
  State s_;
};

// A module pair and its coupling settings.
template <SlowSubsystem Slow, FastSubsystem Fast>
class MultiRateScheduler {
 public:
  using State = typename ModulePair<Slow, Fast>::State;
  MultiRateScheduler(const typename Slow::Params& slow_params, const typename Fast::Params& fast_params,
                     const CouplingSettings& settings)
      : settings_(validated(settings)), pair_(slow_params, fast_params) {}

  // Advances both subsystems by one large step ΔT.
  void step() { multi_rate_step(pair_, settings_, time_s()); }

  double time_s() const { return static_cast<double>(pair_.state().large_steps) * settings_.dt_coupling_s; }
  long large_step() const { return pair_.state().large_steps; }
  const CouplingSettings& settings() const { return settings_; }
  // The whole changing state (checkpoints).
  State& state() { return pair_.state(); }
  const typename Slow::State& slow_state() const { return pair_.state().slow; }
  const typename Fast::State& fast_state() const { return pair_.state().fast; }
  typename Slow::Output slow_output() const { return pair_.slow_output(); }
  typename Fast::Output fast_output() const { return pair_.fast_output(); }

 private:
  static const CouplingSettings& validated(const CouplingSettings& settings) {
    validate(settings);
    return settings;
  }
  CouplingSettings settings_;
  ModulePair<Slow, Fast> pair_;
};

}  // namespace fowtsim::driver
