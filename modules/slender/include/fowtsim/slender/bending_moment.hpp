#pragma once
// Bending moment two ways (seed 004, slide "Bending Moment"):
//  - elastic: M = EI v'' = EI Φ'' q, where the shapes have curvature;
//  - inertia relief: the moment of every force on the part of the body above x, in dynamic
//    equilibrium (d'Alembert), which also works for rigid bodies (Φ'' = 0).
// Both are templates over the scalar so the same code serves time series (double) and complex
// amplitudes (std::complex<double>).
//
// Inertia relief, derived (the slide's F_i = F_wave − m v̈ − T_eff v'' + T_eff' v' has a garbled
// sign: the tension's transverse load per length is +(T_eff v')' = T v'' + T' v'). The beam obeys
// (EI v'')'' = p + (T v')' with p = f_wave − m v̈ (− α m v̇ for mass-proportional damping).
// Integrating twice from the top end, where the natural conditions are M(L) = −k_θ v'(L) and
// M'(L) = T(L) v'(L) − F_top (F_top = −k v(L), plus the support reaction R of a pinned top):
//   M(x) = ∫_x^L (s − x) p(s) ds − ∫_x^L T v' ds + (L − x) F_top − k_θ v'(L).
// Integrated by parts, −∫T v' is the moment of the weight and buoyancy (T' per length) and of the
// top tension about the deflected point: the P–Δ effect. The slide's Σ x_i F_i is the first
// integral; the seed's T v'' form is the second one before the integration by parts. Strips
// above x count whole (arm x_i − x, the midpoint rule); the strip holding x counts its upper half
// (arm Δx/4). A pinned top's R follows from M(0) = 0. Structural damping βK is internal: the
// inertia-relief moment then includes its viscous part βEI v̇'', the elastic moment does not.
#include "fowtsim/slender/model.hpp"

#include <complex>

namespace fowtsim::slender {

template <class Scalar>
using ColumnOf = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;

// EI v'' at the strip midpoints (N) for generalised displacements q (n), into `moment` (N) with
// `curvature` (N) as workspace: no allocation (the time domain's output at every step).
template <class Scalar>
void elastic_moment_into(const Model& model, const ColumnOf<Scalar>& q, ColumnOf<Scalar>& curvature, ColumnOf<Scalar>& moment) {
  curvature.noalias() = model.phi_curvature.template cast<Scalar>() * q;
  moment = model.strips.bending_stiffness_N_m2.template cast<Scalar>().cwiseProduct(curvature);
}

template <class Scalar>
ColumnOf<Scalar> elastic_moment(const Model& model, const ColumnOf<Scalar>& q) {
  ColumnOf<Scalar> curvature(model.strips.x_m.size()), moment(model.strips.x_m.size());
  elastic_moment_into(model, q, curvature, moment);
  return moment;
}

// Inertia-relief moment at the strip midpoints (N), from the load per length p (N) [N/m]
// (wave force − inertia − external damping), the generalised displacements q (n) and r = q̈ + α q̇
// (n), the generalised inertia the point masses' d'Alembert forces −m_p φ(x_p)·r and moments
// −J_p φ'(x_p)·r act with (α: mass-proportional damping). Point springs act with −k v(x_p) and
// −k_θ v'(x_p). A point above x has arm x_p − x.
//
// A clamped top (a hanging body, free bottom) has an unknown reaction force and moment at the top:
// the sum then runs from the bottom end instead, whose natural conditions are known,
//   M(x) = ∫_0^x (x − s) p ds + ∫_0^x T v' ds + x F_bottom + k_θ v'(0) + Σ_{x_p < x} [(x − x_p) F_p − C_p],
// the mirror image of the top form (x → L − x turns v' and a point moment's sense).
//
// `slope` is v' = Φ' q at the strip midpoints (N): the caller that has it for many q at once
// (a spectrum's frequencies) passes it; inertia_relief_moment below forms it. Writes `moment` (N,
// sized by the caller) without allocating: the point loads are formed where they are summed.
template <class Scalar, class Slope>
void inertia_relief_moment_into(const Model& model, const ColumnOf<Scalar>& load_N_m, const Slope& slope,
                                const ColumnOf<Scalar>& q, const ColumnOf<Scalar>& inertial_q, ColumnOf<Scalar>& moment) {
  const StripTable& s = model.strips;
  const auto N = s.x_m.size();
  // Point p (springs, then masses): where it is, its force F_p and its moment C_p.
  const auto springs = model.body.point_springs.size(), points = springs + model.body.point_masses.size();
  const auto point_x = [&](std::size_t p) {
    return p < springs ? model.body.point_springs[p].x_m : model.body.point_masses[p - springs].x_m;
  };
  const auto point_force = [&](std::size_t p) -> Scalar {
    if (p < springs)
      return -model.body.point_springs[p].translational_N_m *
             (model.phi_springs.row(static_cast<Eigen::Index>(p)).template cast<Scalar>() * q)(0);
    const auto row = static_cast<Eigen::Index>(p - springs);
    return -model.body.point_masses[p - springs].mass_kg * (model.phi_masses.row(row).template cast<Scalar>() * inertial_q)(0);
  };
  const auto point_moment = [&](std::size_t p) -> Scalar {
    if (p < springs)
      return -model.body.point_springs[p].rotational_N_m_rad *
             (model.phi_springs_slope.row(static_cast<Eigen::Index>(p)).template cast<Scalar>() * q)(0);
    const auto row = static_cast<Eigen::Index>(p - springs);
    return -model.body.point_masses[p - springs].rotary_inertia_kg_m2 *
           (model.phi_masses_slope.row(row).template cast<Scalar>() * inertial_q)(0);
  };

  if (model.body.top_support == Support::Clamped) {  // from the free bottom (make_model: no bottom springs)
    Scalar first_moment = Scalar(0), resultant = Scalar(0), tension_term = Scalar(0);  // Σ x_i p_i Δx, Σ p_i Δx, Σ T v' Δx below
    for (Eigen::Index j = 0; j < N; ++j) {
      const double dx = s.dx_m(j), x = s.x_m(j);
      moment(j) = x * resultant - first_moment + tension_term + load_N_m(j) * (dx * dx / 8.0) +
                  s.effective_tension_N(j) * slope(j) * (dx / 2.0);
      for (std::size_t p = 0; p < points; ++p)
        if (point_x(p) < x) moment(j) += (x - point_x(p)) * point_force(p) - point_moment(p);
      first_moment += x * load_N_m(j) * dx;
      resultant += load_N_m(j) * dx;
      tension_term += s.effective_tension_N(j) * slope(j) * dx;
    }
    return;
  }

  const Scalar v_top = model.phi_top.template cast<Scalar>().dot(q);
  const Scalar slope_top = model.phi_top_slope.template cast<Scalar>().dot(q);
  const EndSprings& end_springs = model.body.top_springs;
  const Scalar top_moment = -end_springs.rotational_N_m_rad * slope_top;
  Scalar top_force = -end_springs.translational_N_m * v_top;
  // Σ over whole strips above x_j, by suffix sums: Σ x_i p_i Δx, Σ p_i Δx and Σ T_i v'_i Δx.
  Scalar first_moment = Scalar(0), resultant = Scalar(0), tension_term = Scalar(0);
  for (Eigen::Index j = N - 1; j >= 0; --j) {
    const double dx = s.dx_m(j), x = s.x_m(j);
    moment(j) = first_moment - x * resultant - tension_term + load_N_m(j) * (dx * dx / 8.0) -
                s.effective_tension_N(j) * slope(j) * (dx / 2.0);
    for (std::size_t p = 0; p < points; ++p)
      if (point_x(p) > x) moment(j) += (point_x(p) - x) * point_force(p) + point_moment(p);
    first_moment += x * load_N_m(j) * dx;
    resultant += load_N_m(j) * dx;
    tension_term += s.effective_tension_N(j) * slope(j) * dx;
  }
  if (model.body.top_support == Support::Pinned) {
    // M(0) = first_moment − tension_term + Σ_p (x_p F_p + C_p) + L (F_top + R) + top_moment = 0.
    Scalar point_sum = Scalar(0);
    for (std::size_t p = 0; p < points; ++p) point_sum += point_x(p) * point_force(p) + point_moment(p);
    top_force = -(first_moment - tension_term + point_sum + top_moment) / model.length_m;
  }
  for (Eigen::Index j = 0; j < N; ++j) moment(j) += (model.length_m - s.x_m(j)) * top_force + top_moment;
}

template <class Scalar, class Slope>
ColumnOf<Scalar> inertia_relief_moment_with_slope(const Model& model, const ColumnOf<Scalar>& load_N_m, const Slope& slope,
                                                  const ColumnOf<Scalar>& q, const ColumnOf<Scalar>& inertial_q) {
  ColumnOf<Scalar> moment(model.strips.x_m.size());
  inertia_relief_moment_into(model, load_N_m, slope, q, inertial_q, moment);
  return moment;
}

template <class Scalar>
ColumnOf<Scalar> inertia_relief_moment(const Model& model, const ColumnOf<Scalar>& load_N_m, const ColumnOf<Scalar>& q,
                                       const ColumnOf<Scalar>& inertial_q) {
  const ColumnOf<Scalar> slope = model.phi_slope.template cast<Scalar>() * q;
  return inertia_relief_moment_with_slope(model, load_N_m, slope, q, inertial_q);
}

}  // namespace fowtsim::slender
