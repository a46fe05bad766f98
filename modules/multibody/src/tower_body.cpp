#include "fowtsim/multibody/tower_body.hpp"

#include <algorithm>

#include "fowtsim/core/rotation.hpp"

namespace fowtsim::multibody {
namespace {

// The integrals at deflection q, in b: s = ∫m ρ, A_j = ∫m φ_j ρ, P = ∫m ρ ρᵀ (ρ = p + Σ q_j φ_j d_j,
// expanded with TowerInertia's q-independent integrals).
struct Deflected {
  Vec3 s = Vec3::Zero();
  std::array<Vec3, kMaxTowerModes> a{};
  Mat3 p = Mat3::Zero();
};

Deflected deflected_integrals(const FlexibleTower& tower, const TowerInertia& in, const State& state) {
  Deflected d;
  d.s = in.first_moment_kg_m;
  d.p = in.second_moment_kg_m2;
  const auto& q = state.tower_deflection_m;
  for (int j = 0; j < tower.mode_count; ++j) {
    const Vec3& dj = tower.direction_b[j];
    d.s += q[j] * in.shape_mass_kg[j] * dj;
    d.p += q[j] * (in.shape_moment_kg_m[j] * dj.transpose() + dj * in.shape_moment_kg_m[j].transpose());
    d.a[j] = in.shape_moment_kg_m[j];
    for (int i = 0; i < tower.mode_count; ++i) {
      d.a[j] += q[i] * in.shape_product_kg(j, i) * tower.direction_b[i];
      d.p += q[i] * q[j] * in.shape_product_kg(i, j) * tower.direction_b[i] * dj.transpose();
    }
  }
  return d;
}

// ∫ m (ρ·ρ 1 − ρ ρᵀ) from P = ∫ m ρ ρᵀ.
Mat3 inertia_from_second_moment(const Mat3& p) { return p.trace() * Mat3::Identity() - p; }

}  // namespace

void add_tower_mass(const Model& model, const TowerInertia& in, const State& state, const ChainKinematics& chain,
                    GeneralisedMatrix& mass) {
  const FlexibleTower& tower = model.flexible_tower;
  const Deflected d = deflected_integrals(tower, in, state);
  const Mat3& t_gb = chain.base.orientation;
  const Jacobian& a = chain.reference.jacobian;
  const Jacobian& b = chain.base.jacobian;
  // v_k = a u − (T_gb ρ_k)~ b u + Σ_j φ_kj T_gb d_j u_j: the sum of m J_kᵀ J_k, block by block.
  const Mat3 s_skew = skew(t_gb * d.s);
  const Mat3 inertia = t_gb * inertia_from_second_moment(d.p) * t_gb.transpose();
  Jacobian modal_force = Jacobian::Zero();   // columns ∫m φ_j T_gb d_j
  Jacobian modal_moment = Jacobian::Zero();  // columns ∫m (T_gb ρ) × φ_j T_gb d_j = T_gb (A_j × d_j)
  for (int j = 0; j < tower.mode_count; ++j) {
    modal_force.col(kTower + j) = in.shape_mass_kg[j] * (t_gb * tower.direction_b[j]);
    modal_moment.col(kTower + j) = t_gb * d.a[j].cross(tower.direction_b[j]);
    for (int i = 0; i < tower.mode_count; ++i)
      mass(kTower + i, kTower + j) += in.shape_product_kg(i, j) * tower.direction_b[i].dot(tower.direction_b[j]);
  }
  const Jacobian linear = in.mass_kg * a - s_skew * b + modal_force;  // ∫ m v_k per unit u
  mass.noalias() += a.transpose() * linear + linear.transpose() * a - in.mass_kg * a.transpose() * a;
  mass.noalias() += b.transpose() * (inertia * b + modal_moment) + modal_moment.transpose() * b;
}

TowerDAlembert tower_dalembert(const Model& model, const TowerInertia& in, const State& state,
                               const ChainKinematics& chain, const GeneralisedVector& udot, const Vec3& gravity) {
  const FlexibleTower& tower = model.flexible_tower;
  const Deflected d = deflected_integrals(tower, in, state);
  const Mat3& t_gb = chain.base.orientation;
  const Vec3& w = chain.base.angular_velocity_rad_s;
  const Vec3 alpha = angular_acceleration(chain.base, udot);
  const Vec3 free = gravity - acceleration(chain.reference, udot);  // g − a_r
  const Vec3 s = t_gb * d.s;
  const Mat3 inertia = t_gb * inertia_from_second_moment(d.p) * t_gb.transpose();
  const auto& qd = state.tower_deflection_rate_m_s;
  // a_k = a_r + α × x_k + ω × (ω × x_k) + Σ_j φ_kj (D_j q̈_j + 2 ω × D_j q̇_j), x_k = T_gb ρ_k, D_j = T_gb d_j.
  std::array<Vec3, kMaxTowerModes> relative{};  // D_j q̈_j + 2 ω × D_j q̇_j
  std::array<Vec3, kMaxTowerModes> direction{}, shape_moment{};
  for (int j = 0; j < tower.mode_count; ++j) {
    direction[j] = t_gb * tower.direction_b[j];
    shape_moment[j] = t_gb * d.a[j];
    relative[j] = direction[j] * udot[kTower + j] + 2.0 * w.cross(direction[j] * qd[j]);
  }
  TowerDAlembert out;
  out.force_N = in.mass_kg * free - alpha.cross(s) - w.cross(w.cross(s));
  out.moment_N_m = s.cross(free) - inertia * alpha - w.cross(inertia * w);
  for (int j = 0; j < tower.mode_count; ++j) {
    out.force_N -= in.shape_mass_kg[j] * relative[j];
    // ∫ m φ_kj x_k × (D_j q̈_j + 2 ω × D_j q̇_j), with x × (ω × D) = ω (x·D) − D (x·ω).
    const Vec3& aj = shape_moment[j];
    out.moment_N_m -= udot[kTower + j] * aj.cross(direction[j]) +
                      2.0 * qd[j] * (w * aj.dot(direction[j]) - direction[j] * aj.dot(w));
    Vec3 modal = in.shape_mass_kg[j] * free - alpha.cross(aj) - w.cross(w.cross(aj));
    for (int i = 0; i < tower.mode_count; ++i) modal -= in.shape_product_kg(j, i) * relative[i];
    out.modal_N[j] = direction[j].dot(modal);
  }
  return out;
}

TowerMassProperties tower_mass_properties(const Model& model, const TowerInertia& in, const State& state) {
  const Deflected d = deflected_integrals(model.flexible_tower, in, state);
  return {in.mass_kg, d.s, inertia_from_second_moment(d.p)};
}

TowerMomentum tower_momentum(const Model& model, const TowerInertia& in, const State& state,
                             const ChainKinematics& chain) {
  const FlexibleTower& tower = model.flexible_tower;
  const Deflected d = deflected_integrals(tower, in, state);
  const Mat3& t_gb = chain.base.orientation;
  const Vec3& w = chain.base.angular_velocity_rad_s;
  const Vec3& v_r = chain.reference.velocity_m_s;
  const Vec3 s = t_gb * d.s;
  const Mat3 inertia = t_gb * inertia_from_second_moment(d.p) * t_gb.transpose();
  TowerMomentum out;
  out.linear_N_s = in.mass_kg * v_r + w.cross(s);
  out.angular_N_m_s = s.cross(v_r) + inertia * w;
  for (int j = 0; j < tower.mode_count; ++j) {
    const Vec3 dj = t_gb * tower.direction_b[j];
    const double rate = state.tower_deflection_rate_m_s[j];
    out.linear_N_s += in.shape_mass_kg[j] * rate * dj;
    out.angular_N_m_s += rate * (t_gb * d.a[j]).cross(dj);
  }
  // About the origin of g rather than r: x_k = r + T_gb ρ_k.
  out.angular_N_m_s += chain.reference.position_m.cross(out.linear_N_s);
  return out;
}

PointKinematics tower_point(const Model& model, const State& state, const ChainKinematics& chain, double height_m) {
  const FlexibleTower& tower = model.flexible_tower;
  const Mat3& t_gb = chain.base.orientation;
  Vec3 at = model.tower_base_b + Vec3(0.0, 0.0, height_m);
  const double on_tower = std::clamp(height_m, 0.0, model.tower_top_b.z() - model.tower_base_b.z());
  std::array<double, kMaxTowerModes> phi{};
  for (int j = 0; j < tower.mode_count; ++j) {
    phi[j] = tower.shape[j].value(on_tower);
    at += state.tower_deflection_m[j] * phi[j] * tower.direction_b[j];
  }
  PointKinematics p = point_on(chain.reference, chain.base, chain.reference.position_m + t_gb * at);
  // Relative velocity T_gb Σ φ_j d_j q̇_j, its Jacobian columns, and the Coriolis bias 2 ω × v_rel
  // (φ is fixed in b, so the relative acceleration has no bias of its own).
  Vec3 relative = Vec3::Zero();
  for (int j = 0; j < tower.mode_count; ++j) {
    const Vec3 column = t_gb * (phi[j] * tower.direction_b[j]);
    p.jacobian.col(kTower + j) += column;
    relative += state.tower_deflection_rate_m_s[j] * column;
  }
  p.velocity_m_s += relative;
  p.bias_acceleration_m_s2 += 2.0 * chain.base.angular_velocity_rad_s.cross(relative);
  return p;
}

Vec3 tower_deflection(const Model& model, const State& state, double height_m) {
  const FlexibleTower& tower = model.flexible_tower;
  Vec3 d = Vec3::Zero();
  for (int j = 0; j < tower.mode_count; ++j) d += state.tower_deflection_m[j] * tower.shape[j].value(height_m) * tower.direction_b[j];
  return d;
}

Mat3 tower_section_orientation(const Model& model, const State& state, const Mat3& t_gb, double height_m) {
  const FlexibleTower& tower = model.flexible_tower;
  if (tower.mode_count == 0) return t_gb;
  double theta_x = 0.0, theta_y = 0.0;
  for (int j = 0; j < tower.mode_count; ++j) {
    const double turn = tower.shape[j].slope(height_m) * state.tower_deflection_m[j];
    if (j < tower.fore_aft_count) theta_y += turn;
    else theta_x -= turn;
  }
  return t_gb * rotation_x(theta_x) * rotation_y(theta_y);
}

double TowerModeShape::value(double height_m) const {
  const double x = height_m / length_m;
  double v = 0.0;
  for (int k = 6; k >= 2; --k) v = (v + coefficients[k - 2]) * x;  // Horner, then one more × x
  return v * x;
}

double TowerModeShape::slope(double height_m) const {
  const double x = height_m / length_m;
  double v = 0.0;
  for (int k = 6; k >= 2; --k) v = v * x + k * coefficients[k - 2];
  return v * x / length_m;
}

}  // namespace fowtsim::multibody
