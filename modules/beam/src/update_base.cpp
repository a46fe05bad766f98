#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/rotation_vector.hpp"

namespace fowtsim::beam {

double update_base(const VecX& q, BeamState& state) {
  double max_rotation = 0.0;
  for (std::size_t n = 0; n < state.position_m.size(); ++n) {
    const Vec3 u = q.segment<3>(6 * n);
    const Vec3 theta = q.segment<3>(6 * n + 3);
    state.position_m[n] += u;
    state.orientation[n] = rotation_matrix(theta) * state.orientation[n];
    max_rotation = std::max(max_rotation, theta.norm());
  }
  return max_rotation;
}

}  // namespace fowtsim::beam
