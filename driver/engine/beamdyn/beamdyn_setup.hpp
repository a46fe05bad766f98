#pragma once
// A BeamDyn stand-alone driver case (bd_driver.inp → primary → blade properties) translated into
// the beam module's terms, so `fowtsim run bd_driver.inp` reruns a BeamDyn case unchanged.
//
// BeamDyn semantics reproduced (OpenFAST BeamDyn driver; notes in driver/README.md):
//  * the reference line is BeamDyn's: per member a least-squares polynomial in z of degree
//    min(order_elem, key points − 1) through the key points, end points enforced; the section
//    frame turns by −initial_twist about the tangent (BeamDyn negates the input twist);
//  * the root sits at GlbPos with axes GlbDCMᵀ and turns at the constant angular velocity RootVel
//    (global axes) about the global origin; the beam starts undeformed, moving rigidly with it;
//  * gravity, DistrLoad, TipLoad and point loads are dead loads fixed in the global frame;
//  * outputs are in the rotating root frame r, which is the floating frame f of the beam module.
#include <optional>
#include <string>
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"
#include "fowtsim/beam/tip_motion.hpp"
#include "fowtsim/io/beamdyn_input.hpp"

namespace fowtsim::driver {

struct BeamDynSetup {
  beam::BeamDefinition definition;
  std::optional<beam::InternalFlow> flow{};   // fluid flowing inside: a pipe (the `pipe` scene)
  std::optional<beam::SurroundingWater> water{};  // still water around it, in the root frame (the `pipe` scene's sea)
  std::optional<beam::RampAndSway> tip_motion{};  // prescribed motion of a held tip, global (the `pipe` scene)
  Mat3 root_orientation0 = Mat3::Identity();  // root axes at t0 (columns, global) = GlbDCMᵀ
  Vec3 root_position_m = Vec3::Zero();        // GlbPos at t0, global [m]
  Vec3 angular_velocity_rad_s = Vec3::Zero(); // RootVel(4..6), global [rad/s]
  Vec3 gravity_m_s2 = Vec3::Zero();           // global [m/s²]
  Vec6 distributed_load = Vec6::Zero();       // global, per unit length [N/m, N·m/m]
  Vec6 tip_load = Vec6::Zero();               // global [N, N·m]
  std::vector<io::BeamDynPointLoad> point_loads{};  // global
  bool dynamic = false;
  bool quasi_static_init = false;
  double t_initial_s = 0.0, t_final_s = 0.0, dt_s = 0.0;
  double spectral_radius = 0.0;               // rhoinf
  std::vector<std::string> out_list{};
};

// Throws InputError naming the BeamDyn file and key for what cannot be represented.
BeamDynSetup beamdyn_setup(const io::BeamDynCase& bd);

// The beam of a BeamDyn primary file and its blade file: reference line, sections, stiffness-
// proportional damping (damp_type 1; modal damping 2 is refused). Checked by beam::validate: a
// problem names the blade file and station.
beam::BeamDefinition beamdyn_definition(const io::BeamDynPrimary& primary, const io::BeamDynBlade& blade);

// BeamDyn's reference line through key points (z increasing): per coordinate and for the twist a
// least-squares polynomial in z of total degree `degree`, end points met exactly; section frame
// turned by −twist about the tangent. Throws InputError (variable "kp_zr") if z does not increase.
beam::ReferenceLine beamdyn_reference_line(const std::vector<Vec3>& key_points_m,
                                           const std::vector<double>& twist_deg, int degree);

// Frame kinematics and dead loads at time t, resolved in the rotating root frame, written into
// `in` (sized on first use, then reused: no allocation in the time loop). Point loads act at
// their reference-line point, transferred to the nearest node with the moment of the arm in the
// current configuration.
void beamdyn_input(const BeamDynSetup& setup, const beam::BeamModel& model, const beam::BeamState& state,
                   double t_s, beam::BeamInput& in);

}  // namespace fowtsim::driver
