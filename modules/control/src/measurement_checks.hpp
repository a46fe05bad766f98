#pragma once
// Checks shared by the built-in controller and the DLL interface: finite measurements, a time
// that does not run backwards, finite demands (DESIGN.md §7: never hand back NaN).
#include <array>
#include <optional>

#include "fowtsim/control/baseline_controller.hpp"

namespace fowtsim::control::detail {

// Throws NumericalError (module `module`, time t) on a non-finite measurement, a non-finite or
// non-positive dt, or t earlier than `last_call_time_s`.
void check_call(const char* module, const ControllerInput& u, double t, double dt,
                std::optional<double> last_call_time_s);

// Throws NumericalError (module `module`, time t) when a demand is not finite.
void check_demands(const char* module, double t, double torque_N_m, const std::array<double, kBladeCount>& pitch_rad);

}  // namespace fowtsim::control::detail
