#pragma once
// Bodies shared by the slender tests: uniform tubes cut into equal strips.
#include "fowtsim/slender/model.hpp"

#include <vector>

namespace fowtsim::slender::testing {

inline std::vector<Strip> uniform_strips(int count, double length, Strip strip) {
  strip.length_m = length / count;
  return std::vector<Strip>(static_cast<std::size_t>(count), strip);
}

// Steel tube, 0.5 m × 0.45 m, E 210 GPa, Cd 1, Ca 1 (the strip length is set by uniform_strips).
inline Strip steel_tube() { return {0.0, 0.5, 0.45, 7850.0, 2.1e11, 1.0, 1.0, 0.0}; }

}  // namespace fowtsim::slender::testing

#include "fowtsim/slender/statistics.hpp"
#include "fowtsim/slender/wave_synthesis.hpp"

#include <cmath>
#include <complex>
#include <numbers>

namespace fowtsim::slender::testing {

// Pierson–Moskowitz spectrum in Hs, Tp (DNV-RP-C205 eq. 3.5.1) [m² s/rad] at ω [rad/s]: the tests
// build their own sea, as a caller would (the solvers take S(ω) as data).
inline double pierson_moskowitz(double omega, double hs, double tp) {
  const double wp = 2 * std::numbers::pi / tp;
  return 5.0 / 16.0 * hs * hs * std::pow(wp, 4) * std::pow(omega, -5) * std::exp(-1.25 * std::pow(wp / omega, 4));
}

}  // namespace fowtsim::slender::testing
