#pragma once
// A slender body's distributed properties along its axis x ∈ [0, L] (x = 0 at the clamped root):
// mass per length m [kg/m] and bending stiffness EI [N·m²] at stations, linear in between
// (as ElastoDyn interpolates its tower and blade tables).
#include <vector>

namespace fowtsim::flexbody {

struct BeamStations {
  std::vector<double> x;   // [m], strictly increasing, x.front() = 0, x.back() = L
  std::vector<double> m;   // [kg/m]
  std::vector<double> EI;  // [N m^2]

  double length() const { return x.back(); }
};

// Two stations: the uniform beam of the seed's Sec. 5.1 and of welib's test_flexibility.
inline BeamStations uniform_beam(double length, double mass_per_length, double bending_stiffness) {
  return {{0.0, length}, {mass_per_length, mass_per_length}, {bending_stiffness, bending_stiffness}};
}

}  // namespace fowtsim::flexbody
