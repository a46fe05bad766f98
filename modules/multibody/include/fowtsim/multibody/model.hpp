#pragma once
// The multibody model derived once from Params (Pinocchio's Model): the rigid bodies with their
// mass properties, the fixed geometry of the chain and the number of degrees of freedom. Built
// and validated by make_model(); immutable afterwards; shared read-only by every call.
//
// The chain (frames; T_ab rotates b-components into a, core/rotation.hpp):
//   g ──(r, T_gb: platform 6 DOF)──▶ b  base body = platform + rigid tower + yaw-bearing mass
//   b ──(tower top, T_bn = R_z(yaw): prescribed)──▶ n  nacelle (yaw bearing at the tower top)
//   n ──(apex, T_ns = R_y(−ShftTilt): fixed)──▶ s  shaft frame, x_s along the LSS pointing downwind
//   s ──(T_sh = R_x(ψ): rotor azimuth DOF)──▶ h  hub/rotor; blade 1 along z_h at ψ = 0
//   s ──(R_x(N θ_g): generator azimuth, LSS-equivalent θ_g, DOF only with a flexible shaft)──▶ generator
//   h ──(T_hr_i = R_x(2π(i−1)/B) R_y(PreCone), root at HubRad along z_r)──▶ blade-i root frame r_i
#include <array>

#include "fowtsim/core/types.hpp"
#include "fowtsim/multibody/params.hpp"

namespace fowtsim::multibody {

inline constexpr int kMaxBlades = 3;
inline constexpr int kMaxDofs = 8;  // surge, sway, heave, 3 rotations, rotor azimuth, generator azimuth

// Mass properties of one rigid body in its own frame.
struct RigidBody {
  double mass_kg = 0.0;                  // [kg]
  Vec3 cm_m = Vec3::Zero();              // CM from the frame origin, in the body frame [m]
  Mat3 inertia_kg_m2 = Mat3::Zero();     // inertia tensor about the CM, body frame [kg·m²]
};

// Generalised-velocity indices (u = [v_ref; ω_b; ψ̇; θ̇_g]).
enum Dof : int { kSurge = 0, kSway, kHeave, kRoll, kPitch, kYaw, kRotor, kGenerator };

struct Model {
  Params params;                          // the validated input, kept for reference
  RigidBody base;                         // platform + tower + yaw-bearing mass, frame b, from the reference point
  RigidBody tower;                        // tower + yaw-bearing mass alone (above the tower base), frame b
  RigidBody nacelle;                      // frame n, from the tower top
  RigidBody rotor;                        // hub (+ rigid blades), frame h, from the apex
  double generator_inertia_kg_m2 = 0.0;   // polar inertia of the generator about the HSS [kg·m²]
  double gearbox_ratio = 1.0;             // N [-]
  Vec3 tower_base_b = Vec3::Zero();       // tower-base point in b, from the reference point [m]
  Vec3 tower_top_b = Vec3::Zero();        // tower top / yaw bearing in b [m]
  Vec3 apex_n = Vec3::Zero();             // rotor apex in n, from the tower top [m]
  Vec3 imu_n = Vec3::Zero();              // nacelle IMU in n, from the tower top [m]
  Mat3 shaft_in_nacelle = Mat3::Identity();  // T_ns [-]
  int blade_count = 3;                    // B
  std::array<Mat3, kMaxBlades> blade_root_orientation_h{};  // T_hr_i [-]
  std::array<Vec3, kMaxBlades> blade_root_h{};              // root point i in h, from the apex [m]
  int dof_count = 7;                      // 7 (rigid drivetrain) or 8 (torsional flexibility)
  int generator_dof = kRotor;             // index of the DOF that turns the generator
  // DOFs whose acceleration is given instead of solved for (Params::dofs): zero for a held DOF,
  // State::rotor/generator_acceleration_rad_s2 for a prescribed spin. Their rows of M u̇ = f
  // are dropped; the constraint torque that enforces them is internal to the chain.
  std::array<bool, kMaxDofs> acceleration_given{};
};

// Validates params (InputError listing every bad field, module "multibody", with the deck key
// path) and builds the model. Also rejects a system whose mass matrix is singular at the initial
// configuration (e.g. all inertias zero, or a flexible drivetrain without generator inertia).
Model make_model(const Params& params);

// Composite mass properties of the whole structure in b at the initial yaw and azimuth (rigid
// blades included, flexible ones not): for reports, checks and the driver's hydrostatic balance.
struct MassSummary {
  double mass_kg = 0.0;                  // total mass [kg]
  Vec3 cm_b_m = Vec3::Zero();            // CM from the reference point, in b [m]
  Mat3 inertia_ref_kg_m2 = Mat3::Zero(); // inertia about the reference point, in b [kg·m²]
};
MassSummary mass_summary(const Model& model);

}  // namespace fowtsim::multibody
