#include "section_mechanics.hpp"

#include <Eigen/Geometry>

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/core/rotation_vector.hpp"

namespace fowtsim::beam {
namespace {

struct Kinematics {
  Vec3 d;          // chord x_b − x_a
  Vec3 psi;        // relative rotation vector
  Mat3 r_sec;      // R_j
  Vec6 strain;     // [γ; κ]
};

Kinematics kinematics(const SectionModel& sec, const NodePose& a, const NodePose& b) {
  Kinematics k;
  k.d = b.position_m - a.position_m;
  k.psi = rotation_vector(a.orientation.transpose() * b.orientation);
  k.r_sec = a.orientation * rotation_matrix(sec.alpha * k.psi);
  k.strain.head<3>() = k.r_sec.transpose() * k.d / sec.length_m - sec.chord_ref;
  k.strain.tail<3>() = k.psi / sec.length_m - sec.curvature_ref;
  return k;
}

// [f_a; m_a; f_b; m_b] from the section-frame resultant S.
Vec12 loads_from_resultant(const SectionModel& sec, const Kinematics& k, const Vec6& s) {
  const Vec3 f = k.r_sec * s.head<3>();
  const Vec3 m = k.r_sec * s.tail<3>();
  const Vec3 dxf = k.d.cross(f);
  Vec12 out;
  out << f, m + sec.alpha * dxf, -f, -m + (1.0 - sec.alpha) * dxf;
  return out;
}

}  // namespace

void evaluate_section(const SectionModel& sec, const NodePose& a, const NodePose& b,
                      SectionResult& out) {
  const Kinematics k = kinematics(sec, a, b);
  const double inv_ds = 1.0 / sec.length_m;
  out.strain = k.strain;
  out.resultant = sec.stiffness * k.strain;
  out.node_loads = loads_from_resultant(sec, k, out.resultant);

  // Strain map B (columns u_a, θ_a, u_b, θ_b).
  const Mat3 psi_map = right_jacobian_inverse(k.psi) * b.orientation.transpose();     // Ψ
  const Mat3 p = sec.alpha * k.r_sec * right_jacobian(sec.alpha * k.psi) * psi_map;   // P
  const Mat3 rt = k.r_sec.transpose();
  const Mat3 dt = skew(k.d);
  const Mat3 phi_a = Mat3::Identity() - p;  // δφ_j = Φ_a θ_a + Φ_b θ_b
  const Mat3& phi_b = p;
  Mat6x12& bm = out.strain_map;
  bm.setZero();
  bm.block<3, 3>(0, 0) = -rt * inv_ds;
  bm.block<3, 3>(0, 3) = rt * dt * phi_a * inv_ds;
  bm.block<3, 3>(0, 6) = rt * inv_ds;
  bm.block<3, 3>(0, 9) = rt * dt * phi_b * inv_ds;
  bm.block<3, 3>(3, 3) = -psi_map * inv_ds;
  bm.block<3, 3>(3, 9) = psi_map * inv_ds;

  // G: node loads per unit section resultant S = [N; M]:
  //   f_a = R N,  m_a = α d̃ R N + R M,  f_b = −R N,  m_b = (1−α) d̃ R N − R M.
  // Applied blockwise to C B (and D B): X = R (CB)_N, Y = R (CB)_M, Z = d̃ X — a third of the
  // flops of the dense 12×6 · 6×12 product, which dominates the cost of a step.
  auto apply_g = [&](const Mat6x12& sb, Mat12& out_matrix) {
    const Eigen::Matrix<double, 3, 12> x = k.r_sec * sb.topRows<3>();
    const Eigen::Matrix<double, 3, 12> y = k.r_sec * sb.bottomRows<3>();
    const Eigen::Matrix<double, 3, 12> z = dt * x;
    out_matrix.middleRows<3>(0) = -x;
    out_matrix.middleRows<3>(3) = -(sec.alpha * z + y);
    out_matrix.middleRows<3>(6) = x;
    out_matrix.middleRows<3>(9) = -((1.0 - sec.alpha) * z - y);
  };

  // Geometric part: the loads rotate with the section frame and the moment arm d changes,
  // at fixed resultant: δF = −F̃ δφ_j, δM = −M̃ δφ_j, δ(d × F) = −F̃ δd + d̃ δF.
  const Mat3 ft = skew(out.node_loads.head<3>());
  const Mat3 mt = skew(k.r_sec * out.resultant.tail<3>());
  Mat12 geo = Mat12::Zero();
  for (int side = 0; side < 2; ++side) {  // columns of θ_a (side 0) and θ_b (side 1)
    const Mat3& phi = side == 0 ? phi_a : phi_b;
    const int col = side == 0 ? 3 : 9;
    geo.block<3, 3>(0, col) = -ft * phi;
    geo.block<3, 3>(3, col) = -mt * phi - sec.alpha * dt * ft * phi;
    geo.block<3, 3>(6, col) = ft * phi;
    geo.block<3, 3>(9, col) = mt * phi - (1.0 - sec.alpha) * dt * ft * phi;
  }
  // δd = u_b − u_a enters the moment arms.
  geo.block<3, 3>(3, 0) = sec.alpha * ft;
  geo.block<3, 3>(3, 6) = -sec.alpha * ft;
  geo.block<3, 3>(9, 0) = (1.0 - sec.alpha) * ft;
  geo.block<3, 3>(9, 6) = -(1.0 - sec.alpha) * ft;

  apply_g(sec.stiffness * bm, out.stiffness);  // −G C B
  out.stiffness -= geo;
  apply_g(sec.damping * bm, out.damping);      // −G D B
}

Vec12 section_loads(const SectionModel& sec, const NodePose& a, const NodePose& b,
                    const Vec6* velocity_a, const Vec6* velocity_b) {
  const Kinematics k = kinematics(sec, a, b);
  Vec6 s = sec.stiffness * k.strain;
  if (velocity_a && velocity_b) {
    SectionResult r;
    evaluate_section(sec, a, b, r);
    Vec12 q_dot;
    q_dot << *velocity_a, *velocity_b;
    s += sec.damping * (r.strain_map * q_dot);
  }
  return loads_from_resultant(sec, k, s);
}

}  // namespace fowtsim::beam
