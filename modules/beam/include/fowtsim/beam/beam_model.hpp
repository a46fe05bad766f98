#pragma once
// The beam as the solver sees it: a definition (reference line, sectional properties, damping)
// and its finite-volume discretisation (seed 000 §2.3.3, Fig. 2.3), built once — the model half
// of the model/data split. Everything here is constant during a run.
//
// Discretisation: the beam is cut into N segments (finite volumes). Node n is the reference-line
// point at the middle of segment n; it carries the segment's mass, and its position x_n and
// orientation R_n are the unknowns. Section j sits between node j−1 and node j; section 0
// joins the clamped root (s = 0) to node 0 — the equivalent of the seed's imaginary zeroth
// segment (§2.5: mirrored displacements make the root section's displacement zero). The free
// tip has no section (the seed's zero-stiffness last cross-section): the half segment beyond
// node N−1 moves rigidly with it.
#include <optional>
#include <vector>

#include "fowtsim/beam/internal_flow.hpp"
#include "fowtsim/beam/reference_line.hpp"
#include "fowtsim/beam/surrounding_water.hpp"
#include "fowtsim/core/types.hpp"

namespace fowtsim::beam {

// Sectional properties at one station, BeamDyn's convention: local axis 3 along the reference
// line, components in the local (twisted) frame of the station.
struct Station {
  double eta = 0.0;          // arclength fraction from root (0) to tip (1) [-]
  Mat6 stiffness;            // C: strains [γ1 γ2 γ3 κ1 κ2 κ3] -> [F1 F2 F3 M1 M2 M3] [N, N·m, N·m²]
  Mat6 mass;                 // per unit length about the reference point: [m I, m ẽᵀ; m ẽ, i]
                             // [kg/m, kg, kg·m] — ẽ the mass-centre offset, i the inertia
};

// How an end of the beam is held. The root is clamped or pinned; the tip free, clamped or pinned.
enum class EndCondition { free, clamped, pinned };

struct BeamDefinition {
  ReferenceLine line;
  std::vector<Station> stations;     // eta ascending from 0 to 1; linear interpolation between
  Vec6 stiffness_damping = Vec6::Zero();  // μ: section damping D = diag(μ) C [s] (BeamDyn damp_type 1;
                                          // the seed's μ_K is μ with all six entries equal, eq. 2.61)
  double mass_damping_1_s = 0.0;          // μ_M of eq. 2.61 [1/s]
  EndCondition root_end = EndCondition::clamped;  // clamped or pinned
  EndCondition tip_end = EndCondition::free;      // free, clamped or pinned
};

inline constexpr int kRootEnd = -1;  // SectionModel::inboard of the root section
inline constexpr int kTipEnd = -2;   // SectionModel::outboard of a held tip's section

// One section (cross-section j between two nodes) of the discretised beam.
struct SectionModel {
  int inboard = kRootEnd;  // node index on the root side; kRootEnd = the held root
  int outboard = 0;        // node index on the tip side; kTipEnd = the held tip
  bool pinned = false;     // its held end is a pin: the seed's imaginary segment (§3.4.3) mirroring
                           // the node through the end point (u_ghost = −u, θ_ghost = θ: no moment)
  double alpha = 0.5;      // position of the section between the two nodes, fraction from inboard
  double length_m = 0.0;   // Δs^j: arclength between the two nodes [m]
  Mat6 stiffness;          // C at the section [N, N·m, N·m²]
  Mat6 damping;            // D = diag(μ) C [N·s, …]
  Vec3 chord_ref = Vec3::Zero();      // R0_jᵀ d0 / Δs: undeformed chord strain reference [-]
  Vec3 curvature_ref = Vec3::Zero();  // log(R0_aᵀ R0_b)/Δs: undeformed curvature k_l [1/m]
};

// One node (segment centre) with the segment's rigid-body inertia, resolved in the node's own
// undeformed local frame (it moves rigidly with the node's orientation).
struct NodeModel {
  double s_m = 0.0;                   // arclength of the node [m]
  double segment_length_m = 0.0;      // Δs of the segment [m]
  Vec3 position_m = Vec3::Zero();     // undeformed position in f [m]
  Mat3 orientation = Mat3::Identity();  // undeformed local frame R0_n (columns in f)
  double mass_kg = 0.0;               // M^n (eq. 2.40)
  Vec3 mass_offset_m = Vec3::Zero();  // mass centre − node, local frame [m]
  Mat3 inertia_kg_m2 = Mat3::Zero();  // inertia about the node, local frame [kg·m²]
  Vec3 load_arm_m = Vec3::Zero();     // segment length centroid − node, local frame [m]:
                                      // where uniform distributed loads act
};

struct BeamModel {
  std::vector<NodeModel> nodes;
  std::vector<SectionModel> sections;  // sections[j] is inboard of nodes[j]; a held tip adds
                                       // sections[N] between the last node and the tip
  Vec3 root_position_m = Vec3::Zero();  // clamped root point in f [m]
  Mat3 root_orientation = Mat3::Identity();  // clamped root frame
  Vec3 tip_arm_m = Vec3::Zero();        // tip point − last node, in the last node's local frame [m]
  Vec3 tip_position_m = Vec3::Zero();   // undeformed tip point in f [m]; a held tip may be moved from
                                        // it (BeamInput::tip_displacement_m, BeamState::tip_offset_m)
  Mat3 tip_orientation = Mat3::Identity();
  double mass_damping_1_s = 0.0;        // μ_M
  double length_m = 0.0;
  std::optional<InternalFlow> flow;     // fluid flowing inside: a pipe (pipe.hpp); none for a beam
  std::optional<SurroundingWater> water;  // buoyancy and Morison loads of still water around it; none in air

  int node_count() const { return static_cast<int>(nodes.size()); }
  bool free_tip() const { return sections.back().outboard != kTipEnd; }
  int dof_count() const { return 6 * node_count(); }
};

// Sectional properties at arclength fraction eta, linearly interpolated between stations.
Mat6 stiffness_at(const BeamDefinition& def, double eta);
Mat6 mass_at(const BeamDefinition& def, double eta);

// Throws InputError when the definition is unusable: no station, eta not increasing, a property
// not finite, a negative mass per length or damping. The variable names the station
// ("stations[2].mass"), so a reader can point at where it came from.
void validate(const BeamDefinition& def);

// Discretise into `segments` equal-length finite volumes. Inertia per segment is integrated with
// Gauss quadrature over the segment (the segment's own length contributes its rod inertia, as the
// seed's control-volume inertia I^n does). Throws InputError on a bad definition.
BeamModel discretise(const BeamDefinition& def, int segments);

}  // namespace fowtsim::beam
