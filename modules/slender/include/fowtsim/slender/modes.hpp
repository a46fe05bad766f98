#pragma once
// Undamped modes (seed 004, slide "Undamped Modes"): (K − ω²M)ψ = 0, Ψᵀ M Ψ = I, Ψᵀ K Ψ = Ω²,
// and q = Ψ a with a the modal coordinates.
#include "fowtsim/core/types.hpp"
#include "fowtsim/slender/model.hpp"

namespace fowtsim::slender {

struct Modes {
  VecX omega_rad_s;   // ω_k, ascending (ζ) [rad/s]
  MatX shapes;        // Ψ (n × ζ): mass-normalised eigenvectors in generalised coordinates
};

// The lowest `count` modes (count <= n; 0 or less means all). Throws InputError when some
// ω² < 0 (the body buckles under its effective tension) or K, M are not finite.
Modes compute_modes(const Model& model, int count = 0);

}  // namespace fowtsim::slender
