#include "section_mechanics.hpp"

#include <Eigen/Geometry>

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/core/rotation_vector.hpp"

namespace fowtsim::beam {
namespace {

using Mat3x9 = Eigen::Matrix<double, 3, 9>;

// Strains and section frame of the section between poses a and b (header, "Kinematics").
void kinematics(const SectionModel& sec, const NodePose& a, const NodePose& b, Vec3& psi,
                SectionLinearization& out) {
  out.alpha = sec.alpha;
  out.chord = b.position_m - a.position_m;
  psi = rotation_vector(a.orientation.transpose() * b.orientation);
  out.orientation = a.orientation * rotation_matrix(sec.alpha * psi);
  out.strain.head<3>() = out.orientation.transpose() * out.chord / sec.length_m - sec.chord_ref;
  out.strain.tail<3>() = psi / sec.length_m - sec.curvature_ref;
}

}  // namespace

Vec12 node_loads_of(const SectionLinearization& lin, const Vec6& s) {
  const Vec3 f = lin.orientation * s.head<3>();
  const Vec3 m = lin.orientation * s.tail<3>();
  const Vec3 dxf = lin.chord.cross(f);
  Vec12 out;
  out << f, m + lin.alpha * dxf, -f, -m + (1.0 - lin.alpha) * dxf;
  return out;
}

Vec9 reduced(const Vec12& q) {
  Vec9 r;
  r << q.head<3>() - q.segment<3>(6), q.segment<3>(3), q.tail<3>();
  return r;
}

void linearize_section(const SectionModel& sec, const NodePose& a, const NodePose& b,
                       SectionLinearization& out, const Vec6* offset) {
  Vec3 psi;
  kinematics(sec, a, b, psi, out);
  out.resultant = sec.stiffness * out.strain;
  if (offset) out.resultant += *offset;
  out.node_loads = node_loads_of(out, out.resultant);

  // Strain map B on the reduced columns: [−E, E d̃ Φ_a, E d̃ Φ_b; 0, −Y, Y] with E = R_jᵀ/Δs,
  // Y = Ψ/Δs and δφ_j = Φ_a θ_a + Φ_b θ_b, Φ_a = I − P, Φ_b = P.
  const double inv_ds = 1.0 / sec.length_m;
  const Mat3 psi_map = right_jacobian_inverse(psi) * b.orientation.transpose();          // Ψ
  const Mat3 p = sec.alpha * out.orientation * right_jacobian(sec.alpha * psi) * psi_map;  // P
  const Mat3 dt = skew(out.chord);
  const Mat3 e_dt = out.orientation.transpose() * dt * inv_ds;
  Mat6x9& bm = out.strain_map;
  bm.block<3, 3>(0, 0) = -out.orientation.transpose() * inv_ds;
  bm.block<3, 3>(0, 6).noalias() = e_dt * p;
  bm.block<3, 3>(0, 3) = e_dt - bm.block<3, 3>(0, 6);
  bm.block<3, 3>(3, 0).setZero();
  bm.block<3, 3>(3, 6) = psi_map * inv_ds;
  bm.block<3, 3>(3, 3) = -bm.block<3, 3>(3, 6);

  // Geometric part: the loads rotate with the section frame and the moment arm d changes,
  // at fixed resultant: δF = −F̃ δφ_j, δM = −M̃ δφ_j, δ(d × F) = −F̃ δd + d̃ δF.
  const Mat3 ft = skew(out.node_loads.head<3>());
  const Mat3 mt = skew(out.orientation * out.resultant.tail<3>());
  const Mat3 ft_a = ft * (Mat3::Identity() - p), ft_b = ft * p;  // F̃ Φ_a, F̃ Φ_b
  const Mat3 mt_a = mt * (Mat3::Identity() - p), mt_b = mt * p;
  const Mat3 dft_a = dt * ft_a, dft_b = dt * ft_b;
  Mat12x9& geo = out.geometric;
  geo.col(0).setZero();
  geo.col(1).setZero();
  geo.col(2).setZero();
  geo.block<3, 3>(3, 0) = sec.alpha * ft;  // δd = u_b − u_a enters the moment arms
  geo.block<3, 3>(9, 0) = (1.0 - sec.alpha) * ft;
  geo.block<3, 3>(0, 3) = -ft_a;
  geo.block<3, 3>(3, 3) = -mt_a - sec.alpha * dft_a;
  geo.block<3, 3>(6, 3) = ft_a;
  geo.block<3, 3>(9, 3) = mt_a - (1.0 - sec.alpha) * dft_a;
  geo.block<3, 3>(0, 6) = -ft_b;
  geo.block<3, 3>(3, 6) = -mt_b - sec.alpha * dft_b;
  geo.block<3, 3>(6, 6) = ft_b;
  geo.block<3, 3>(9, 6) = mt_b - (1.0 - sec.alpha) * dft_b;
}

void section_tangent(const SectionLinearization& lin, const Mat6& weight, double geometric_weight,
                     Mat12& out) {
  // W B, using the zero block of B: (W B)_{·,u_a} = −W_N E, and so on.
  const Mat6x9& bm = lin.strain_map;
  Mat6x9 sb;
  const auto wn = weight.leftCols<3>();
  const auto wm = weight.rightCols<3>();
  sb.middleCols<3>(0).noalias() = wn * bm.block<3, 3>(0, 0);
  const Eigen::Matrix<double, 6, 3> wy = wm * bm.block<3, 3>(3, 6);
  sb.middleCols<3>(3).noalias() = wn * bm.block<3, 3>(0, 3);
  sb.middleCols<3>(3) -= wy;
  sb.middleCols<3>(6).noalias() = wn * bm.block<3, 3>(0, 6);
  sb.middleCols<3>(6) += wy;

  // −G (W B): X = R (WB)_N, Y = R (WB)_M, Z = d̃ X, rows [−X; −(αZ + Y); X; Y − (1−α)Z].
  const Mat3x9 x = lin.orientation * sb.topRows<3>();
  const Mat3x9 y = lin.orientation * sb.bottomRows<3>();
  Mat3x9 z;
  for (int c = 0; c < 9; ++c) z.col(c) = lin.chord.cross(x.col(c));
  Mat12x9 t;
  t.middleRows<3>(0) = -x;
  t.middleRows<3>(3) = -(lin.alpha * z + y);
  t.middleRows<3>(6) = x;
  t.middleRows<3>(9) = y - (1.0 - lin.alpha) * z;
  if (geometric_weight != 0.0) t -= geometric_weight * lin.geometric;

  out.middleCols<6>(0) = t.leftCols<6>();
  out.middleCols<3>(6) = -t.leftCols<3>();
  out.middleCols<3>(9) = t.rightCols<3>();
}

Vec12 section_residual_loads(const SectionModel& sec, const NodePose& a, const NodePose& b,
                             const Vec9& w_k, const Vec9& w_c, const Vec6* offset) {
  Vec3 psi;
  SectionLinearization k;
  kinematics(sec, a, b, psi, k);
  const Mat3& r_j = k.orientation;
  const Mat3 psi_inverse_jacobian = right_jacobian_inverse(psi);
  const Mat3 section_jacobian = right_jacobian(sec.alpha * psi);
  const double inv_ds = 1.0 / sec.length_m;

  // B w (header, "Increments"): δψ = J_r⁻¹(ψ) R_bᵀ (θ_b − θ_a), δφ_j = θ_a + α R_j J_r(αψ) δψ,
  // δγ = R_jᵀ (δd + d × δφ_j)/Δs with δd = u_b − u_a = −w_0, δκ = δψ/Δs.
  auto strain_increment = [&](const Vec9& w, Vec3& section_rotation) {
    const Vec3 dpsi = psi_inverse_jacobian * (b.orientation.transpose() * (w.tail<3>() - w.segment<3>(3)));
    section_rotation = w.segment<3>(3) + sec.alpha * (r_j * (section_jacobian * dpsi));
    Vec6 e;
    e.head<3>() = r_j.transpose() * (k.chord.cross(section_rotation) - w.head<3>()) * inv_ds;
    e.tail<3>() = dpsi * inv_ds;
    return e;
  };
  Vec3 phi_k, phi_c;
  const Vec6 e_k = strain_increment(w_k, phi_k);
  const Vec6 e_c = strain_increment(w_c, phi_c);
  Vec6 s_base = sec.stiffness * k.strain;
  if (offset) s_base += *offset;
  Vec12 out = node_loads_of(k, s_base + sec.stiffness * e_k + sec.damping * e_c);

  // Geometric part at the base resultant (as in linearize_section): the loads turn with δφ_j and
  // the arm d stretches by δd.
  const Vec3 f = r_j * s_base.head<3>(), m = r_j * s_base.tail<3>();
  const Vec3 arm = f.cross(w_k.head<3>());  // F̃ (u_a − u_b)
  const Vec3 g = f.cross(phi_k), h = m.cross(phi_k), dg = k.chord.cross(g);
  out.segment<3>(0) -= g;
  out.segment<3>(3) += sec.alpha * (arm - dg) - h;
  out.segment<3>(6) += g;
  out.segment<3>(9) += (1.0 - sec.alpha) * (arm - dg) + h;
  return out;
}

Vec12 section_loads(const SectionModel& sec, const NodePose& a, const NodePose& b,
                    const Vec6* velocity_a, const Vec6* velocity_b, const Vec6* offset) {
  SectionLinearization lin;
  linearize_section(sec, a, b, lin, offset);
  if (!velocity_a || !velocity_b) return lin.node_loads;
  Vec12 q_dot;
  q_dot << *velocity_a, *velocity_b;
  return node_loads_of(lin, lin.resultant + sec.damping * (lin.strain_map * reduced(q_dot)));
}

}  // namespace fowtsim::beam
