#include "fowtsim/wind/record_length.hpp"

#include <fmt/format.h>

namespace fowtsim::wind {

std::optional<std::string> box_length_warning(const WindField& field, double t_end_s, double upwind_reach_m) {
  const FullField* box = field.full_field();
  if (box == nullptr || !(box->u_hub_m_s > 0.0)) return std::nullopt;
  const double lead_s = (box->initial_x_m() + upwind_reach_m) / box->u_hub_m_s;  // the box passing the rotor
  const double needed_s = t_end_s + lead_s;
  const double covered_s = box->total_time_s();
  if (!(needed_s > covered_s * (1.0 + 1e-9))) return std::nullopt;
  const std::string source = field.params().model == WindModel::bts ? "the .bts file " + field.params().file : "wind.turbulence.duration_s";
  const std::string fix = field.params().model == WindModel::bts ? "generate a longer box"
                                                                   : fmt::format("set wind.turbulence.duration_s ≥ {:.6g}", needed_s);
  if (box->periodic)
    return fmt::format("the turbulence box covers {:.6g} s ({}), the run needs {:.6g} s ({:.6g} s + {:.3g} s for the box to pass the "
                       "rotor at {:.3g} m/s): it wraps around, the wind after t ≈ {:.6g} s repeats that of {:.6g} s earlier; {}",
                       covered_s, source, needed_s, t_end_s, lead_s, box->u_hub_m_s, covered_s - lead_s, covered_s, fix);
  return fmt::format("the turbulence box covers {:.6g} s ({}), the run needs {:.6g} s ({:.6g} s + {:.3g} s for the box to pass the "
                     "rotor at {:.3g} m/s): the run stops where the box ends, at t ≈ {:.6g} s; {}",
                     covered_s, source, needed_s, t_end_s, lead_s, box->u_hub_m_s, covered_s - lead_s, fix);
}

}  // namespace fowtsim::wind
