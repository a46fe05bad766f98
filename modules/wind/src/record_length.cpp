#include "fowtsim/wind/record_length.hpp"

#include <fmt/format.h>

namespace fowtsim::wind {

std::optional<std::string> box_length_warning(const WindField& field, double t_end_s, double upwind_reach_m) {
  const WindParams& p = field.params();
  if (p.model == WindModel::uniform_file && !p.uniform.rows.empty() && t_end_s > p.uniform.rows.back().time_s)
    return fmt::format("the uniform wind file {} ends at {:.6g} s, the run goes to {:.6g} s: its last row is held after it (as "
                       "InflowWind does)",
                       p.file, p.uniform.rows.back().time_s, t_end_s);
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

std::optional<std::string> event_timing_warning(const WindField& field, double t_end_s) {
  const WindEventParams& e = field.params().event;
  if (e.type == WindEventType::none || e.start_s < t_end_s) return std::nullopt;
  return fmt::format("wind.event.start_s = {:.6g} s is not before the run's end, {:.6g} s: the event never acts", e.start_s, t_end_s);
}

}  // namespace fowtsim::wind
