#pragma once
// The sweep spec (`fowtsim sweep SPEC`): a base deck, load-case groups whose factors expand into
// cases (case_expansion.hpp), and what the load table holds (load_table.hpp). The spec is a YAML
// deck validated like every other (io/schema.hpp): problems are reported together, each with its
// file:line:col. Format and an example: driver/app/sweep/README.md, inputs/sweeps/dlc12_oc3.yaml.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fowtsim/io/deck.hpp"
#include "fowtsim/io/schema.hpp"
#include "sweep/slurm_options.hpp"

namespace fowtsim::driver::sweep {

enum class Combination {
  cross,  // every value of every factor with every value of the others
  zip,    // the i-th value of each factor together; single values are shared by all
};

// A deck key set per case: one value per case (`set:` in the spec).
struct KeyFactor {
  std::string key_path;             // deck key, e.g. "controller.min_pitch_rad"
  std::vector<std::string> values;  // YAML scalar text of each value, as written in the spec
  io::SourceLocation location;      // where the key is written in the spec
};

// Hs and Tp as a function of the hub-height mean wind speed, for irregular seas.
struct SeaStateTableRow {
  double wind_speed_m_s = 0.0;  // hub-height mean wind speed [m/s]
  double hs_m = 0.0;            // significant wave height [m]
  double tp_s = 0.0;            // peak period [s]
};

struct SeaStateSpec {
  enum class Kind {
    from_base_deck,  // waves as the base deck has them
    fixed,           // one Hs, Tp for every case (severe or extreme seas, DLC 6.1)
    table,           // linear interpolation in the wind speed between table rows
    relation,        // Hs = Σ c_k V^k, Tp = tp_factor √(Hs/g)
  };
  Kind kind = Kind::from_base_deck;
  double hs_m = 0.0;                      // fixed: significant wave height [m]
  double tp_s = 0.0;                      // fixed: peak period [s]
  std::vector<SeaStateTableRow> table;    // table: rows by increasing wind speed
  std::vector<double> hs_coefficients;    // relation: c_0, c_1, … of Hs(V) [m, m/(m/s), …]
  double tp_factor = 0.0;                 // relation: Tp / √(Hs/g), – (IEC 61400-3: 11.1 … 14.3)
  io::SourceLocation location;            // the spec's `sea_state`, for errors about it
};

struct LoadCaseGroup {
  std::string name;                          // case-name prefix, e.g. "dlc12"
  std::string preset;                        // "dlc1.1" … "dlc7.1" (iec_presets.hpp) or "" (none)
  std::vector<double> wind_speeds_m_s;       // hub-height mean speeds; empty = the base deck's
  int seeds = 1;                             // stochastic realisations per factor combination
  SeaStateSpec sea_state;                    // waves per case
  std::vector<double> yaw_misalignment_deg;  // wind direction relative to the rotor axis; empty = 0
  std::vector<double> wave_heading_deg;      // wave propagation direction; empty = the base deck's
  std::vector<KeyFactor> set;                // other deck keys
  Combination combine = Combination::cross;  // how the factors above combine
  bool fatigue = false;                      // enters the lifetime DEL (default: the preset's analysis F)
  bool ultimate = true;                      // enters the ultimate-load table (the preset's analysis U; else true)
  double partial_safety_factor = 1.35;       // γ_f of its ultimate loads (the preset's; else N, 1.35)
  double fatigue_time_fraction = 1.0;        // share of the design life this group's conditions hold (time-weighted fatigue)
  std::vector<double> events_per_year;       // event-weighted fatigue: occurrences a year, one or one per wind speed
  io::SourceLocation location;               // the group's mapping in the spec
};

struct FatigueChannel {
  std::string channel;           // output channel, e.g. "TwrBsMyt"
  double wohler_exponent = 0.0;  // m, S-N slope exponent, –
};

struct LoadTableSpec {
  std::vector<std::string> channels;       // channels with statistics (min, max, mean, std)
  std::vector<FatigueChannel> fatigue;     // channels with short-term and lifetime DELs
  double equivalent_frequency_hz = 1.0;    // f_eq of the DELs [Hz]
  double design_life_years = 20.0;         // T_life of the lifetime damage [years]
  double weibull_shape = 2.0;              // k of the wind-speed distribution, – (2 = Rayleigh)
  std::optional<double> mean_wind_speed_m_s;  // V_ave; absent = 0.2 V_ref of the turbine class
  std::optional<double> bin_width_m_s;        // wind-speed bin; absent = spacing of the fatigue speeds
};

struct TurbineClass {
  int wind_class = 1;            // IEC 61400-1 wind turbine class I, II, III (V_ref 50, 42.5, 37.5 m/s)
  std::string turbulence_class;  // "A", "B", "C" (I_ref 0.16, 0.14, 0.12)
  double hub_height_m = 90.0;    // hub height above the still-water level [m]
  std::optional<double> rotor_diameter_m;  // D of the gust and shear events [m]
  std::optional<double> cut_in_m_s;        // V_in, hub height [m/s]: the presets' default speeds derive from
  std::optional<double> rated_m_s;         // V_r [m/s]   these three
  std::optional<double> cut_out_m_s;       // V_out [m/s]
};

// Steady runs that trim the operating cases' initial conditions (trim.hpp).
struct TrimSpec {
  double duration_s = 400.0;  // length of each steady run [s]: long enough for the platform's surge to settle
  double average_s = 150.0;   // averaged end of it [s]: at least one surge period of a floating platform
};

struct SweepSpec {
  std::filesystem::path spec_path;     // the spec file as given
  std::string name;                    // sweep name: seeds and the default output folder derive from it
  std::filesystem::path base_deck;     // scene deck every case includes (resolved against the spec)
  std::filesystem::path output_dir;    // where decks, outputs, logs and the table go
  double transient_s = 120.0;          // start discarded from the statistics [s]
  double analysis_s = 600.0;           // analysed length after the transient [s]
  TurbineClass turbine;                // IEC classes for the presets and the wind distribution
  std::vector<LoadCaseGroup> groups;   // load-case groups, expanded in order
  LoadTableSpec load_table;            // what the table holds
  SlurmOptions slurm;                  // the spec's `slurm:` section (--slurm; the command line overrides)
  std::optional<TrimSpec> trim;        // sweep.trim: start operating cases at their steady operating point
  std::string hash;                    // deck_hash of the spec file
};

io::Schema sweep_spec_schema();

// Reads and validates a spec; throws io::DeckError (file:line:col per problem) for a bad one.
SweepSpec read_sweep_spec(const std::filesystem::path& spec_path);

}  // namespace fowtsim::driver::sweep
