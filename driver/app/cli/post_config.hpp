#pragma once
// The YAML files of `fowtsim post`: the fatigue configuration (--del-config) and the lifetime
// specification (--lifetime), validated with file:line errors like the decks (DESIGN.md §5).
//
// Fatigue configuration — per channel Wöhler exponent, optional ultimate load (Goodman on), the fixed
// mean of the Goodman correction; `default` applies to every channel not listed:
//
//   equivalent_frequency_hz: 1.0       # f_eq (MLife; n_eq = f_eq T)
//   channels:
//     RootMyc1: {wohler_exponent: 10, ultimate_load: 17750}   # kN-m, the channel's own unit
//     RotTorq:  {wohler_exponent: 3, ultimate_load: 8909, goodman_fixed_mean: 0}
//     default:  {wohler_exponent: 4}
//   calculated:                        # optional: channels computed in every file first
//     RootMxyb1: {magnitude_of: [RootMxb1, RootMyb1]}
//
// Lifetime specification — runs with their mean wind speed, the wind distribution, the design life,
// and the fatigue configuration above under `fatigue:` (`fatigue: {include: del.yaml}` shares one):
//
//   design_life_years: 20
//   bin_width_m_s: 2                  # bins centred on each run's speed
//   renormalise: false                # true: scale the bin probabilities to sum to 1 (pCrunch)
//   wind_distribution: {model: rayleigh, iec_class: 1}   # or {model: rayleigh, mean_speed_m_s: 10}
//                                     # or {model: weibull, shape: 2.2, scale_m_s: 11} / mean_speed_m_s
//   runs:
//     - {file: runs/ntm_08mps_s1.h5, wind_speed_m_s: 8}   # paths relative to this file
//     - {file: runs/ntm_12mps_s1.h5, wind_speed_m_s: 12}
//   fatigue: {channels: {RootMyc1: {wohler_exponent: 10}}}
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fowtsim/io/schema.hpp"
#include "fowtsim/post/damage_equivalent_load.hpp"
#include "fowtsim/post/lifetime.hpp"

namespace fowtsim::driver {

// A channel computed from others in every file (MLife's calculated channels): the vector magnitude
// of its components, e.g. the combined flap-edge root moment √(RootMxb1² + RootMyb1²).
struct CalculatedChannel {
  std::string name;                     // new channel
  std::vector<std::string> components;  // channels it is the magnitude of (same unit)
  std::string location;                 // "file:line:col" of its entry
};

struct FatigueConfig {
  double equivalent_frequency_hz = 1.0;                   // f_eq [Hz]
  std::vector<CalculatedChannel> calculated;             // added to each file's channels, in order
  std::map<std::string, post::FatigueParams> channels;   // per channel name
  std::optional<post::FatigueParams> default_params;     // for channels not listed
  std::map<std::string, std::string> channel_locations;  // channel → "file:line:col" of its entry

  // The parameters of `channel`, if it has a DEL.
  std::optional<post::FatigueParams> params_for(const std::string& channel) const;
};

struct LifetimeRunSpec {
  std::filesystem::path file;  // run output, resolved against the specification's directory
  double wind_speed_m_s = 0;   // mean hub-height wind speed of the run [m/s]
};

struct LifetimeSpec {
  double design_life_years = 20.0;                 // T_life [years]
  double bin_width_m_s = 2.0;                      // ΔV [m/s]
  bool renormalise = false;                        // scale the f_j to sum to 1
  post::WindSpeedDistribution distribution;       // wind-speed distribution
  std::string distribution_text;                   // e.g. "Rayleigh, V_ave 10 m/s (IEC class 1)"
  std::vector<LifetimeRunSpec> runs;               // in file order
  FatigueConfig fatigue;                           // DEL parameters
};

io::Schema fatigue_config_schema();
io::Schema lifetime_spec_schema();

// Reads and validates the files; throws DeckError / InputError naming file:line:col.
FatigueConfig read_fatigue_config(const std::filesystem::path& file);
LifetimeSpec read_lifetime_spec(const std::filesystem::path& file);

}  // namespace fowtsim::driver
