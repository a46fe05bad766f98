#include "fowtsim/mooring/stiffness.hpp"

#include <cmath>

#include <Eigen/LU>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/core/rotation_vector.hpp"
#include "line_solution.hpp"

namespace fowtsim::mooring {
namespace {

// Lateral stiffness H/X of an exactly vertical line lifted off the seabed (V_A > 0): the X → 0
// limit of the suspended span equation, X ≈ H [ln(V/V_A)/w + L/EA].
double vertical_lateral_stiffness(const CatenaryLine& line, const CatenarySolution& sol) {
  if (!(sol.anchor_v_N > 0.0)) return 0.0;  // hanging into a U or onto a heap: no restoring H
  return 1.0 / (std::log(sol.fairlead_v_N / sol.anchor_v_N) / line.weight_per_length_N_m +
                line.unstretched_length_m / line.ea_N);
}

// −∂F/∂p_F of one catenary line (3×3, g): the 2-D stiffness in the vertical plane of the line
// plus the lateral stiffness H/X of turning that plane about the anchor.
Mat3 catenary_line_stiffness(const CatenaryLine& line, const CatenarySolution& sol, const detail::LineGeometry& g) {
  const Vec3 eh = g.horizontal_unit, ez = Vec3::UnitZ();
  Mat3 horizontal_plane = Mat3::Identity();
  horizontal_plane(2, 2) = 0.0;
  const Eigen::Matrix2d& k2 = sol.stiffness;  // ∂(H, V)/∂(X, Z)
  Mat3 k = ez * ez.transpose() * k2(1, 1);
  if (sol.regime == CatenaryRegime::vertical) return k + vertical_lateral_stiffness(line, sol) * horizontal_plane;
  k += eh * (k2(0, 0) * eh.transpose() + k2(0, 1) * ez.transpose()) + ez * (k2(1, 0) * eh.transpose());
  if (g.span_x_m > 0.0) k += sol.fairlead_h_N / g.span_x_m * (horizontal_plane - eh * eh.transpose());
  return k;
}

// −∂F/∂p_F of a taut spring: EA/L along the chord, T/|d| across it; nothing when slack.
Mat3 taut_line_stiffness(const LineParams& line, const detail::LineGeometry& g, const LineOutput& out) {
  const double length = g.chord_m.norm();
  if (out.slack || length <= 0.0) return Mat3::Zero();
  const Vec3 u = g.chord_m / length;
  const Mat3 along = u * u.transpose();
  return line.ea_N / line.unstretched_length_m * along + out.fairlead_tension_N / length * (Mat3::Identity() - along);
}

Vec6 total_load(const MooringParams& p, const QuasiStaticMooring::Input& u, const QuasiStaticMooring::State& s) {
  QuasiStaticMooring::State scratch = s;
  const QuasiStaticMooring::Output y = QuasiStaticMooring::evaluate(p, u, scratch);
  Vec6 load;
  load << y.force_N, y.moment_N_m;
  return load;
}

}  // namespace

Mat6 linearized_stiffness(const MooringParams& p, const QuasiStaticMooring::Input& u,
                          const QuasiStaticMooring::State& s) {
  detail::check_pose(u.platform, u.time_s);
  Mat6 k = Mat6::Zero();
  for (std::size_t i = 0; i < p.lines.size(); ++i) {
    const detail::LineGeometry g = detail::line_geometry(p, i, u.platform);
    const detail::SolvedLine solved = detail::solve_line(p, i, g, s.lines[i], u.time_s);
    const Mat3 kl = p.model == LineModel::taut ? taut_line_stiffness(p.lines[i], g, solved.output)
                                               : catenary_line_stiffness(catenary_line(p, i), solved.catenary, g);
    // δp_F = δx − r̃ δθ;  F = −k_l δp_F;  M = r × F with δr = −r̃ δθ.
    const Mat3 r = skew(g.lever_m), f = skew(solved.output.force_N);
    k.block<3, 3>(0, 0) += kl;
    k.block<3, 3>(0, 3) -= kl * r;
    k.block<3, 3>(3, 0) += r * kl;
    k.block<3, 3>(3, 3) -= r * kl * r + f * r;
  }
  if (p.delta_yaw_stiffness_N_m_rad > 0.0) {
    // M_z = −k ψ; ∂θ_Euler/∂δθ = E(θ)⁻¹ T_gbᵀ (ω_b = E θ̇, ω_b = T_gbᵀ ω_g).
    const Mat3& t = u.platform.orientation;
    const Vec3 theta = matrix_to_euler123(t);
    if (std::abs(std::cos(theta.y())) < 1e-9) {
      throw NumericalError({"mooring", u.time_s, "platform pitch (Euler θ₂)", "the yaw spring needs |pitch| < 90°"},
                           "yaw-spring stiffness undefined at gimbal lock");
    }
    const Mat3 d_theta = euler123_rate_matrix(theta).inverse() * t.transpose();
    k.block<1, 3>(5, 3) += p.delta_yaw_stiffness_N_m_rad * d_theta.row(2);
  }
  return k;
}

Mat6 linearized_stiffness_finite_difference(const MooringParams& p, const QuasiStaticMooring::Input& u,
                                            const QuasiStaticMooring::State& s, double translation_step_m,
                                            double rotation_step_rad) {
  QuasiStaticMooring::State base = s;
  QuasiStaticMooring::evaluate(p, u, base);  // warm start every perturbed solve from the base pose
  Mat6 k;
  for (int j = 0; j < 6; ++j) {
    QuasiStaticMooring::Input plus = u, minus = u;
    const double h = j < 3 ? translation_step_m : rotation_step_rad;
    if (j < 3) {
      plus.platform.position_m[j] += h;
      minus.platform.position_m[j] -= h;
    } else {
      plus.platform.orientation = rotation_matrix(h * Vec3::Unit(j - 3)) * u.platform.orientation;
      minus.platform.orientation = rotation_matrix(-h * Vec3::Unit(j - 3)) * u.platform.orientation;
    }
    k.col(j) = -(total_load(p, plus, base) - total_load(p, minus, base)) / (2.0 * h);
  }
  return k;
}

}  // namespace fowtsim::mooring
