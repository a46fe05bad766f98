#include "fowtsim/flexbody/two_bladed_turbine.hpp"

#include "fowtsim/flexbody/body_mass_matrix.hpp"
#include "fowtsim/flexbody/integrals.hpp"
#include "fowtsim/flexbody/shape_functions.hpp"
#include "fowtsim/flexbody/shape_integrals.hpp"

#include <numbers>

namespace fowtsim::flexbody {
namespace {

Eigen::Matrix3d rot_y(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix();
}
Eigen::Matrix3d rot_z(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// B' of a body (6 + n_f rows, 4 columns) from its ground-frame B_x, B_θ (3 × 4), its orientation R_0i
// and the generalised coordinate of each of its shapes (eq. 11, B^i = R_0i B'^i).
Eigen::MatrixXd body_frame_B(const Eigen::Matrix<double, 3, 4>& Bx, const Eigen::Matrix<double, 3, 4>& Bt,
                             const Eigen::Matrix3d& R0i, int shape_dof) {
  const int nf = shape_dof < 0 ? 0 : 1;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(6 + nf, 4);
  B.topRows<3>() = R0i.transpose() * Bx;
  B.middleRows<3>(3) = R0i.transpose() * Bt;
  if (nf) B(6, shape_dof) = 1.0;
  return B;
}

struct FlexBody {
  SampledBody sampled;
  ShapeIntegrals integrals;
  BeamStations stations;
};

FlexBody flex_body(double L, double m, double EI, int stations, double top_mass_ratio,
                   const QuadratureRule& rule) {
  FlexBody b;
  for (int i = 0; i < stations; ++i) {
    b.stations.x.push_back(L * i / (stations - 1.0));
    b.stations.m.push_back(m);
    b.stations.EI.push_back(EI);
  }
  b.sampled = sample(quadrature_points(b.stations, rule), {clamped_free_mode(1, L, top_mass_ratio)});
  b.integrals = shape_integrals(straight_beam_mass_points(b.sampled, Eigen::Vector3d::UnitZ()));
  return b;
}

Eigen::MatrixXd flex_mass(const FlexBody& b, double g, bool axial_correction, double polar_inertia) {
  const Eigen::VectorXd gv = Eigen::VectorXd::Constant(1, g);
  Eigen::MatrixXd M = body_mass_matrix(b.integrals, gv);
  add_section_inertia(M, polar_inertia);
  // Per unit axial acceleration the outboard mass ∫_x^L m (self_weight_axial_force is −g × that).
  if (axial_correction) apply_axial_inertia_correction(M, b.sampled, gv, self_weight_axial_force(b.stations, -1.0));
  return M;
}

}  // namespace

TurbineMatrices two_bladed_turbine_matrices(const TwoBladedTurbine& t, const Eigen::Vector4d& q) {
  TurbineMatrices out;
  const double blade_mass = t.blade_m * t.blade_length;
  const double top_mass = t.nacelle_mass + t.shaft_mass + 2.0 * blade_mass;  // Sec. 6's M_t
  const FlexBody tower = flex_body(t.tower_length, t.tower_m, t.tower_EI, t.tower_stations,
                                   top_mass / (t.tower_m * t.tower_length), t.rule);
  const FlexBody blade = flex_body(t.blade_length, t.blade_m, t.blade_EI, t.blade_stations, 0.0, t.rule);

  // Body matrices (eq. 2 with eqs. 28–29 and 31; eq. 5 for the rigid bodies).
  out.tower_mass = flex_mass(tower, q(0), t.tower_axial_correction, 0.0);
  out.blade_mass[0] = flex_mass(blade, q(2), t.blade_axial_correction, t.blade_jG * t.blade_length);
  out.blade_mass[1] = flex_mass(blade, q(3), t.blade_axial_correction, t.blade_jG * t.blade_length);
  out.nacelle_mass = rigid_body_mass_matrix(t.nacelle_mass, t.nacelle_cog, t.nacelle_inertia_at_N.asDiagonal());
  out.shaft_mass = rigid_body_mass_matrix(t.shaft_mass, Eigen::Vector3d::Zero(), t.shaft_inertia.asDiagonal());

  // Stiffness (eq. 20) and geometric stiffness (eq. 26): the tower under its top mass and self-weight,
  // a blade pointing up under its self-weight.
  out.tower_stiffness = generalized_stiffness(tower.sampled)(0, 0);
  const AxialForce top = top_mass_axial_force(top_mass, t.gravity);
  const AxialForce self = self_weight_axial_force(tower.stations, t.gravity);
  out.tower_geometric =
      geometric_stiffness(tower.sampled, [top, self](double x) { return top(x) + self(x); })(0, 0);
  out.blade_stiffness = generalized_stiffness(blade.sampled)(0, 0);
  out.blade_geometric = geometric_stiffness(blade.sampled, self_weight_axial_force(blade.stations, t.gravity))(0, 0);

  // Kinematics (eq. 35). Tower tip slope ν_t(L) from the shape at L.
  const ShapeValue tip = clamped_free_mode(1, t.tower_length, top_mass / (t.tower_m * t.tower_length))(t.tower_length);
  const double Cy = -tip.nu;
  out.tower_coupling = Cy;
  const Eigen::Matrix3d R_0n = rot_y(Cy * q(0));
  const Eigen::Matrix3d R_0s = R_0n * rot_z(q(1) + std::numbers::pi);
  using Mat34 = Eigen::Matrix<double, 3, 4>;
  Mat34 Bx_n = Mat34::Zero(), Bt_n = Mat34::Zero();
  Bx_n(2, 0) = tip.u;  // v_N = u_t(L) q̇1 e_z
  Bt_n(1, 0) = Cy;     // ω_N = C_y q̇1 e_y
  const Eigen::Vector3d r_ns = R_0n * Eigen::Vector3d(0.0, 0.0, -t.tower_top_to_shaft);
  Mat34 Bx_s = Bx_n, Bt_s = Bt_n;
  for (int j = 0; j < 4; ++j) Bx_s.col(j) += Bt_n.col(j).cross(r_ns);  // eq. 13
  Bt_s.col(1) = R_0n * Eigen::Vector3d::UnitZ();                         // revolute joint about z_n

  // Eq. 8: M_q = Σ B'ᵀ M' B'. The tower's own rigid motion is zero (clamped at the ground).
  Eigen::MatrixXd B_t = Eigen::MatrixXd::Zero(7, 4);
  B_t(6, 0) = 1.0;
  const Eigen::MatrixXd B_n = body_frame_B(Bx_n, Bt_n, R_0n, -1);
  const Eigen::MatrixXd B_s = body_frame_B(Bx_s, Bt_s, R_0s, -1);
  out.Mq = B_t.transpose() * out.tower_mass * B_t + B_n.transpose() * out.nacelle_mass * B_n +
           B_s.transpose() * out.shaft_mass * B_s;
  Eigen::MatrixXd K_t = Eigen::MatrixXd::Zero(7, 7), K_b = Eigen::MatrixXd::Zero(7, 7);
  K_t(6, 6) = out.tower_stiffness;
  K_b(6, 6) = out.blade_stiffness;
  out.Kq = B_t.transpose() * K_t * B_t;
  for (int i = 0; i < 2; ++i) {
    const Eigen::Matrix3d R_0b = R_0s * rot_z(-i * std::numbers::pi);  // r_SB = 0: B_b = B_s
    const Eigen::MatrixXd B_b = body_frame_B(Bx_s, Bt_s, R_0b, 2 + i);
    out.Mq += B_b.transpose() * out.blade_mass[i] * B_b;
    out.Kq += B_b.transpose() * K_b * B_b;
  }
  return out;
}

}  // namespace fowtsim::flexbody
