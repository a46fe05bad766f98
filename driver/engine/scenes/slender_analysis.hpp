#pragma once
// The slender-body analysis of a deck (modules/slender, seed 004): the model, its modes, the
// frequency-domain solution (drag linearised, mode acceleration) and the time-domain one (nonlinear
// Morison, stepped by scenes/slender_time_domain.hpp), each reduced to profiles along the body —
// amplitudes in a regular wave, RMS in a JONSWAP sea — so that the two can be set side by side (the
// seed's figures). The scene, the driver tests and `fowtsim verify slender` all run through here.
#include <optional>

#include "decks/slender_deck.hpp"
#include "fowtsim/slender/modes.hpp"
#include "fowtsim/slender/model.hpp"

namespace fowtsim::driver {

// Per strip (midpoints, bottom to top): amplitude (regular wave) or standard deviation (JONSWAP).
struct SlenderProfiles {
  VecX displacement_m;
  VecX moment_elastic_N_m;         // EI v'' (zero on rigid shapes)
  VecX moment_inertia_relief_N_m;  // the dynamic force balance above x
  VecX stress_elastic_Pa;          // moment / Z at the outer fibre
  VecX stress_inertia_relief_Pa;
};

// Frequency-domain response spectra in a JONSWAP sea, per strip (N × Nf) on the sea's grid.
struct SlenderSpectra {
  VecX omega_rad_s;
  MatX displacement_m2_s;           // S_v [m²·s/rad]
  MatX moment_inertia_relief_N2m2_s;  // S of the inertia-relief moment [N²·m²·s/rad]
};

struct SlenderResults {
  slender::Model model;
  slender::Modes modes;
  int drag_iterations = 0;                           // of the frequency domain's linearisation
  std::optional<SlenderProfiles> frequency_domain;
  std::optional<SlenderSpectra> spectra;             // frequency domain, JONSWAP sea
  std::optional<SlenderProfiles> time_domain;        // over [transient, t_max]
};

// The model, its modes and, if deck.analysis asks, the frequency domain (time_domain left empty).
SlenderResults solve_frequency_domain(const SlenderDeck& deck);

// Solves what deck.analysis asks; the time domain over [0, t_max_s] in steps of dt_s, from rest,
// stepped as the scene steps it (SlenderTimeDomain) without writing anything. Throws InputError
// (unlocated) when the transient leaves no whole wave period or no samples.
SlenderResults solve_slender(const SlenderDeck& deck, double dt_s, double t_max_s);

// Profiles with their stresses: moment / Z at the outer fibre, per strip.
SlenderProfiles profiles_with_stress(const slender::Model& model, VecX displacement_m, VecX moment_elastic_N_m,
                                     VecX moment_inertia_relief_N_m);

// max_i |other_i − reference_i| / max_i |reference_i|: how far two profiles along the body part,
// against the reference's peak (a profile's near-zero ends would make pointwise ratios meaningless).
double profile_difference(const VecX& reference, const VecX& other);

// The wave spectrum the deck's JONSWAP sea gives on its grid ω_j = (first + j)Δω, and first.
struct SeaGrid {
  double delta_omega_rad_s;
  int first_index;
  VecX omega_rad_s, spectrum_m2_s;
};
SeaGrid jonswap_grid(const SlenderSea& sea);

}  // namespace fowtsim::driver
