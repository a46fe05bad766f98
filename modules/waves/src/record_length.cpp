#include "fowtsim/waves/record_length.hpp"

#include <fmt/format.h>

namespace fowtsim::waves {

std::optional<double> repeat_period_s(const WaveParams& params) {
  switch (params.model) {
    case WaveModel::jonswap:
    case WaveModel::pierson_moskowitz:
      return params.duration_s;
    case WaveModel::elevation_series:
      if (!params.elevation_record) return std::nullopt;
      return check_elevation_record(*params.elevation_record).duration_s;
    case WaveModel::still:
    case WaveModel::regular:
      return std::nullopt;
  }
  return std::nullopt;
}

std::optional<std::string> repeat_warning(const WaveParams& params, double t_end_s) {
  const std::optional<double> period = repeat_period_s(params);
  // A run exactly one period long ends on the sea it started with; only a longer one repeats.
  if (!period || !(t_end_s > *period * (1.0 + 1e-9))) return std::nullopt;
  const bool replayed = params.model == WaveModel::elevation_series;
  const double later = std::min(t_end_s, *period + 5.0);
  return fmt::format("the sea repeats every {:.6g} s ({}), the run lasts {:.6g} s: the waves at t = {:.6g} s are those at "
                     "t = {:.6g} s; {}",
                     *period, replayed ? "the length of the elevation record " + params.elevation_record->source : "waves.duration_s",
                     t_end_s, later, later - *period,
                     replayed ? "give a record as long as the run" : fmt::format("set waves.duration_s ≥ {:.6g}", t_end_s));
}

}  // namespace fowtsim::waves
