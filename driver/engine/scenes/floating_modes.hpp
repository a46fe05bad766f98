#pragma once
// The modes behind `fowtsim modes DECK` (driver/app/cli/modes_command.hpp): natural frequencies, damping ratios and mode shapes of a floating-turbine
// deck's structure, linearised about its initial state with the flexible tower and Rayleigh–Ritz
// blades at their static deflection there (FloatingScene::settle_elastic, linearised_system) — the
// eigenvalues λ = −ζω ± iω√(1−ζ²) of ẋ = A x. Parked or not, the rotor is taken as it is at t = 0
// (no multi-blade transformation), the controller's demands held.
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace fowtsim::driver {

struct StructuralMode {
  double frequency_hz = 0.0;     // undamped natural frequency |λ|/2π (0: a rigid-body mode)
  double damping_ratio = 0.0;    // −Re λ / |λ|
  std::string dominant;          // the coordinate with the largest share of the shape
  Eigen::VectorXd shape;         // displacement part of the eigenvector, largest entry 1 (real part after phase alignment)
};

struct ModesResult {
  std::vector<std::string> coordinates;  // names of the shape entries (PtfmSurge …, in m or rad)
  std::vector<StructuralMode> modes;     // one per complex-conjugate pair or real eigenvalue, by frequency
};

// The names of the model's coordinates (multibody Dof indices): PtfmSurge … PtfmYaw, Azimuth,
// GenAzimuth, a flexible tower's modes, fore-aft first (ElastoDyn's DOF names TwFADOF1, TwFADOF2,
// TwSSDOF1, TwSSDOF2), Rayleigh–Ritz blades' modes (ElastoDyn's modal channels Q_B<b>F1, Q_B<b>F2,
// Q_B<b>E1).
std::vector<std::string> coordinate_names(const std::vector<int>& dofs, int fore_aft);

// The modes of the deck (with `--set` settings applied): InputError for a deck without a floating
// scene or with flexible blades.
ModesResult floating_modes(const std::filesystem::path& deck, const std::vector<std::string>& settings = {});


}  // namespace fowtsim::driver
