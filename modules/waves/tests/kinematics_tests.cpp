// Airy kinematics by direct summation: closed form of a regular wave (deep, finite depth, any
// heading and phase) and consistency relations of an irregular sea (acceleration = ∂v/∂t,
// continuity, kinematic surface condition, pressure transfer), Wheeler stretching.
#include <cmath>

#include <catch2/catch.hpp>

#include "test_waves.hpp"

using namespace waves_test;

namespace {

// max over a set of points and times of |module − closed form| for each quantity, relative to
// the quantity's amplitude at the surface.
void check_against_closed_form(const WaveParams& p, double tolerance) {
  const WaveField field(p);
  const ClosedForm scale = [&] {
    // amplitudes at the surface: a, aω F_cs(0), aω, aω² F_cs(0), aω², ρ g a
    const double a = 0.5 * p.height_m, om = 2.0 * kPi / p.period_s;
    const double k = wavenumber(om, p.depth_m, p.gravity_m_s2);
    const double cs0 = std::isinf(p.depth_m) ? 1.0 : 1.0 / std::tanh(k * p.depth_m);
    return ClosedForm{a, a * om * cs0, a * om, a * om * om * cs0, a * om * om, p.water_density_kg_m3 * p.gravity_m_s2 * a};
  }();
  const double zs[] = {0.0, -1.0, -7.3, -0.5 * std::min(p.depth_m, 60.0), -std::min(p.depth_m, 60.0)};
  const double beta = p.heading_deg * kPi / 180.0;
  for (double z : zs) {
    for (double x : {0.0, 13.7, -42.0}) {
      for (double t : {0.0, 0.37, 3.9, 11.1}) {
        const Vec3 pt(x, 0.5 * x - 3.0, z);
        const WaveKinematics m = field.evaluate(pt, t);
        const ClosedForm c = closed_form(p, pt, t);
        INFO("z " << z << " x " << x << " t " << t);
        CHECK(m.wetted);
        CHECK(std::abs(m.elevation_m - c.eta) <= tolerance * scale.eta);
        CHECK(std::abs(m.velocity_m_s.x() - std::cos(beta) * c.u_h) <= tolerance * scale.u_h);
        CHECK(std::abs(m.velocity_m_s.y() - std::sin(beta) * c.u_h) <= tolerance * scale.u_h);
        CHECK(std::abs(m.velocity_m_s.z() - c.w) <= tolerance * scale.w);
        CHECK(std::abs(m.acceleration_m_s2.x() - std::cos(beta) * c.a_h) <= tolerance * scale.a_h);
        CHECK(std::abs(m.acceleration_m_s2.y() - std::sin(beta) * c.a_h) <= tolerance * scale.a_h);
        CHECK(std::abs(m.acceleration_m_s2.z() - c.a_z) <= tolerance * scale.a_z);
        CHECK(std::abs(m.dynamic_pressure_Pa - c.p) <= tolerance * scale.p);
      }
    }
  }
}

}  // namespace

TEST_CASE("regular-wave kinematics match the closed-form Airy solution", "[verification][waves]") {
  // Tolerance 1e-13 of each quantity's surface amplitude: the two formulations (cosh/sinh vs
  // exponentials) differ by round-off only (measured ≤ 1e-14).
  SECTION("deep water, h = inf") { check_against_closed_form(regular(4.0, 10.0, kInf), 1e-13); }
  SECTION("OC3 depth 320 m, 30 deg heading, phase 40 deg") {
    check_against_closed_form(regular(8.0, 12.0, 320.0, 30.0, 40.0), 1e-13);
  }
  SECTION("intermediate depth 60 m, T 12 s (kh = 1.1)") { check_against_closed_form(regular(3.0, 12.0, 60.0, -20.0, 10.0), 1e-13); }
  SECTION("shallow 8 m, T 14 s (kh = 0.25)") { check_against_closed_form(regular(1.0, 14.0, 8.0), 1e-13); }
}

TEST_CASE("irregular-sea kinematics are consistent: accelerations, continuity, surface conditions",
          "[verification][waves]") {
  // A 20-minute JONSWAP sea at 40 m depth, heading 25°: every component contributes, so these
  // check the summation as a whole. Central differences with step δ have error O(δ² · max
  // frequency³); tolerances are set from measured residuals (× ~10).
  WaveParams p = jonswap(4.0, 8.0, 3.3, 40.0, 1200.0, 0.25, 7);
  p.heading_deg = 25.0;
  const WaveField field(p);
  const Vec3 e = field.direction();
  for (const Vec3& pt : {Vec3(0.0, 0.0, -5.0), Vec3(17.0, -8.0, -0.3), Vec3(-30.0, 12.0, -39.0)}) {
    for (double t : {12.0, 345.6, 1000.3}) {
      INFO("point " << pt.transpose() << " t " << t);
      const WaveKinematics k0 = field.evaluate(pt, t);
      // a = ∂v/∂t (central difference, δ = 1e-3 s; relative error ~ (ω δ)²/6 < 1e-6)
      const double dt = 1e-3;
      const Vec3 dv = (field.evaluate(pt, t + dt).velocity_m_s - field.evaluate(pt, t - dt).velocity_m_s) / (2 * dt);
      CHECK((dv - k0.acceleration_m_s2).norm() <= 1e-5 * (1.0 + k0.acceleration_m_s2.norm()));
      // continuity ∂u/∂x + ∂v/∂y + ∂w/∂z = 0 by central differences, δ = 1e-4 m: the truncation
      // error (k δ)²/6 of each term is 4e-8 relative at the top component (2 Hz, k = 16 rad/m),
      // which dominates the velocity gradients (gradient spectrum k² ω² S ~ ω). Measured ≤ 5e-8 of
      // |∂w/∂z|; tolerance 2e-7.
      const double d = 1e-4;
      const auto vel = [&](const Vec3& q) { return field.evaluate(q, t).velocity_m_s; };
      const double div = (vel(pt + Vec3(d, 0, 0)).x() - vel(pt - Vec3(d, 0, 0)).x()) / (2 * d) +
                         (vel(pt + Vec3(0, d, 0)).y() - vel(pt - Vec3(0, d, 0)).y()) / (2 * d) +
                         (vel(pt + Vec3(0, 0, d)).z() - vel(pt - Vec3(0, 0, d)).z()) / (2 * d);
      const double grad_scale = std::abs((vel(pt + Vec3(0, 0, d)).z() - vel(pt - Vec3(0, 0, d)).z()) / (2 * d));
      INFO("divergence " << div << " vs |dw/dz| " << grad_scale);
      CHECK(std::abs(div) <= 2e-7 * (1.0 + grad_scale));
      // horizontal velocity along the heading, none across it
      CHECK(std::abs(k0.velocity_m_s.x() * e.y() - k0.velocity_m_s.y() * e.x()) <= 1e-12);
    }
    // kinematic surface condition w(z = 0) = ∂η/∂t and pressure p(z = 0) = ρ g η (linear)
    const Vec3 surface(pt.x(), pt.y(), 0.0);
    for (double t : {50.0, 500.0}) {
      const double dt = 1e-3;
      const double deta = (field.elevation(pt.x(), pt.y(), t + dt) - field.elevation(pt.x(), pt.y(), t - dt)) / (2 * dt);
      const WaveKinematics k = field.evaluate(surface, t);
      CHECK(k.velocity_m_s.z() == Approx(deta).margin(1e-6));
      CHECK(k.dynamic_pressure_Pa == Approx(p.water_density_kg_m3 * p.gravity_m_s2 * k.elevation_m).margin(1e-8));
    }
  }
  // seabed: w = 0
  CHECK(field.evaluate(Vec3(3.0, 4.0, -40.0), 77.0).velocity_m_s.z() == Approx(0.0).margin(1e-15));
}

TEST_CASE("dynamic pressure of a regular wave is rho g eta cosh k(z+h) / cosh kh", "[verification][waves]") {
  const WaveParams p = regular(5.0, 9.0, 45.0, 0.0, 0.0);
  const WaveField field(p);
  const double k = field.components()[0].wavenumber_rad_m;
  for (double z : {0.0, -3.0, -20.0, -45.0}) {
    for (double t : {0.0, 1.3, 4.4}) {
      const WaveKinematics m = field.evaluate(Vec3(2.0, 0.0, z), t);
      const double expected = p.water_density_kg_m3 * p.gravity_m_s2 * m.elevation_m * std::cosh(k * (z + 45.0)) / std::cosh(k * 45.0);
      CHECK(m.dynamic_pressure_Pa == Approx(expected).margin(1e-9 * p.water_density_kg_m3 * p.gravity_m_s2));
    }
  }
}

TEST_CASE("Wheeler stretching maps the water column onto the still-water column", "[verification][waves]") {
  // Under Wheeler stretching the kinematics at the instantaneous surface z = η are the linear
  // values at z = 0, at the seabed those at −h, and at z the linear values at h (z − η)/(h + η).
  WaveParams p = regular(6.0, 10.0, 50.0, 0.0, 0.0);
  p.stretching = Stretching::wheeler;
  const WaveField field(p);
  for (double t : {0.0, 2.5, 5.0, 7.1}) {
    const double eta = field.elevation(0.0, 0.0, t);
    const WaveKinematics top = field.evaluate(Vec3(0.0, 0.0, eta), t);
    const WaveKinematics surface_linear = field.evaluate(Vec3(0.0, 0.0, 0.0), t, Stretching::none);
    CHECK(top.wetted);
    CHECK((top.velocity_m_s - surface_linear.velocity_m_s).norm() <= 1e-12);
    CHECK(top.dynamic_pressure_Pa == Approx(surface_linear.dynamic_pressure_Pa).margin(1e-8));
    const double z = -12.0, zp = 50.0 * (z - eta) / (50.0 + eta);
    const WaveKinematics mid = field.evaluate(Vec3(0.0, 0.0, z), t);
    const WaveKinematics mid_linear = field.evaluate(Vec3(0.0, 0.0, zp), t, Stretching::none);
    CHECK((mid.velocity_m_s - mid_linear.velocity_m_s).norm() <= 1e-12);
    CHECK((mid.acceleration_m_s2 - mid_linear.acceleration_m_s2).norm() <= 1e-12);
    // above the instantaneous surface: dry, zero, not NaN
    const WaveKinematics above = field.evaluate(Vec3(0.0, 0.0, eta + 0.01), t);
    CHECK_FALSE(above.wetted);
    CHECK(above.velocity_m_s.norm() == 0.0);
    CHECK(above.dynamic_pressure_Pa == 0.0);
    CHECK(above.elevation_m == eta);
  }
  // deep water: z' = z − η
  WaveParams deep = regular(6.0, 10.0, kInf);
  deep.stretching = Stretching::wheeler;
  const WaveField deep_field(deep);
  const double eta = deep_field.elevation(0.0, 0.0, 1.0);
  CHECK((deep_field.evaluate(Vec3(0, 0, -5.0), 1.0).velocity_m_s -
         deep_field.evaluate(Vec3(0, 0, -5.0 - eta), 1.0, Stretching::none).velocity_m_s).norm() <= 1e-12);
}

TEST_CASE("without stretching the field stops at z = 0", "[unit][waves]") {
  const WaveField field(regular(6.0, 10.0, 50.0));
  // crest at x = 0, t = 0: η = 3 m; a point at z = 1 m is in the water but above z = 0 → zero
  const WaveKinematics k = field.evaluate(Vec3(0.0, 0.0, 1.0), 0.0);
  CHECK(k.elevation_m == Approx(3.0));
  CHECK_FALSE(k.wetted);
  CHECK(k.velocity_m_s.norm() == 0.0);
  // trough at t = T/2: η = −3 m; a point at z = −1 m is above the water but still gets the field
  const WaveKinematics trough = field.evaluate(Vec3(0.0, 0.0, -1.0), 5.0);
  CHECK(trough.wetted);
  CHECK(trough.velocity_m_s.norm() > 0.0);
}
