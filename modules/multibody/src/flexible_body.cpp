#include "fowtsim/multibody/flexible_body.hpp"

#include "fowtsim/core/rotation.hpp"

namespace fowtsim::multibody {
namespace {

// ∫ a × b from B = ∫ a bᵀ.
Vec3 cross_of(const Mat3& b) { return Vec3(b(1, 2) - b(2, 1), b(2, 0) - b(0, 2), b(0, 1) - b(1, 0)); }

// The integrals at the body's deflection, in k: s = ∫m ρ, P = ∫m ρ ρᵀ and B_j = ∫m ρ φ_jᵀ
// (ρ = p + Σ q_i φ_i, expanded with ShapeIntegrals' q-independent integrals).
struct Deflected {
  Vec3 s = Vec3::Zero();
  Mat3 p = Mat3::Zero();
  std::array<Mat3, kMaxBodyModes> b{};
};

Deflected deflected(const ShapeIntegrals& in, const FlexibleBodyMotion& body) {
  Deflected d;
  d.s = in.first_moment_kg_m;
  d.p = in.second_moment_kg_m2;
  const auto& q = body.q;
  for (int j = 0; j < body.mode_count; ++j) {
    d.s += q[j] * in.shape_mass_kg[j];
    d.p += q[j] * (in.shape_moment_kg_m[j] + in.shape_moment_kg_m[j].transpose());
    d.b[j] = in.shape_moment_kg_m[j].transpose();
    for (int i = 0; i < body.mode_count; ++i) {
      d.b[j] += q[i] * in.shape_product_kg[i][j];
      d.p += q[i] * q[j] * in.shape_product_kg[i][j];
    }
  }
  return d;
}

// ∫ m (ρ·ρ 1 − ρ ρᵀ) from P = ∫ m ρ ρᵀ.
Mat3 inertia_from_second_moment(const Mat3& p) { return p.trace() * Mat3::Identity() - p; }

}  // namespace

void add_flexible_body_mass(const ShapeIntegrals& in, const FlexibleBodyMotion& body, GeneralisedMatrix& mass) {
  const Deflected d = deflected(in, body);
  const Mat3& t = body.orientation;
  // The chain's Jacobians touch only its first kBlade columns (kinematics.hpp): the products run
  // over those (a 12 × 12 block), and a body whose modes lie beyond them (a blade) adds its coupling
  // columns separately — a third of the work of the full 21 × 21 products.
  constexpr int kChain = kBlade;
  using ChainJacobian = Eigen::Matrix<double, 3, kChain>;
  const ChainJacobian a = body.origin->jacobian.leftCols<kChain>();
  const ChainJacobian b = body.rotation->jacobian.leftCols<kChain>();
  // v_k = a u − (T ρ_k)~ b u + Σ_j T φ_kj u_j: the sum of m J_kᵀ J_k, block by block.
  const Mat3 s_skew = skew(t * d.s);
  const Mat3 inertia = t * inertia_from_second_moment(d.p) * t.transpose();
  Eigen::Matrix<double, 3, kMaxBodyModes> modal_force, modal_moment;  // ∫m T φ_j and ∫m (T ρ) × T φ_j
  for (int j = 0; j < body.mode_count; ++j) {
    modal_force.col(j) = t * in.shape_mass_kg[j];
    modal_moment.col(j) = t * cross_of(d.b[j]);
    for (int i = 0; i < body.mode_count; ++i) mass(body.first_dof + i, body.first_dof + j) += in.shape_product_kg[i][j].trace();
  }
  ChainJacobian linear = in.mass_kg * a - s_skew * b;  // ∫ m v_k per unit u, chain columns
  ChainJacobian rotary = inertia * b;
  const bool inside = body.first_dof < kChain;  // the tower's modes are chain columns, a blade's are not
  if (inside) {
    for (int j = 0; j < body.mode_count; ++j) {
      linear.col(body.first_dof + j) += modal_force.col(j);
      rotary.col(body.first_dof + j) += modal_moment.col(j);
    }
  }
  ChainJacobian moment_columns = ChainJacobian::Zero();  // modal_moment placed in the chain columns
  if (inside)
    for (int j = 0; j < body.mode_count; ++j) moment_columns.col(body.first_dof + j) = modal_moment.col(j);
  // Coefficient-based products (small fixed sizes).
  mass.topLeftCorner<kChain, kChain>().noalias() += a.transpose().lazyProduct(linear - in.mass_kg * a) + linear.transpose().lazyProduct(a);
  mass.topLeftCorner<kChain, kChain>().noalias() += b.transpose().lazyProduct(rotary) + moment_columns.transpose().lazyProduct(b);
  if (!inside) {
    for (int j = 0; j < body.mode_count; ++j) {
      const Eigen::Matrix<double, kChain, 1> coupling = a.transpose() * modal_force.col(j) + b.transpose() * modal_moment.col(j);
      mass.block<kChain, 1>(0, body.first_dof + j) += coupling;
      mass.block<1, kChain>(body.first_dof + j, 0) += coupling.transpose();
    }
  }
}

FlexibleBodyDAlembert flexible_body_dalembert(const ShapeIntegrals& in, const FlexibleBodyMotion& body,
                                              const GeneralisedVector& udot, const Vec3& gravity) {
  const Deflected d = deflected(in, body);
  const Mat3& t = body.orientation;
  const Vec3& w = body.rotation->angular_velocity_rad_s;
  const Vec3 w_k = t.transpose() * w;
  const Vec3 alpha = angular_acceleration(*body.rotation, udot);
  const Vec3 free = gravity - acceleration(*body.origin, udot);  // g − a_O
  const Vec3 s = t * d.s;
  const Mat3 inertia = t * inertia_from_second_moment(d.p) * t.transpose();
  // a_k = a_O + α × x_k + ω × (ω × x_k) + Σ_j (D_kj q̈_j + 2 ω × D_kj q̇_j), x_k = T ρ_k, D_kj = T φ_kj.
  FlexibleBodyDAlembert out;
  out.force_N = in.mass_kg * free - alpha.cross(s) - w.cross(w.cross(s));
  out.moment_N_m = s.cross(free) - inertia * alpha - w.cross(inertia * w);
  for (int j = 0; j < body.mode_count; ++j) {
    const double qdd = udot[body.first_dof + j], qd = body.q_rate[j];
    const Vec3 c = t * in.shape_mass_kg[j];
    out.force_N -= qdd * c + 2.0 * qd * w.cross(c);
    // ∫ m x_k × (D_kj q̈_j + 2 ω × D_kj q̇_j), with ∫ x × (ω × D) = ω tr B − T Bᵀ Tᵀ ω.
    out.moment_N_m -= qdd * (t * cross_of(d.b[j])) + 2.0 * qd * (w * d.b[j].trace() - t * (d.b[j].transpose() * w_k));
    // ∫ m D_kj · (g − a_k): ∫ φ·(α × ρ) = α·∫ ρ × φ, ∫ φ·(ω × (ω × ρ)) = ωᵀ B ω − ω² tr B,
    // ∫ φ_j·(ω × φ_i) = ω·∫ φ_i × φ_j.
    double modal = c.dot(free) - alpha.dot(t * cross_of(d.b[j])) - (w_k.dot(d.b[j] * w_k) - w_k.squaredNorm() * d.b[j].trace());
    for (int i = 0; i < body.mode_count; ++i) {
      const Mat3& g = in.shape_product_kg[i][j];
      modal -= g.trace() * udot[body.first_dof + i] + 2.0 * body.q_rate[i] * w_k.dot(cross_of(g));
    }
    out.modal_N[j] = modal;
  }
  return out;
}

FlexibleBodyMassProperties flexible_body_mass_properties(const ShapeIntegrals& in, const FlexibleBodyMotion& body) {
  const Deflected d = deflected(in, body);
  return {in.mass_kg, d.s, inertia_from_second_moment(d.p)};
}

FlexibleBodyMomentum flexible_body_momentum(const ShapeIntegrals& in, const FlexibleBodyMotion& body) {
  const Deflected d = deflected(in, body);
  const Mat3& t = body.orientation;
  const Vec3& w = body.rotation->angular_velocity_rad_s;
  const Vec3& v_o = body.origin->velocity_m_s;
  const Vec3 s = t * d.s;
  const Mat3 inertia = t * inertia_from_second_moment(d.p) * t.transpose();
  FlexibleBodyMomentum out;
  out.linear_N_s = in.mass_kg * v_o + w.cross(s);
  out.angular_N_m_s = s.cross(v_o) + inertia * w;
  for (int j = 0; j < body.mode_count; ++j) {
    out.linear_N_s += body.q_rate[j] * (t * in.shape_mass_kg[j]);
    out.angular_N_m_s += body.q_rate[j] * (t * cross_of(d.b[j]));
  }
  // About the origin of g rather than O: x_k = x_O + T ρ_k.
  out.angular_N_m_s += body.origin->position_m.cross(out.linear_N_s);
  return out;
}

PointKinematics flexible_body_point(const FlexibleBodyMotion& body, const Vec3& p,
                                    const std::array<Vec3, kMaxBodyModes>& shape) {
  const Mat3& t = body.orientation;
  Vec3 rho = p;
  for (int j = 0; j < body.mode_count; ++j) rho += body.q[j] * shape[j];
  PointKinematics k = point_on(*body.origin, *body.rotation, body.origin->position_m + t * rho);
  Vec3 relative = Vec3::Zero();
  for (int j = 0; j < body.mode_count; ++j) {
    const Vec3 column = t * shape[j];
    k.jacobian.col(body.first_dof + j) += column;
    relative += body.q_rate[j] * column;
  }
  k.velocity_m_s += relative;
  k.bias_acceleration_m_s2 += 2.0 * body.rotation->angular_velocity_rad_s.cross(relative);
  return k;
}

PointMotion flexible_body_point_motion(const FlexibleBodyMotion& body, const Vec3& p,
                                       const std::array<Vec3, kMaxBodyModes>& shape) {
  Vec3 rho = p, relative = Vec3::Zero();
  for (int j = 0; j < body.mode_count; ++j) {
    rho += body.q[j] * shape[j];
    relative += body.q_rate[j] * shape[j];
  }
  const Vec3 arm = body.orientation * rho;
  return {body.origin->position_m + arm,
          body.origin->velocity_m_s + body.rotation->angular_velocity_rad_s.cross(arm) + body.orientation * relative};
}

}  // namespace fowtsim::multibody
