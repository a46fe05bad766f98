#pragma once
// Parameters of the incident sea, one field per deck key of the `waves:` section (the driver's
// deck reader maps them one to one; README "Deck keys"). Units are in the key names (project
// rule). Inertial frame of DESIGN.md §3: origin at the still-water level on the undisplaced
// platform centre line, x downwind (waves heading 0° travel along +x), z up.
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fowtsim/waves/elevation_record.hpp"

namespace fowtsim::waves {

// `model:` still | regular | jonswap | pm | elevation_series
enum class WaveModel {
  still,              // no waves: calm water, every kinematic quantity zero
  regular,            // one Airy wave: height_m, period_s, phase_deg
  jonswap,            // irregular, JONSWAP spectrum (IEC 61400-3 form): hs_m, tp_s, gamma
  pierson_moskowitz,  // irregular, Pierson–Moskowitz spectrum (JONSWAP with γ = 1): hs_m, tp_s
  elevation_series,   // the sea rebuilt from a recorded η(0, 0, t) (OpenFAST SeaState WaveMod 5):
                      //   elevation_record (deck key `file`); duration_s, dt_s come from the record
};

// `stretching:` none | wheeler
enum class Stretching {
  none,     // linear field up to z = 0 whatever η is; zero above the still-water level (z > 0)
  wheeler,  // field at z' = h (z − η)/(h + η) for z ≤ η; zero above the instantaneous surface
};

// Most wave-elevation probes (Wave1Elev … Wave9Elev), as in OpenFAST (NWaveElev ≤ 9).
inline constexpr std::size_t kMaxElevationProbes = 9;

struct WaveParams {
  WaveModel model = WaveModel::still;  // `model`: which sea
  // Irregular seas (jonswap, pm).
  double hs_m = 0.0;                   // `hs_m`: significant wave height Hs = 4 √m0 [m], ≥ 0 (0 = calm)
  double tp_s = 0.0;                   // `tp_s`: spectral peak period Tp [s], > 0
  std::optional<double> gamma;         // `gamma`: JONSWAP peak-shape γ [-], ≥ 1; absent = IEC 61400-3
                                       //   default (default_peak_shape); pm: absent or 1
  bool rayleigh_amplitudes = false;    // `rayleigh_amplitudes`: amplitudes Rayleigh-random around the
                                       //   spectrum (HydroDyn WaveNDAmp = TRUE); false = deterministic
                                       //   amplitudes √(2 S Δω), random phases only
  std::uint64_t seed = 1;              // `seed`: random seed of phases (and amplitudes) [-]
  double duration_s = 3600.0;          // `duration_s`: record length D [s]; frequency spacing 1/D, the
                                       //   record repeats with period D (as HydroDyn's WaveTMax)
  double dt_s = 0.25;                  // `dt_s`: record time step [s]; D/dt must be a whole number;
                                       //   Nyquist frequency 1/(2 dt) bounds the spectrum
  // Irregular seas and elevation_series.
  double cutoff_low_hz = 0.0;          // `cutoff_low_hz`: components below are zeroed [Hz], ≥ 0
  std::optional<double> cutoff_high_hz;  // `cutoff_high_hz`: components above are zeroed [Hz];
                                       //   absent = Nyquist 1/(2 dt); above Nyquist is an error
  // Replayed sea (elevation_series).
  std::shared_ptr<const ElevationRecord> elevation_record;  // `file`: η(0, 0, t) as read by the driver
                                       //   (shared: parameters are copied, the record is not)
  // Regular waves.
  double height_m = 0.0;               // `height_m`: crest-to-trough height H [m], ≥ 0
  double period_s = 0.0;               // `period_s`: wave period T [s], > 0, ≥ 2 dt_s
  double phase_deg = 0.0;              // `phase_deg`: φ in η(0, 0, t) = H/2 cos(2π t/T + φ) [deg]
  // All models.
  double heading_deg = 0.0;            // `heading_deg`: propagation direction β, from +x towards +y [deg]
  double depth_m = std::numeric_limits<double>::infinity();  // `depth_m`: water depth h [m], > 0;
                                       //   .inf = deep water (seabed never reached)
  Stretching stretching = Stretching::none;  // `stretching`: kinematics above/near the surface
  double water_density_kg_m3 = 1025.0;  // `water_density_kg_m3`: ρ for the dynamic pressure [kg/m³]
  double gravity_m_s2 = 9.80665;        // `gravity_m_s2`: g in the dispersion relation [m/s²]
  std::vector<std::array<double, 2>> elevation_probes_m{{0.0, 0.0}};  // `elevation_probes_m`:
                                       //   (x, y) [m] of Wave1Elev, Wave2Elev, … (1 to 9 probes)
};

// `base` with model elevation_series and the record (time_s[j], elevation_m[j]) at x = y = 0; the
// other keys (heading, depth, stretching, cut-offs, …) are kept. The record is checked when the
// WaveField is built (or by validate).
WaveParams with_elevation_record(WaveParams base, std::span<const double> time_s, std::span<const double> elevation_m,
                                 std::string source = "elevation record");

// IEC 61400-3 (2009) Annex B default peak shape (as HydroDyn's WavePkShpDefault):
// γ = 5 for Tp/√Hs ≤ 3.6, exp(5.75 − 1.15 Tp/√Hs) for 3.6 < Tp/√Hs ≤ 5, 1 above (Tp in s, Hs in m).
// Hs = 0 gives 1.
double default_peak_shape(double hs_m, double tp_s);

// The peak shape in use: gamma if given, else the IEC default (jonswap); 1 for pm.
double peak_shape(const WaveParams& params);

// Checks every parameter the model uses and throws one InputError listing every problem
// (module "waves", variable = the deck keys concerned). Called by WaveField's constructor.
void validate(const WaveParams& params);

// Deck spellings: "still", "regular", "jonswap", "pm", "elevation_series"; "none", "wheeler". The parsers throw
// InputError naming the allowed values.
std::string_view to_string(WaveModel model);
std::string_view to_string(Stretching stretching);
WaveModel parse_wave_model(std::string_view text);
Stretching parse_stretching(std::string_view text);

}  // namespace fowtsim::waves
