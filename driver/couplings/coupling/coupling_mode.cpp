#include "coupling/coupling_mode.hpp"

#include <cmath>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

long CouplingSettings::large_steps() const { return std::lround(t_max_s / dt_coupling_s); }

CouplingMode parse_coupling_mode(std::string_view text) {
  if (text == "multi_rate") return CouplingMode::multi_rate;
  if (text == "predictor_corrector") return CouplingMode::predictor_corrector;
  if (text == "single_rate") return CouplingMode::single_rate;
  throw InputError({"coupling", {}, "coupling", "one of multi_rate, predictor_corrector, single_rate"},
                   fmt::format("unknown coupling mode '{}'", text));
}

std::string to_string(CouplingMode mode) {
  switch (mode) {
    case CouplingMode::multi_rate: return "multi_rate";
    case CouplingMode::predictor_corrector: return "predictor_corrector";
    case CouplingMode::single_rate: return "single_rate";
  }
  return "?";
}

void validate(const CouplingSettings& s) {
  auto fail = [](const std::string& variable, const std::string& message, const std::string& hint) {
    throw InputError({"coupling", {}, variable, hint}, message);
  };
  if (!(s.dt_coupling_s > 0.0)) fail("dt_coupling_s", "the coupling step must be > 0", "");
  if (s.substeps < 1) fail("substeps", "substeps must be ≥ 1", "");
  if (s.mode == CouplingMode::single_rate && s.substeps != 1) {
    fail("substeps", fmt::format("single_rate coupling runs every subsystem at one step, found substeps = {}", s.substeps),
         "set substeps: 1, or use multi_rate");
  }
  if (!(s.t_max_s > 0.0)) fail("t_max_s", "the simulated time must be > 0", "");
  const double steps = s.t_max_s / s.dt_coupling_s;
  if (std::abs(steps - std::round(steps)) > 1e-9 * steps) {
    fail("t_max_s", fmt::format("t_max_s = {} is not a whole number of coupling steps of {} s", s.t_max_s, s.dt_coupling_s),
         "make t_max_s a multiple of dt_coupling_s");
  }
}

}  // namespace fowtsim::driver
