#pragma once
// The matrix of an implicit step and the record of when it was factored. The cache lives in the
// beam's State (beam_state.hpp), not in the stepper: whether a step reuses it depends on its age
// and on how far the nodes have turned since it was built, so a copied state continues exactly
// as the original would only if the cache travels with it (checkpoints, retries).
#include "fowtsim/beam/block_tridiagonal.hpp"

namespace fowtsim::beam {

// A = m M + c C + k K (linear_system.hpp).
struct StepWeights {
  double mass = 1.0, damping = 0.0, stiffness = 0.0;  // m, c, k
};

struct StepMatrixCache {
  BlockTridiagonal factored;   // A, factored in place; empty until the first dynamic step
  bool valid = false;
  int age = 0;                 // steps taken with it
  double turned_rad = 0.0;     // Σ over those steps of the largest node rotation [rad]
  StepWeights weights;         // the m, c, k it was built with (they change with Δt)
};

// Field lists (core/fields.hpp).
template <class Archive>
void fields(Archive& a, BlockTridiagonal& m) {
  for (std::vector<Mat6>* blocks : m.storage()) a.io(*blocks);
}
template <class Archive>
void fields(Archive& a, StepMatrixCache& c) {
  a.io(c.factored, c.valid, c.age, c.turned_rad, c.weights);
}

}  // namespace fowtsim::beam
