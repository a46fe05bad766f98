#pragma once
// The slender body's time domain as the engine steps it (modules/slender, seed 004): the module's
// RK4 step (time_stepping.hpp) on the deck's sea in blocks of half-step samples (wave_blocks.hpp),
// and the TD profiles along the body accumulated step by step over the window after the
// transient — a regular wave's first-harmonic amplitude over whole wave periods, a JONSWAP sea's
// standard deviation (statistics.hpp; the window as it always was: the last whole wave periods, or
// every sample, after analysis.transient_s). Nothing grows with the run: the scene, solve_slender
// and the checkpoints all hold one SlenderTimeState.
#include <array>

#include "decks/slender_deck.hpp"
#include "fowtsim/slender/statistics.hpp"
#include "fowtsim/slender/time_stepping.hpp"
#include "fowtsim/slender/wave_blocks.hpp"

namespace fowtsim::driver {

struct SlenderProfiles;  // slender_analysis.hpp

// The whole changing state of a slender time domain (plain, copyable; one field list below).
struct SlenderTimeState {
  slender::SlenderBody::State body;   // step index, a, ȧ
  slender::WaveBlock waves;           // the sea's samples; holds 2·step … 2·step + 2 between steps
  // Per strip, of the displacement, EI v'' and the inertia-relief moment (in that order), from the
  // window's first step to the current one: regular wave, JONSWAP sea (the other one left empty).
  std::array<slender::HarmonicSums, 3> harmonic;
  std::array<slender::DeviationSums, 3> deviation;
};

template <class Archive>
void fields(Archive& a, SlenderTimeState& s) {
  a.io(s.body, s.waves, s.harmonic, s.deviation);
}

class SlenderTimeDomain {
 public:
  // The time domain of `deck` over `steps` steps of dt_s from rest. Throws InputError (unlocated,
  // key analysis.transient_s) when the window after the transient keeps no whole wave period or
  // fewer than two samples.
  SlenderTimeDomain(const SlenderDeck& deck, const slender::Model& model, const slender::Modes& modes, double dt_s, long steps);

  SlenderTimeState make_state();              // at rest at t = 0, the sea's first block filled
  void step(SlenderTimeState& state);         // one step; adds its outputs to the window's statistics
  // The response at the state's time (workspace of this object, valid until the next call); the
  // state is only read.
  const slender::SlenderBody::Output& outputs(const SlenderTimeState& state);
  double wave_elevation_m(const SlenderTimeState& state) const;  // η at the body at the state's time
  // The TD profiles over the window; the state must have taken every step.
  SlenderProfiles profiles(const SlenderTimeState& state) const;
  long steps() const { return steps_; }

 private:
  void load_input(const SlenderTimeState& state, int columns);  // samples 2·step … into input_
  void accumulate(SlenderTimeState& state);

  SlenderSea sea_;
  double dt_s_;
  long steps_;
  long window_first_;                      // the statistics' first step
  slender::SlenderBody::Params params_;
  slender::WaveSource waves_;
  // Workspace (written before it is read; nothing in it crosses a call).
  slender::WaveBlockWorkspace wave_work_;
  slender::SlenderBody::Input input_;
  slender::SlenderBody::Workspace work_;
  slender::SlenderBody::Output output_;
};

}  // namespace fowtsim::driver
