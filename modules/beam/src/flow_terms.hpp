#pragma once
// The terms the fluid flowing inside a pipe adds to the beam's locally linear system
// (internal_flow.hpp has the physics and the seed's equation numbers). linear_system.cpp adds
// them to the assembled matrices and step_residual.cpp applies the same blocks to vectors, so the
// matrix and the matrix-free residual share one set of formulas.
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"
#include "section_mechanics.hpp"

namespace fowtsim::beam {

// Internal pressure at the N + 1 faces of the finite volumes [Pa]: face j < N is section j
// (face 0 the root), face N the tip. From the fluid's axial momentum balance of each volume about
// the base configuration (eq. 3.47): A^f (p_n − p_{n+1}) = τ Δs + m^f Δs (a_0 + 2 Ω × u̇_n) · t_n,
// τ the wall friction per length and a_0 = a_W − g + Ω̇ × x_n + Ω × (Ω × x_n) the frame
// acceleration at the node; the given end pressure fixes the constant.
void face_pressures(const BeamModel& model, const BeamInput& input, const BeamState& state,
                    std::vector<double>& out);

// The resultant of pressure and momentum flux at a face, in the section frame: a compressive
// force p A^f + m^f V² along the section axis (local axis 3), eqs. 3.21 and 3.48.
Vec6 flow_section_offset(const InternalFlow& flow, double pressure_pa);

// Node i's own flow terms added to its blocks (mass and damping only with `inertia`), and for the
// last node the jet leaving the free tip at pressure tip_pressure_pa.
void add_flow_node_terms(const BeamModel& model, const BeamInput& input, const BeamState& state, int i,
                         double tip_pressure_pa, bool inertia, Mat6& mass, Mat6& damping, Mat6& stiffness,
                         Vec6& rhs);

// Damping tangent (rows and columns [node a; node b]) of the pipe velocity carried by the flow
// through the face of `sec`: Φ = m^f V (I − 2 t tᵀ) ((1−α) u̇_a + α u̇_b), −Φ on a and +Φ on b,
// with t the chord direction; a held end (clamped or pinned) counts as a point at rest in f.
void flow_section_damping(const InternalFlow& flow, const SectionModel& sec, const NodePose& a,
                          const NodePose& b, Mat12& out);

}  // namespace fowtsim::beam
