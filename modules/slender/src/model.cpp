#include "fowtsim/slender/model.hpp"

#include "fowtsim/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace fowtsim::slender {
namespace {

using std::numbers::pi;

[[noreturn]] void fail(const std::string& variable, const std::string& hint, const std::string& message) {
  throw InputError({"slender.model", std::nullopt, variable, hint}, message);
}

void check_strip(const Strip& s, std::size_t i) {
  const std::string at = "strip " + std::to_string(i) + ": ";
  if (!(s.length_m > 0.0)) fail("length_m", "give each strip a positive length", at + "length " + std::to_string(s.length_m));
  if (!(s.outer_diameter_m > 0.0) || !(s.inner_diameter_m >= 0.0) || !(s.inner_diameter_m < s.outer_diameter_m))
    fail("diameters", "need 0 <= inner < outer", at + "outer " + std::to_string(s.outer_diameter_m) + " m, inner " +
                                                      std::to_string(s.inner_diameter_m) + " m");
  if (!(s.density_kg_m3 >= 0.0) || !(s.youngs_modulus_Pa > 0.0) || !(s.drag_coefficient >= 0.0) ||
      !(s.added_mass_coefficient >= 0.0) || !(s.contents_density_kg_m3 >= 0.0))
    fail("material", "density, Cd, Ca, contents >= 0 and E > 0", at + "a material number is out of range");
}

// Essential conditions: a pinned end needs φ = 0, a clamped one φ = φ' = 0, for every shape.
void check_support(Support support, const VecX& value, const VecX& slope, double length, const char* end) {
  const double tol = 1e-9;
  const bool v_ok = support == Support::Free || value.cwiseAbs().maxCoeff() <= tol;
  const bool s_ok = support != Support::Clamped || slope.cwiseAbs().maxCoeff() * length <= tol;
  if (!v_ok || !s_ok)
    fail("shapes", "choose a shape family that carries the support (clamped_free_shapes, pinned_pinned_shapes)",
         std::string("a shape function moves the ") + end + " end, which is " +
             (support == Support::Pinned ? "pinned" : "clamped"));
}

}  // namespace

VecX effective_tension(const BodyDescription& body, const Environment& env, const VecX& structural_mass,
                       const VecX& submerged_fraction) {
  const auto n = static_cast<Eigen::Index>(body.strips.size());
  VecX tension(n);
  if (body.top_support == Support::Clamped) {
    // A hanging body: the free bottom carries nothing, every section the part below it.
    double below = 0.0;
    double x = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const Strip& s = body.strips[static_cast<std::size_t>(i)];
      const double area = pi * s.outer_diameter_m * s.outer_diameter_m / 4.0;
      const double net_down = (structural_mass(i) - env.water_density_kg_m3 * area * submerged_fraction(i)) * env.gravity_m_s2;
      tension(i) = below + 0.5 * net_down * s.length_m;
      for (const PointMass& m : body.point_masses)
        if (m.x_m < x + 0.5 * s.length_m) tension(i) += m.mass_kg * env.gravity_m_s2;
      below += net_down * s.length_m;
      x += s.length_m;
    }
    return tension;
  }
  double above = body.top_tension_N;  // T_eff at the top of the current strip
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    const Strip& s = body.strips[static_cast<std::size_t>(i)];
    const double area = pi * s.outer_diameter_m * s.outer_diameter_m / 4.0;
    const double net_up = (env.water_density_kg_m3 * area * submerged_fraction(i) - structural_mass(i)) *
                          env.gravity_m_s2;  // buoyancy − weight per length [N/m]
    tension(i) = above + 0.5 * net_up * s.length_m;
    above += net_up * s.length_m;
  }
  // A point mass's weight hangs on every section below it.
  Eigen::Index i = 0;
  double x = 0.0;
  for (const Strip& s : body.strips) {
    const double midpoint = x + 0.5 * s.length_m;
    for (const PointMass& m : body.point_masses)
      if (m.x_m > midpoint) tension(i) -= m.mass_kg * env.gravity_m_s2;
    x += s.length_m;
    ++i;
  }
  return tension;
}

Model make_model(const BodyDescription& body, const Environment& env) {
  if (body.strips.empty()) fail("strips", "give at least one strip", "no strips");
  if (body.shapes.empty()) fail("shapes", "give at least one shape function", "no shape functions");
  if (body.top_support == Support::Clamped && (body.bottom_support != Support::Free ||
                                                body.bottom_springs.translational_N_m != 0.0 || body.bottom_springs.rotational_N_m_rad != 0.0))
    fail("top_support", "a clamped top takes a free bottom end without springs (a hanging body), or clamp the bottom instead",
         "a clamped top above a supported bottom: the inertia-relief moment needs a reaction statics does not give");
  if (body.top_support == Support::Clamped && body.top_tension_N != 0.0)
    fail("top_tension_N", "leave it 0: a hanging body's tension is the weight below each section",
         "a clamped top with a top tension of " + std::to_string(body.top_tension_N) + " N");
  const auto N = static_cast<Eigen::Index>(body.strips.size());
  const auto n = static_cast<Eigen::Index>(body.shapes.size());
  Model model{body, env, 0.0, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
  StripTable& t = model.strips;
  for (VecX* v : {&t.x_m, &t.dx_m, &t.diameter_m, &t.section_modulus_m3, &t.bending_stiffness_N_m2,
                  &t.structural_mass_kg_m, &t.mass_kg_m, &t.submerged_fraction, &t.x_kinematics_m,
                  &t.inertia_coefficient_kg_m, &t.drag_factor_kg_m2})
    v->resize(N);
  const double rho = env.water_density_kg_m3;
  double bottom = 0.0;
  for (Eigen::Index i = 0; i < N; ++i) {
    const Strip& s = body.strips[static_cast<std::size_t>(i)];
    check_strip(s, static_cast<std::size_t>(i));
    const double D = s.outer_diameter_m, Di = s.inner_diameter_m, dx = s.length_m;
    const double area = pi * D * D / 4.0, bore = pi * Di * Di / 4.0;
    const double inertia = pi * (D * D * D * D - Di * Di * Di * Di) / 64.0;
    const double wet = std::clamp((env.still_water_level_m - bottom) / dx, 0.0, 1.0);
    t.x_m(i) = bottom + 0.5 * dx;
    t.dx_m(i) = dx;
    t.diameter_m(i) = D;
    t.section_modulus_m3(i) = inertia / (0.5 * D);
    t.bending_stiffness_N_m2(i) = s.youngs_modulus_Pa * inertia;
    t.structural_mass_kg_m(i) = s.density_kg_m3 * (area - bore) + s.contents_density_kg_m3 * bore;
    t.mass_kg_m(i) = t.structural_mass_kg_m(i) + rho * s.added_mass_coefficient * area * wet;
    t.submerged_fraction(i) = wet;
    t.x_kinematics_m(i) = bottom + 0.5 * wet * dx;
    t.inertia_coefficient_kg_m(i) = rho * (1.0 + s.added_mass_coefficient) * area * wet;
    t.drag_factor_kg_m2(i) = 0.5 * rho * s.drag_coefficient * D * wet;
    bottom += dx;
  }
  model.length_m = bottom;
  t.effective_tension_N = effective_tension(body, env, t.structural_mass_kg_m, t.submerged_fraction);

  model.phi.resize(N, n);
  model.phi_slope.resize(N, n);
  model.phi_curvature.resize(N, n);
  for (VecX* v : {&model.phi_top, &model.phi_top_slope, &model.phi_bottom, &model.phi_bottom_slope}) v->resize(n);
  for (Eigen::Index m = 0; m < n; ++m) {
    const ShapeFunction& shape = body.shapes[static_cast<std::size_t>(m)];
    for (Eigen::Index i = 0; i < N; ++i) {
      const ShapeValue v = evaluate(shape, t.x_m(i));
      model.phi(i, m) = v.value;
      model.phi_slope(i, m) = v.slope;
      model.phi_curvature(i, m) = v.curvature;
    }
    const ShapeValue top = evaluate(shape, model.length_m), foot = evaluate(shape, 0.0);
    model.phi_top(m) = top.value;
    model.phi_top_slope(m) = top.slope;
    model.phi_bottom(m) = foot.value;
    model.phi_bottom_slope(m) = foot.slope;
  }
  // Point springs and masses: the shapes sampled where they sit.
  const auto sample = [&](double x, const char* what, MatX& value, MatX& slope, Eigen::Index row) {
    if (!(x >= 0.0 && x <= model.length_m))
      fail(what, "place it on the body, 0 <= x <= L", std::string(what) + " at x = " + std::to_string(x) + " m, off the body (L = " +
                                                          std::to_string(model.length_m) + " m)");
    for (Eigen::Index m = 0; m < n; ++m) {
      const ShapeValue v = evaluate(body.shapes[static_cast<std::size_t>(m)], x);
      value(row, m) = v.value;
      slope(row, m) = v.slope;
    }
  };
  const auto springs = static_cast<Eigen::Index>(body.point_springs.size()), masses = static_cast<Eigen::Index>(body.point_masses.size());
  model.phi_springs.resize(springs, n);
  model.phi_springs_slope.resize(springs, n);
  model.phi_masses.resize(masses, n);
  model.phi_masses_slope.resize(masses, n);
  for (Eigen::Index p = 0; p < springs; ++p) {
    const PointSpring& k = body.point_springs[static_cast<std::size_t>(p)];
    if (!(k.translational_N_m >= 0.0) || !(k.rotational_N_m_rad >= 0.0)) fail("point spring", "stiffnesses >= 0", "a negative point spring");
    sample(k.x_m, "point spring", model.phi_springs, model.phi_springs_slope, p);
  }
  for (Eigen::Index p = 0; p < masses; ++p) {
    const PointMass& m = body.point_masses[static_cast<std::size_t>(p)];
    if (!(m.mass_kg >= 0.0) || !(m.rotary_inertia_kg_m2 >= 0.0)) fail("point mass", "mass and inertia >= 0", "a negative point mass");
    sample(m.x_m, "point mass", model.phi_masses, model.phi_masses_slope, p);
  }

  check_support(body.bottom_support, model.phi_bottom, model.phi_bottom_slope, model.length_m, "bottom");
  check_support(body.top_support, model.phi_top, model.phi_top_slope, model.length_m, "top");

  // Slide "Equation of Motion for Linear Vibration": M = Φᵀ m Φ Δx, K = Φ''ᵀ EI Φ'' Δx + Φ'ᵀ T_eff Φ' Δx
  // (midpoint rule per strip), plus the end springs' ½k v² and ½k_θ v'² energies.
  const VecX m_dx = t.mass_kg_m.cwiseProduct(t.dx_m);
  const VecX ei_dx = t.bending_stiffness_N_m2.cwiseProduct(t.dx_m);
  const VecX tension_dx = t.effective_tension_N.cwiseProduct(t.dx_m);
  model.mass = model.phi.transpose() * m_dx.asDiagonal() * model.phi;
  model.stiffness = model.phi_curvature.transpose() * ei_dx.asDiagonal() * model.phi_curvature +
                    model.phi_slope.transpose() * tension_dx.asDiagonal() * model.phi_slope;
  model.stiffness += body.bottom_springs.translational_N_m * model.phi_bottom * model.phi_bottom.transpose() +
                     body.bottom_springs.rotational_N_m_rad * model.phi_bottom_slope * model.phi_bottom_slope.transpose() +
                     body.top_springs.translational_N_m * model.phi_top * model.phi_top.transpose() +
                     body.top_springs.rotational_N_m_rad * model.phi_top_slope * model.phi_top_slope.transpose();
  // Their energies: ½k v(x_p)² + ½k_θ v'(x_p)², ½m v̇(x_p)² + ½J v̇'(x_p)².
  for (Eigen::Index p = 0; p < springs; ++p) {
    const PointSpring& k = body.point_springs[static_cast<std::size_t>(p)];
    model.stiffness += k.translational_N_m * model.phi_springs.row(p).transpose() * model.phi_springs.row(p) +
                       k.rotational_N_m_rad * model.phi_springs_slope.row(p).transpose() * model.phi_springs_slope.row(p);
  }
  for (Eigen::Index p = 0; p < masses; ++p) {
    const PointMass& m = body.point_masses[static_cast<std::size_t>(p)];
    model.mass += m.mass_kg * model.phi_masses.row(p).transpose() * model.phi_masses.row(p) +
                  m.rotary_inertia_kg_m2 * model.phi_masses_slope.row(p).transpose() * model.phi_masses_slope.row(p);
  }
  model.structural_damping = body.rayleigh_mass_per_s * model.mass + body.rayleigh_stiffness_s * model.stiffness;
  return model;
}

}  // namespace fowtsim::slender
