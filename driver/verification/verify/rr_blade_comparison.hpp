#pragma once
// The NREL 5MW blade as ElastoDyn's Rayleigh–Ritz body (modules/flexbody rr_blade.hpp, deck
// inputs/nrel5mw/blade_elastodyn.yaml) against the MBBT beam of the same blade (modules/beam, the
// BeamDyn blade of the r-test 5MW case, 6×6 sections), non-rotating and spinning at rated speed.
// Shared by driver/tests/rr_blade_mbbt_tests.cpp and `fowtsim verify flexbody`.
#include <filesystem>
#include <vector>

#include <Eigen/Core>

#include "fowtsim/flexbody/rr_blade.hpp"

namespace fowtsim::driver {

struct RrBladeComparison {
  double omega_rad_s = 0.0;                    // rated speed, 12.1 rpm (38060)
  flexbody::BladeMassProperties elastodyn_rule;  // mass moments on ElastoDyn's 17 nodes
  Eigen::Vector3d rr_rest_hz, rr_spinning_hz;  // flap 1, edge 1, flap 2 of the coupled 3×3
  std::vector<double> mbbt_rest_hz, mbbt_spinning_hz;  // the MBBT beam's first three
};
// `blade_deck`: the ElastoDyn blade deck; `beamdyn_driver`: the BeamDyn driver input naming the
// same blade. MBBT: 48 elements, clamped at the root of a frame spinning at Ω about the blade's flap
// axis through the rotor apex, HubRad inboard of the root; Ω > 0: static equilibrium under the
// centrifugal load first, then the eigen-analysis about it (stress stiffening in K).
RrBladeComparison rr_blade_comparison(const std::filesystem::path& blade_deck, const std::filesystem::path& beamdyn_driver);

}  // namespace fowtsim::driver
