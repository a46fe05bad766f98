#pragma once
// Whether a run outlasts its sea. Irregular seas (synthesised from a record of duration_s) and
// replayed seas (an elevation record of duration D) repeat with that period, as HydroDyn's do: a
// run longer than it meets the same waves again, without a word from the wave field itself. Still
// water and regular waves have nothing to repeat.
#include <optional>
#include <string>

#include "fowtsim/waves/wave_params.hpp"

namespace fowtsim::waves {

// The sea's period [s] (the record's duration), or nullopt for a sea that does not repeat a record.
std::optional<double> repeat_period_s(const WaveParams& params);

// A warning for the run summary when a run to t_end_s (from t = 0) is longer than the period: it
// names the period, where it comes from and a time that repeats an earlier one; nullopt otherwise.
std::optional<std::string> repeat_warning(const WaveParams& params, double t_end_s);

}  // namespace fowtsim::waves
