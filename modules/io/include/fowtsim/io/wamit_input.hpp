#pragma once
// WAMIT first-order output files, read and made dimensional as HydroDyn does (issue 15: potential-
// flow hydrodynamics). WAMIT writes nondimensional coefficients (WAMIT v7 User Manual, §4.1–4.3);
// with ρ the water density, g gravity and L the length scale (HydroDyn's WAMITULEN), k = 3, 4 or 5
// when both, one or none of the modes i, j is a translation (1–3), and m = 2 for a force, 3 for a
// moment:
//   .1    PER  I  J  Ā_ij  B̄_ij       A_ij = Ā ρ L^k,  B_ij = B̄ ρ ω L^k   (PER = −1: infinite period,
//                                                                           ω = 0; PER = 0: zero period,
//                                                                           ω = ∞; A only)
//   .3    PER  β  I  |X̄|  arg X̄  Re X̄  Im X̄     X_i = X̄ ρ g L^m   per unit wave amplitude, β in deg
//   .hst  I  J  C̄_ij                  C_ij = C̄ ρ g L^(k−1)
// PER is the wave period [s] (ω = 2π/PER). Modes are 1–6 (surge, sway, heave, roll, pitch, yaw)
// about the WAMIT body origin; entries a file leaves out are zero.
#include <complex>
#include <filesystem>
#include <optional>
#include <vector>

#include "fowtsim/core/types.hpp"

namespace fowtsim::io {

using Vec6c = Eigen::Matrix<std::complex<double>, 6, 1>;  // complex amplitudes of the six modes

struct WamitScales {
  double water_density_kg_m3 = 1025.0;  // ρ
  double gravity_m_s2 = 9.80665;        // g
  double length_m = 1.0;                // L (WAMITULEN)
};

// Radiation coefficients of a .1 file, dimensional, frequencies ascending.
struct WamitRadiation {
  std::vector<double> frequencies_rad_s;  // finite, > 0
  std::vector<Mat6> added_mass;           // A(ω) [kg, kg·m, kg·m²]
  std::vector<Mat6> damping;              // B(ω) [N·s/m, N·s, N·m·s]
  std::optional<Mat6> added_mass_infinite_frequency;  // A(∞), from PER = 0
  std::optional<Mat6> added_mass_zero_frequency;      // A(0), from PER = −1
};

// First-order wave excitation of a .3 file per unit wave amplitude, dimensional: for each heading
// (ascending) and frequency (ascending) the six complex forces/moments [N/m, N·m/m].
struct WamitExcitation {
  std::vector<double> headings_deg;
  std::vector<double> frequencies_rad_s;
  std::vector<std::vector<Vec6c>> force;  // force[heading][frequency]
};

// Each reader throws InputError (module "io.wamit") naming file and line for a malformed line, a
// mode outside 1–6 or a non-positive scale, a last line without a line end (cut short), and for a
// table that is not complete: a .1 period or a .3 period and heading without the entries the first
// one has, a .3 heading without the frequencies of the first, a .hst without all 36 entries.
WamitRadiation read_wamit_radiation(const std::filesystem::path& wamit_1, const WamitScales& scales);
WamitExcitation read_wamit_excitation(const std::filesystem::path& wamit_3, const WamitScales& scales);
Mat6 read_wamit_hydrostatics(const std::filesystem::path& wamit_hst, const WamitScales& scales);

// The .1 and .3 files of one WAMIT run hold the same periods; a file cut at the end of a period
// block is complete in itself, and only this comparison finds it. Throws InputError naming both.
void check_same_frequencies(const WamitRadiation& radiation, const std::filesystem::path& wamit_1,
                            const WamitExcitation& excitation, const std::filesystem::path& wamit_3);

}  // namespace fowtsim::io
