#include "scenes/record_length_warnings.hpp"

#include "fowtsim/waves/record_length.hpp"
#include "fowtsim/wind/record_length.hpp"

namespace fowtsim::driver {

std::vector<std::string> record_length_warnings(const wind::WindField* wind, double upwind_reach_m, const waves::WaveParams* waves,
                                                double t_end_s) {
  std::vector<std::string> warnings;
  if (wind) {
    if (auto w = wind::box_length_warning(*wind, t_end_s, upwind_reach_m)) warnings.push_back(*w);
    if (auto w = wind::event_timing_warning(*wind, t_end_s)) warnings.push_back(*w);
  }
  if (waves)
    if (auto w = waves::repeat_warning(*waves, t_end_s)) warnings.push_back(*w);
  return warnings;
}

}  // namespace fowtsim::driver
