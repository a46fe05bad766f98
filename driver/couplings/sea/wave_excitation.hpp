#pragma once
// First-order potential-flow wave excitation on the platform, precomputed (issue 15): the WAMIT
// .3 transfer function X(ω, β) per unit wave amplitude, interpolated linearly in ω and in the
// sea's heading β (zero outside the table's frequencies), applied to every component of the sea
// at the platform's initial position (HydroDyn ExctnMod 1 with ExctnDisp 0), one record per DOF
// (waves/precomputed_response.hpp). WAMIT's convention e^{iωt} is the wave field's: the force is
// Re[X A e^{iωt}] for the elevation Re[A e^{iωt}] at the origin.
#include <optional>
#include <string>

#include "fowtsim/core/types.hpp"
#include "fowtsim/io/wamit_input.hpp"
#include "fowtsim/waves/precomputed_response.hpp"
#include "fowtsim/waves/wave_field.hpp"

namespace fowtsim::driver {

class WaveExcitation {
 public:
  // Throws InputError when the heading lies outside the table's headings.
  WaveExcitation(const waves::WaveField& field, const io::WamitExcitation& table);
  // [F; M] about the reference point, inertial frame, at time t [N, N·m].
  Vec6 at(double t_s) const;
  // A warning when more than 1 % of the sea's variance lies outside the table's frequencies.
  std::optional<std::string> coverage_warning() const { return warning_; }

 private:
  std::optional<waves::PrecomputedResponse> response_;
  std::optional<std::string> warning_;
};

// X_i(ω, β) of the table, linear in ω (zero outside its range) and in β [N/m, N·m/m].
std::complex<double> excitation_transfer(const io::WamitExcitation& table, int dof, double omega_rad_s, double heading_deg);

}  // namespace fowtsim::driver
