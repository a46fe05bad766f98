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
#include <vector>

#include "fowtsim/core/types.hpp"
#include "fowtsim/multibody/params.hpp"

namespace fowtsim::multibody {

inline constexpr int kMaxBlades = 3;
inline constexpr int kMaxTowerModes = 4;  // fore-aft + side-side tower bending modes (2 + 2, ElastoDyn)
inline constexpr int kMaxBladeModes = 3;  // Rayleigh–Ritz blade: flap 1, flap 2, edge 1 (ElastoDyn)
inline constexpr int kMaxBodyModes = 4;   // shape functions of one flexible body (tower or blade)
static_assert(kMaxTowerModes <= kMaxBodyModes && kMaxBladeModes <= kMaxBodyModes);
// surge, sway, heave, 3 rotations, rotor azimuth, generator azimuth, the tower modes, then each
// blade's modes
inline constexpr int kMaxDofs = 8 + kMaxTowerModes + kMaxBlades * kMaxBladeModes;

// Mass properties of one rigid body in its own frame.
struct RigidBody {
  double mass_kg = 0.0;                  // [kg]
  Vec3 cm_m = Vec3::Zero();              // CM from the frame origin, in the body frame [m]
  Mat3 inertia_kg_m2 = Mat3::Zero();     // inertia tensor about the CM, body frame [kg·m²]
};

// Generalised-velocity indices (u = [v_ref; ω_b; ψ̇; θ̇_g]).
// With a flexible tower the tower modes follow at kTower … kTower + tower modes − 1 (fore-aft
// first), and the generator row stays in place (an identity row with a rigid shaft). Rayleigh–Ritz
// blade b's modes are at kBlade + b·kMaxBladeModes + j.
enum Dof : int { kSurge = 0, kSway, kHeave, kRoll, kPitch, kYaw, kRotor, kGenerator, kTower,
                 kBlade = kTower + kMaxTowerModes };

// The mass of a flexible body (or a part of it) as shape integrals, so that its inertia costs the
// same whatever the mass distribution (seed 002 Sec. 2, eq. 2, and App. A: a flexible body's mass
// matrix from ∫m, ∫m p, ∫m p pᵀ, ∫m φ_j, ∫m φ_j pᵀ, ∫m φ_i φ_jᵀ — Wallrapp's "standard input
// data"). A point of the body at p (undeflected, in the body frame from its origin) moves to
// ρ = p + Σ_j q_j φ_j(p), φ_j a vector shape in the body frame.
struct ShapeIntegrals {
  double mass_kg = 0.0;                                   // ∫ m [kg]
  Vec3 first_moment_kg_m = Vec3::Zero();                  // ∫ m p [kg·m]
  Mat3 second_moment_kg_m2 = Mat3::Zero();                // ∫ m p pᵀ [kg·m²]
  std::array<Vec3, kMaxBodyModes> shape_mass_kg;          // c_j = ∫ m φ_j [kg]
  std::array<Mat3, kMaxBodyModes> shape_moment_kg_m;      // E_j = ∫ m φ_j pᵀ [kg·m]
  std::array<std::array<Mat3, kMaxBodyModes>, kMaxBodyModes> shape_product_kg;  // G_ij = ∫ m φ_i φ_jᵀ [kg]

  ShapeIntegrals() {  // Eigen members are not zeroed by {}
    for (int i = 0; i < kMaxBodyModes; ++i) {
      shape_mass_kg[i].setZero();
      shape_moment_kg_m[i].setZero();
      for (auto& g : shape_product_kg[i]) g.setZero();
    }
  }
  // Adds a point mass m at p with the shapes' values φ_0 … φ_{n−1} there.
  void add_point(double m, const Vec3& p, const std::array<Vec3, kMaxBodyModes>& phi, int n) {
    mass_kg += m;
    first_moment_kg_m += m * p;
    second_moment_kg_m2 += m * p * p.transpose();
    for (int j = 0; j < n; ++j) {
      shape_mass_kg[j] += m * phi[j];
      shape_moment_kg_m[j] += m * phi[j] * p.transpose();
      for (int i = 0; i < n; ++i) shape_product_kg[i][j] += m * phi[i] * phi[j].transpose();
    }
  }
};

// A tower mode's shape as ElastoDyn gives it, φ(h) = Σ_{k=2..6} c_k (h/L)^k (normalised to φ(L) = 1),
// h the height above the tower base along the undeflected axis.
struct TowerModeShape {
  std::array<double, 5> coefficients{};                   // c_2 … c_6 [-]
  double length_m = 1.0;                                  // L [m]
  double value(double height_m) const;                    // φ(h) [-]
  double slope(double height_m) const;                    // φ'(h) [1/m]
};

// A tower gauge (ElastoDyn's TwHt{k} outputs): its height and the mass above it (tower line mass
// from the gauge up and the yaw-bearing mass) as shape integrals, in the tower's coordinates (p from
// the reference point, φ_j at the tower's own heights), so flexible_body_dalembert() gives its d'Alembert load.
inline constexpr int kMaxTowerGauges = 9;  // ElastoDyn's NTwGages ≤ 9
struct TowerGauge {
  double height_m = 0.0;                  // above the tower base, undeflected axis [m]
  ShapeIntegrals above;                   // the tower mass above the gauge
};

// The flexible tower's Rayleigh–Ritz model (flexbody integrals), built by make_model().
struct FlexibleTower {
  int mode_count = 0;                                    // 0: rigid tower
  int fore_aft_count = 0;                                // modes 0 … fore_aft_count−1 bend along x_b, the rest along y_b
  std::array<Vec3, kMaxTowerModes> direction_b{};        // x_b or y_b
  std::array<TowerModeShape, kMaxTowerModes> shape{};    // φ_j
  std::array<double, kMaxTowerModes> top_shape{};        // φ_j(H) [-] (= 1)
  std::array<double, kMaxTowerModes> top_slope{};        // φ_j'(H) [1/m]
  ShapeIntegrals inertia;                                  // the whole tower + yaw-bearing mass
  Eigen::Matrix<double, kMaxTowerModes, kMaxTowerModes> stiffness =
      Eigen::Matrix<double, kMaxTowerModes, kMaxTowerModes>::Zero();      // K_q [N/m]
  Eigen::Matrix<double, kMaxTowerModes, kMaxTowerModes> geometric_stiffness_per_g =
      Eigen::Matrix<double, kMaxTowerModes, kMaxTowerModes>::Zero();      // K^T per unit g (top mass + self-weight) [kg/m]
  Eigen::Matrix<double, kMaxTowerModes, kMaxTowerModes> damping =
      Eigen::Matrix<double, kMaxTowerModes, kMaxTowerModes>::Zero();      // ElastoDyn's CTFA/CTSS [N·s/m]
  Eigen::Matrix<double, kMaxTowerModes, kMaxTowerModes> generalized_mass =
      Eigen::Matrix<double, kMaxTowerModes, kMaxTowerModes>::Zero();      // M_q of the tower alone [kg]
  double top_mass_kg = 0.0;                              // mass above the tower for K^T [kg]
};

// The Rayleigh–Ritz blades (flexbody's ElastoDyn blade), built by make_model(). Each blade is a
// flexible body in its pitched root frame f_i = r_i R_z(−β_i) (β: pitch, + toward feather), from
// its root: points at p = (0, 0, x) bend along φ_j(x) = (flap, edge, 0) displacements per unit q_j
// (flap along x_f, edge along y_f; ElastoDyn's twisted shapes, so a flap shape moves in-plane too).
// Pitch is a prescribed rotation without rate terms, as in ElastoDyn.
inline constexpr int kMaxBladeStations = 64;  // capacity of blade stations (aero nodes + tip)
struct BladeStation {
  double span_m = 0.0;                                    // x from the root along the pitch axis [m]
  std::array<Vec3, kMaxBodyModes> shape{};                // φ_j(x) in f [-]
  std::array<Vec3, kMaxBodyModes> slope{};                // φ_j'(x) in f [1/m]
  double twist_rad = 0.0;                                 // structural twist θ_s(x), + like pitch (ElastoDyn's StrcTwst) [rad]
};
// A Rayleigh–Ritz blade gauge: its station and the blade mass outboard of it as shape integrals
// (in the blade's frame, from the root), so flexible_body_dalembert() gives its d'Alembert load.
inline constexpr int kMaxBladeGauges = 9;  // ElastoDyn's NBlGages ≤ 9
struct BladeGauge {
  BladeStation station;                   // x of the gauge, shapes and slopes there
  ShapeIntegrals outboard;                // the blade mass beyond x
};
struct RayleighRitzBlades {
  int mode_count = 0;                                     // 0: rigid or MBBT blades; else 3
  double length_m = 0.0;                                  // TipRad − HubRad [m]
  ShapeIntegrals inertia;                                 // one blade, frame f, from the root
  Mat3 stiffness = Mat3::Zero();                          // K (eq. 20 with ElastoDyn's tuners) [N/m]
  Mat3 centrifugal_stiffness = Mat3::Zero();              // G per Ω² (eq. 26, centrifugal axial force) [kg]
  Mat3 damping = Mat3::Zero();                            // ElastoDyn's BldFlDmp/BldEdDmp [N·s/m]
  std::array<BladeStation, kMaxBladeStations> stations{}; // Params' spans, then the tip
  int station_count = 0;
  std::array<BladeGauge, kMaxBladeGauges> gauges{};       // the first gauge_count (RotorParams::blade_gauge_fractions)
  int gauge_count = 0;
};

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
  int dof_count = 7;                      // 7 (rigid drivetrain) or 8 (torsional flexibility); 8 + tower modes with a flexible
                                          // tower; kBlade + 3 B with Rayleigh–Ritz blades (unused rows between: dof_active)
  FlexibleTower flexible_tower;           // mode_count 0: the rigid tower (merged into base)
  RayleighRitzBlades rr_blades;           // mode_count 0: rigid (in `rotor`) or MBBT blades
  std::array<TowerGauge, kMaxTowerGauges> tower_gauges{};  // the first tower_gauge_count (TowerParams::gauge_heights_m)
  int tower_gauge_count = 0;
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

// Whether row/column i of M u̇ = f is a DOF of the model (the generator row is not with a rigid
// shaft, nor are the unused tower rows).
inline bool dof_active(const Model& model, int i) {
  if (i < kGenerator) return true;
  if (i == kGenerator) return model.generator_dof == kGenerator;
  if (i < kBlade) return i < kTower + model.flexible_tower.mode_count;
  return model.rr_blades.mode_count > 0 && i < kBlade + model.blade_count * kMaxBladeModes;
}

// Composite mass properties of the whole structure in b at the initial yaw and azimuth (rigid
// blades included, flexible ones not): for reports, checks and the driver's hydrostatic balance.
struct MassSummary {
  double mass_kg = 0.0;                  // total mass [kg]
  Vec3 cm_b_m = Vec3::Zero();            // CM from the reference point, in b [m]
  Mat3 inertia_ref_kg_m2 = Mat3::Zero(); // inertia about the reference point, in b [kg·m²]
};
MassSummary mass_summary(const Model& model);

}  // namespace fowtsim::multibody
