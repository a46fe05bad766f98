#pragma once
// Shape of a line at a pose: node positions along the line, for plots and for initialising a
// lumped-mass (MoorDyn-like) model from the quasi-static equilibrium.
#include <cstddef>
#include <vector>

#include "fowtsim/core/types.hpp"
#include "fowtsim/mooring/quasi_static_mooring.hpp"

namespace fowtsim::mooring {

struct LineNode {
  double arc_length_m = 0.0;     // unstretched arc length from the anchor [m]
  Vec3 position_m = Vec3::Zero();  // position, inertial frame g [m]
  double tension_N = 0.0;        // tension magnitude there [N]
};

// node_count ≥ 2 nodes evenly spaced in unstretched arc length, from the anchor (first) to the
// fairlead (last), for line `index` at the pose in `u` (warm-started from `s`). Catenary lines
// follow the analytic solution (a slack heap on the seabed is drawn stretched evenly over the
// grounded span); taut lines are straight. Throws InputError on a bad index or node count.
std::vector<LineNode> line_profile(const MooringParams& p, const QuasiStaticMooring::Input& u,
                                   const QuasiStaticMooring::State& s, std::size_t index, std::size_t node_count);

}  // namespace fowtsim::mooring
