#pragma once
// The sea and wind of a frequency-domain screening (scenes/floating_screening.hpp), from a floating
// turbine deck: the one-sided wave-elevation spectrum of its `waves` section, the rotor-effective
// longitudinal wind spectrum of its `wind` section's IEC Kaimal turbulence, the platform's
// first-order wave excitation (WAMIT's .3 table, or Morison's inertia and dynamic pressure on the
// strips), WAMIT's frequency-dependent radiation, and the members' drag linearised stochastically.
#include <complex>
#include <filesystem>
#include <optional>
#include <vector>

#include "fowtsim/core/types.hpp"
#include "fowtsim/hydro/params.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/io/wamit_input.hpp"
#include "fowtsim/waves/wave_params.hpp"
#include "fowtsim/wind/params.hpp"

namespace fowtsim::driver {

using io::Vec6c;

// One-sided wave-elevation spectrum S_ζ(f) [m²/Hz] of the waves section: JONSWAP (γ from the deck
// or IEC 61400-3's default), Pierson–Moskowitz, or calm (still water, Hs = 0). InputError for the
// other models (regular, replayed), which have no spectrum.
class WaveSpectrum {
 public:
  explicit WaveSpectrum(const waves::WaveParams& waves);
  double at_hz(double f_hz) const;

 private:
  waves::WaveParams waves_;
  double gamma_ = 1.0, normalisation_ = 1.0;  // JONSWAP γ and C(γ), computed once
};

// The rotor-effective longitudinal wind: one-sided S_Ueff(f) = S_u(f) · (1/A²) ∬ Coh(|r₁ − r₂|, f) dA dA
// over the rotor disk [m²/s² per Hz], with the IEC 61400-1 Annex B Kaimal u spectrum and exponential
// coherence (Coh = exp(−12 √((f r/V)² + (0.12 r/L_c)²))), the disk area-weighted. Precomputes the
// pair distances of a polar grid once (a histogram of them), so each frequency costs a few dozen
// exponentials.
class RotorEffectiveWind {
 public:
  // No turbulence (a steady, power-law or log wind; a .bts file has no spectrum we can know): zero.
  RotorEffectiveWind(const wind::WindParams& wind, double hub_height_m, double rotor_radius_m);
  double spectrum_hz(double f_hz) const;
  double sigma_u_m_s() const { return sigma_u_; }  // σ₁ of the point spectrum (0 without turbulence)
  bool turbulent() const { return turbulent_; }

 private:
  bool turbulent_ = false;
  double sigma_u_ = 0.0, length_u_m_ = 1.0, speed_m_s_ = 1.0, coherence_scale_m_ = 1.0;
  std::vector<double> distance_m_, weight_;  // pair distances (bin centres) and their area weights (sum 1)
};

// A Morison strip of the platform's members at rest, in g about the platform reference point.
struct PlatformStrip {
  Vec3 centre_m = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();       // unit, A → B
  double length_m = 0.0;
  double diameter_m = 0.0;
  double cd = 0.0, ca = 0.0;
  double area_slope_m = 0.0;       // dA/dl of the cross-section along the axis [m²/m]
};
// Axial end plates below the surface (dynamic pressure on them, as the hydro module's end effects).
struct PlatformEnd {
  Vec3 centre_m = Vec3::Zero();
  Vec3 outward = Vec3::UnitZ();    // unit normal out of the member
  double area_m2 = 0.0;
  double cp = 1.0;
};
struct PlatformStrips {
  std::vector<PlatformStrip> strips;
  std::vector<PlatformEnd> ends;
};
// The strips of the hydro parameters' members below z = 0 (the member's `strips` count over its
// submerged length), at the platform's initial pose (excitation at the initial position, as
// HydroDyn's ExctnDisp 0).
PlatformStrips platform_strips(const hydro::Params& hydro);

// Linear first-order wave excitation [F; M] per unit amplitude of the elevation Re[e^{iωt}] at the
// origin, heading β: Morison's inertia ρ (1 + C_a) A a_n on every strip and the dynamic pressure on
// the end plates and tapers (the Froude–Krylov part along the axes). Airy kinematics at depth h.
Vec6c morison_excitation(const PlatformStrips& s, const hydro::Params& hydro, double omega_rad_s, double heading_rad, double depth_m);

// The undisturbed wave particle velocity normal to each strip's axis per unit amplitude (g).
std::vector<Eigen::Vector3cd> strip_wave_velocity(const PlatformStrips& s, double omega_rad_s, double heading_rad, double depth_m,
                                                 double gravity_m_s2);

// WAMIT's radiation coefficients A(ω) − A(∞) and B(ω) interpolated linearly in ω (zero outside the
// table: the radiation memory's kernel integrates B only over its frequencies too).
struct RadiationCoefficients {
  io::WamitRadiation table;
  Mat6 added_mass_infinite = Mat6::Zero();
  void at(double omega_rad_s, Mat6& added_mass_minus_infinite, Mat6& damping) const;
};
// The hydro section's WAMIT files (potential_flow.wamit_root), or none without potential flow.
std::optional<RadiationCoefficients> radiation_coefficients(const io::ValidatedDeck& hydro_section, const hydro::Params& hydro);

// WAMIT's first-order excitation table (ROOT.3) when the deck as written has potential-flow
// excitation on (hydro_section: the source deck's; the screening's own linearisation deck turns
// it off so that its scene does not read the file again), else none.
std::optional<io::WamitExcitation> wamit_excitation(const io::ValidatedDeck& hydro_section, const hydro::Params& hydro);

}  // namespace fowtsim::driver
