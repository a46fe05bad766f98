// The blade's twisted shapes and generalised matrices (blade_shapes.hpp, rr_blade.hpp) on uniform
// blades with closed forms, derived here: shapes x̃² and x̃³, constant or linear twist.
#include "fowtsim/core/error.hpp"
#include "fowtsim/flexbody/rr_blade.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace fowtsim::flexbody;

namespace {

constexpr double kL = 60.0, kM = 500.0, kEIf = 2e10, kEIe = 5e10, kHub = 2.0;

// Uniform blade, two stations, twist θ_root → θ_tip [deg] linear; flap 1 = x̃², flap 2 = x̃³, edge = x̃².
ElastoDynBlade uniform_blade(double twist_root_deg, double twist_tip_deg) {
  ElastoDynBlade b;
  b.hub_radius = kHub;
  b.tip_radius = kHub + kL;
  b.span_fraction = {0.0, 1.0};
  b.twist_deg = {twist_root_deg, twist_tip_deg};
  b.mass_density = {kM, kM};
  b.flap_stiffness = {kEIf, kEIf};
  b.edge_stiffness = {kEIe, kEIe};
  b.flap1_shape = {1, 0, 0, 0, 0};
  b.flap2_shape = {0, 1, 0, 0, 0};
  b.edge1_shape = {1, 0, 0, 0, 0};
  b.flap_damping_percent = {1.0, 2.0};
  b.edge_damping_percent = 3.0;
  return b;
}

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

}  // namespace

TEST_CASE("Untwisted frame and zero twist: the blade shapes are the polynomials on fixed axes", "[unit]") {
  for (BladeShapeFrame frame : {BladeShapeFrame::twisted, BladeShapeFrame::untwisted}) {
    const SampledBlade s = sample_blade(uniform_blade(0, 0), {}, frame);
    // The double integral of φ'' from the root is φ (8-point Gauss, exact for these polynomials):
    // rounding only, 1e-13 of the unit tip value.
    for (int j = 0; j < 2; ++j) {
      CHECK((s.u_flap.col(j) - s.phi.col(j)).cwiseAbs().maxCoeff() < 1e-13);
      CHECK(s.u_edge.col(j).cwiseAbs().maxCoeff() < 1e-13);
      CHECK((s.nu_flap.col(j) - s.dphi.col(j)).cwiseAbs().maxCoeff() < 1e-13 / kL);
    }
    CHECK((s.u_edge.col(2) - s.phi.col(2)).cwiseAbs().maxCoeff() < 1e-13);
    CHECK(s.u_flap.col(2).cwiseAbs().maxCoeff() < 1e-13);
  }
}

TEST_CASE("Constant twist θ0: flap shape along (cos θ0, −sin θ0), edge along (sin θ0, cos θ0)", "[unit]") {
  const double t0 = 10.0, th = t0 * std::numbers::pi / 180.0;
  const SampledBlade s = sample_blade(uniform_blade(t0, t0));
  const double c = std::cos(th), sn = std::sin(th);
  // Rounding bound as above.
  CHECK((s.u_flap.col(0) - c * s.phi.col(0)).cwiseAbs().maxCoeff() < 1e-13);
  CHECK((s.u_edge.col(0) + sn * s.phi.col(0)).cwiseAbs().maxCoeff() < 1e-13);
  CHECK((s.u_flap.col(2) - sn * s.phi.col(2)).cwiseAbs().maxCoeff() < 1e-13);
  CHECK((s.u_edge.col(2) - c * s.phi.col(2)).cwiseAbs().maxCoeff() < 1e-13);

  // Twisted: each shape bends about its own principal axis, so eq. 20 is ∫ EI_flap φ''² for a
  // flap shape (4 EI/L³ for x̃²) and the flap–edge stiffness coupling is zero; the mass couples
  // flap 1 and edge: ∫ m φ² (cos θ sin θ − sin θ cos θ) = 0 too for a constant twist.
  const RrBladeMatrices m = rr_blade_matrices(uniform_blade(t0, t0), s);
  CHECK(rel(m.stiffness(0, 0), 4 * kEIf / std::pow(kL, 3)) < 1e-13);
  CHECK(rel(m.stiffness(2, 2), 4 * kEIe / std::pow(kL, 3)) < 1e-13);
  CHECK(std::abs(m.stiffness(0, 2)) < 1e-13 * m.stiffness(0, 0));
  CHECK(std::abs(m.mass(0, 2)) < 1e-13 * m.mass(0, 0));
  CHECK(rel(m.mass(0, 0), kM * kL / 5) < 1e-13);  // ∫ m x̃⁴ = mL/5

  // Untwisted shapes on the same blade: eq. 20 gives ∫ (EI_f cos² + EI_e sin²) φ''² and the
  // coupling ∫ (EI_e − EI_f) sin θ cos θ φ_f'' φ_e''.
  const RrBladeMatrices u = rr_blade_matrices(uniform_blade(t0, t0), sample_blade(uniform_blade(t0, t0), {},
                                                                                   BladeShapeFrame::untwisted));
  const double k0 = 4 / std::pow(kL, 3);
  CHECK(rel(u.stiffness(0, 0), k0 * (kEIf * c * c + kEIe * sn * sn)) < 1e-13);
  CHECK(rel(u.stiffness(2, 2), k0 * (kEIf * sn * sn + kEIe * c * c)) < 1e-13);
  CHECK(rel(u.stiffness(0, 2), k0 * (kEIe - kEIf) * sn * c) < 1e-13);
}

TEST_CASE("Linear twist θ = a x̃: the twisted flap shape x̃² integrates to its closed form", "[unit]") {
  // Φ'' = (2/L²)(cos a x̃, −sin a x̃) ⇒ Φ_flap = 2(1 − cos a x̃)/a², Φ_edge = 2(sin(a x̃)/a − x̃)/a.
  const double a_deg = 20.0, a = a_deg * std::numbers::pi / 180.0;
  const SampledBlade s = sample_blade(uniform_blade(0, a_deg));
  double err = 0.0;
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    const double xt = s.points[k].x / kL;
    const auto i = static_cast<Eigen::Index>(k);
    err = std::max(err, std::abs(s.u_flap(i, 0) - 2 * (1 - std::cos(a * xt)) / (a * a)));
    err = std::max(err, std::abs(s.u_edge(i, 0) - 2 * (std::sin(a * xt) / a - xt) / a));
  }
  INFO("max |error| " << err);
  CHECK(err < 1e-12);  // 8-point Gauss on cos/sin of a linear function over 60 m: measured 2.6e-15
  // The tip is no longer at unit flap deflection: 2(1 − cos a)/a² = 0.9899 for 20°.
  CHECK(rel(s.u_flap(s.u_flap.rows() - 1, 0), 2 * (1 - std::cos(a * s.points.back().x / kL)) / (a * a)) < 1e-12);
}

TEST_CASE("Blade centrifugal stiffness and softening: closed forms for x̃² on a hub of radius r", "[unit]") {
  const ElastoDynBlade b = uniform_blade(0, 0);
  const RrBladeMatrices m = rr_blade_matrices(b, sample_blade(b));
  // G = ∫ (T/Ω²) φ'² with T/Ω² = m[r(L − x) + (L² − x²)/2], φ = x̃²: m(r/3 + 4L/15) (derived);
  // the flap shape has no in-plane part (S_11 = 0), the edge shape's S = ∫ m x̃⁴ = mL/5.
  CHECK(rel(m.centrifugal(0, 0), kM * (kHub / 3 + 4 * kL / 15)) < 1e-12);
  CHECK(rel(m.centrifugal(2, 2), kM * (kHub / 3 + 4 * kL / 15)) < 1e-12);
  CHECK(std::abs(m.softening(0, 0)) < 1e-12 * kM * kL);
  CHECK(rel(m.softening(2, 2), kM * kL / 5) < 1e-13);
  // ElastoDyn's per-mode Rayleigh quotient equals the single-shape closed form:
  // ω² = 20 EI/(mL⁴) + (4/3 + 5r/(3L)) Ω² for the flap x̃².
  const double omega = 1.2;
  const double w2 = 20 * kEIf / (kM * std::pow(kL, 4)) + (4.0 / 3 + 5 * kHub / (3 * kL)) * omega * omega;
  CHECK(rel(elastodyn_frequencies_hz(m, omega)(0), std::sqrt(w2) / (2 * std::numbers::pi)) < 1e-12);
}

TEST_CASE("ElastoDyn damping: ζ percent of critical for each shape alone", "[unit]") {
  const ElastoDynBlade b = uniform_blade(5, 5);
  const RrBladeMatrices m = rr_blade_matrices(b, sample_blade(b));
  const Eigen::Matrix3d c = elastodyn_damping(b, m);
  const Eigen::Vector3d f = elastodyn_frequencies_hz(m);
  const double zeta[3] = {1.0, 2.0, 3.0};
  // C_ii = 2 (ζ/100) ω_i M_ii with ElastoDyn's M_ii = ∫ m φ_i² (definition; rounding).
  for (int i = 0; i < 3; ++i)
    CHECK(rel(c(i, i), 2 * 0.01 * zeta[i] * 2 * std::numbers::pi * f(i) * m.mass_polynomial(i)) < 1e-13);
}

TEST_CASE("Blade input checks", "[unit]") {
  ElastoDynBlade b = uniform_blade(0, 0);
  b.span_fraction.back() = 0.9;
  CHECK_THROWS_AS(sample_blade(b), fowtsim::InputError);
  b = uniform_blade(0, 0);
  b.flap1_shape = {1, 1, 0, 0, 0};  // Σ c_j = 2: not an ElastoDyn shape
  CHECK_THROWS_AS(sample_blade(b), fowtsim::InputError);
  b = uniform_blade(0, 0);
  b.tip_radius = b.hub_radius;
  CHECK_THROWS_AS(sample_blade(b), fowtsim::InputError);
  CHECK_THROWS_AS(blade_points(uniform_blade(0, 0), {BladeRule::Kind::ElastoDynNodes, {}, 0, {}}), fowtsim::InputError);
}
