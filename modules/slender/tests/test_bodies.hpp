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
