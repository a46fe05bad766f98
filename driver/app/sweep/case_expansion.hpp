#pragma once
// Expansion of a sweep spec into cases: each case is the base deck plus deck-key overrides, with a
// stable name and seeds derived from the spec alone (FNV-1a of the sweep name and the case's
// factors, the same on every machine and in every run), so any case reruns bit-identically alone.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fowtsim/io/deck.hpp"
#include "sweep/iec_presets.hpp"
#include "sweep/sweep_spec.hpp"

namespace fowtsim::driver::sweep {

// One deck key a case sets over the base deck.
struct DeckOverride {
  std::string key_path;        // e.g. "wind.turbulence.seed"
  std::string yaml_value;      // YAML scalar text (flow: a flow-style YAML list or mapping, written as is)
  io::SourceLocation source;   // spec location it comes from (line 0: derived by the sweep)
  bool flow = false;           // yaml_value is flow-style YAML (a preset's controller.events)
};

struct SweepCase {
  std::string name;                       // unique in the sweep; names the deck, output and log files
  std::size_t group = 0;                  // index in SweepSpec::groups
  std::optional<double> wind_speed_m_s;   // hub-height mean wind speed, if the deck has wind
  int realisation = 1;                    // 1 … seeds of its factor combination
  std::optional<std::uint64_t> wind_seed;  // turbulence seed, if the wind is turbulent
  std::optional<std::uint64_t> wave_seed;  // wave phase seed, if the sea is irregular
  std::optional<double> hs_m, tp_s;       // sea state, if the sweep sets it
  std::vector<std::pair<std::string, std::string>> factors;  // varied factors (label, value), for --list
  std::vector<DeckOverride> overrides;    // in the order they apply; a later key replaces an earlier one
  bool fatigue = false;                   // enters the lifetime DEL
};

// What the expansion needs to know of the base deck (read from it, with its includes).
struct BaseDeckFacts {
  std::string wind_model;                 // wind.model ("" without a wind section)
  std::optional<double> wind_speed_m_s;   // wind.speed_m_s
  double turbulence_width_m = 0.0;        // wind.turbulence.width_m (0: not given)
  std::string wave_model;                 // waves.model ("" without a waves section)
  BaseController controller;              // its type and pitch limit (the parked preset)
  bool rayleigh_ritz_blades = false;      // structure.rotor.rayleigh_ritz_blade_file given (the trim settles them)
};
BaseDeckFacts read_base_deck_facts(const std::filesystem::path& base_deck);

// Every case of the spec, group by group, factors nested in the order wind speed, the preset's
// factors (event sign, event time, yaw), yaw, wave heading, `set` keys, realisation (innermost). Throws io::DeckError naming the spec line when
// two cases would get the same name.
std::vector<SweepCase> expand_cases(const SweepSpec& spec, const BaseDeckFacts& base);

// The seed of a case: FNV-1a 64 of "sweep|group|factor=value|…|realisation|stream", folded to
// [0, 2^31) so that it fits every seed field (TurbSim's is a 32-bit signed integer).
std::uint64_t case_seed(const std::string& canonical_case, const std::string& stream);

}  // namespace fowtsim::driver::sweep
