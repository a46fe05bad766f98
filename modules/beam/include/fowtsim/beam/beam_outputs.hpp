#pragma once
// What a beam reports: tip deflection and rotation, and the loads at its root. All in the
// floating frame f the root is clamped to (BeamDyn's root frame "r" when f is that frame).
#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"

namespace fowtsim::beam {

struct BeamOutputs {
  Vec3 tip_displacement_m = Vec3::Zero();  // tip point − undeformed tip point, in f [m]
  Vec3 tip_rotation_wm = Vec3::Zero();     // Wiener–Milenkovic parameters of R_tip R0_tipᵀ [-]
  Vec3 tip_position_m = Vec3::Zero();      // deformed tip point, in f [m]
  Vec6 root_load = Vec6::Zero();           // [force N; moment N·m about the root point] that the
                                           // beam puts on its root (incl. strain-rate damping), in f
};

BeamOutputs beam_outputs(const BeamModel& model, const BeamState& state);

// A span gauge: the internal load at the section nearest to arclength fraction eta — force and
// moment (about the section point) that the outboard part puts on the inboard part, strain-rate
// damping included, in f. At the root it is the root load.
Vec6 section_load_at(const BeamModel& model, const BeamState& state, double eta);

// The frame of that section (columns in f): the frame its strains and stress resultant are resolved
// in, between the two nodes' frames — the section's own twisted and deflected frame, axis 3 along
// the reference line (ElastoDyn's local blade frame n at a span gauge: its loads are Rᵀ F, Rᵀ M).
Mat3 section_frame_at(const BeamModel& model, const BeamState& state, double eta);

// Elastic strain energy Σ_j ½ Δs_j [γ; κ]ᵀ C [γ; κ] of the sections [J].
double strain_energy(const BeamModel& model, const BeamState& state);

}  // namespace fowtsim::beam
