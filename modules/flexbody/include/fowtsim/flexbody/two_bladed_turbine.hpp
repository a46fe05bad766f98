#pragma once
// The seed's Sec. 6 application: a 4-DOF two-bladed turbine of 5 bodies — flexible tower (q1, fore-aft
// along z_t), rigid nacelle fixed at the tower top, rigid shaft+hub on a revolute joint (q2, azimuth
// about the shaft axis), two flexible blades fixed perpendicular to the shaft at π apart (q3, q4, flap
// along the shaft axis) — assembled as M_q = Σ B'ᵀ M' B' (eq. 8) with the velocity transformation
// matrices of eq. 35, and K_q = Σ B'ᵀ K' B'.
//
// Geometry and frames follow the author's implementation of this example (welib yams
// models/TNSB.py `manual_assembly`, main_axis 'x', used by tests_numeric_recursive/test_TNSB_article.py):
// ground = tower frame, x_t up, z_t downstream; tower top N at x = L_t; R_tn = R_y(α_y),
// α_y = C_y q1, C_y = −ν_t(L_t) (eq. 35's coupling); the nacelle COG 2 m downstream of N (+z_n); the
// shaft origin S 10 m upstream of N (−z_n); R_ns = R_z(q2 + π); R_sb1 = R_z(0), R_sb2 = R_z(−π); blade
// axis x_b, flap along z_b (the shaft axis); r_SB = 0. The tower top's displacement moves the nacelle
// (B^n_x = [0 0 1]ᵀ, u_t(L) = 1), its position is kept at the undeformed x = L_t (it does not enter M_q).
#include "fowtsim/flexbody/quadrature.hpp"

#include <Eigen/Dense>

namespace fowtsim::flexbody {

struct TwoBladedTurbine {
  double tower_length = 100.0;         // L^t [m]
  double tower_EI = 2e12;              // EI_y^t [N m²]
  double tower_m = 9e3;                // m^t [kg/m]
  double nacelle_mass = 4e5;           // M^n [kg]
  Eigen::Vector3d nacelle_cog{0.0, 0.0, 2.0};                            // ρ^n from N [m]
  Eigen::Vector3d nacelle_inertia_at_N{7e6, 3e6, 1e6};                    // diag J_N^n [kg m²]
  double shaft_mass = 1e5;             // M^s [kg], COG at S
  Eigen::Vector3d shaft_inertia{2e5, 2e5, 3e5};                           // diag J_S^s [kg m²]
  double tower_top_to_shaft = 10.0;    // |r_NS| [m], upstream
  double blade_length = 60.0;          // L^b [m] (60 m: M^b = 30 t at 500 kg/m; the text's 75 m is not)
  double blade_EI = 2e10;              // EI_y^b [N m²]
  double blade_m = 500.0;              // m^b [kg/m]
  double blade_jG = 1e5;               // j_G^b section polar inertia [kg m] (eq. 31)
  double gravity = 9.81;               // [m/s²], for the geometric stiffness only
  // Eqs. 28–29 per body. The seed's printed M'^t has M_17 = 0 and M_15 = ∫ m u: it was computed
  // without the correction (welib's test builds the tower with bAxialCorr=False); its M'^b has
  // M_17 ≠ 0 (welib's hard-coded blade matrix, with the correction).
  bool tower_axial_correction = false;
  bool blade_axial_correction = true;
  // Equidistant station tables (welib's nSpan): used by the StationTrapezoid rule to reproduce the
  // author's discretisation; the default Gauss rule is exact-to-rounding on any of them.
  int tower_stations = 101;
  int blade_stations = 61;
  QuadratureRule rule{};
};

struct TurbineMatrices {
  Eigen::MatrixXd tower_mass;     // M'^t, 7 × 7 at g = q1
  Eigen::MatrixXd blade_mass[2];  // M'^b1, M'^b2, 7 × 7 at g = q3, q4
  Eigen::Matrix<double, 6, 6> nacelle_mass, shaft_mass;  // eq. 5 at N and at S
  double tower_stiffness = 0.0;   // K^tt_77 = ∫ EI κ² [N/m]
  double tower_geometric = 0.0;   // K^tt_g,77: top mass (M^n + M^s + 2M^b) and self-weight, eq. 26 [N/m]
  double blade_stiffness = 0.0;   // K^tb_77 [N/m]
  double blade_geometric = 0.0;   // self-weight of a blade pointing up, eq. 26 [N/m]
  double tower_coupling = 0.0;    // C_y = −ν_t(L) [rad/m]
  Eigen::Matrix4d Mq, Kq;         // eq. 36 (K_q without geometric stiffness, as printed)
};

// At q = [q1 (tower tip [m]), q2 (azimuth [rad]), q3, q4 (blade tips [m])].
TurbineMatrices two_bladed_turbine_matrices(const TwoBladedTurbine& turbine, const Eigen::Vector4d& q);

}  // namespace fowtsim::flexbody
