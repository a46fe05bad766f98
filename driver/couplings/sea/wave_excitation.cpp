#include "sea/wave_excitation.hpp"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/interpolation.hpp"

namespace fowtsim::driver {

std::complex<double> excitation_transfer(const io::WamitExcitation& table, int dof, double omega, double heading_deg) {
  const std::vector<double>& w = table.frequencies_rad_s;
  if (omega < w.front() || omega > w.back()) return 0.0;
  const std::vector<double>& b = table.headings_deg;
  const std::size_t i = bracket_index(w, omega);
  const double s = w.size() > 1 ? (omega - w[i]) / (w[i + 1] - w[i]) : 0.0;
  const std::size_t j = bracket_index(b, heading_deg);
  const double u = b.size() > 1 ? (heading_deg - b[j]) / (b[j + 1] - b[j]) : 0.0;
  const auto at_heading = [&](std::size_t h) {
    if (w.size() == 1) return table.force[h][0][dof];
    return lerp(table.force[h][i][dof], table.force[h][i + 1][dof], s);
  };
  return b.size() > 1 ? lerp(at_heading(j), at_heading(j + 1), u) : at_heading(0);
}

WaveExcitation::WaveExcitation(const waves::WaveField& field, const io::WamitExcitation& table) {
  const double heading = field.params().heading_deg;
  const std::vector<double>& b = table.headings_deg;
  if (heading < b.front() - 1e-9 || heading > b.back() + 1e-9)
    throw InputError({"hydro.potential_flow", std::nullopt, "waves.heading_deg", "a heading the .3 table covers"},
                     fmt::format("the sea's heading {}° lies outside the WAMIT excitation headings {}° … {}°", heading,
                                 b.front(), b.back()));
  if (field.calm()) return;
  std::array<waves::PrecomputedResponse::Transfer, 6> transfers;
  for (int dof = 0; dof < 6; ++dof)
    transfers[static_cast<std::size_t>(dof)] = [&table, dof, heading](double omega) {
      return excitation_transfer(table, dof, omega, heading);
    };
  response_.emplace(field, transfers);
  double outside = 0.0, total = 0.0;
  for (const waves::WaveComponent& c : field.components()) {
    const double variance = 0.5 * std::norm(c.amplitude_m);
    total += variance;
    if (c.omega_rad_s < table.frequencies_rad_s.front() || c.omega_rad_s > table.frequencies_rad_s.back()) outside += variance;
  }
  if (outside > 0.01 * total)
    warning_ = fmt::format("{:.1f} % of the sea's variance lies outside the WAMIT excitation frequencies {:.3g} … {:.3g} rad/s "
                           "and gets no excitation",
                           100.0 * outside / total, table.frequencies_rad_s.front(), table.frequencies_rad_s.back());
}

Vec6 WaveExcitation::at(double t) const {
  Vec6 f = Vec6::Zero();
  if (!response_) return f;
  for (int dof = 0; dof < 6; ++dof) f[dof] = response_->value(static_cast<std::size_t>(dof), t);
  return f;
}

}  // namespace fowtsim::driver
