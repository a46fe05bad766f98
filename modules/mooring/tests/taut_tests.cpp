// The taut-leg model of seed 000 §4.4/§4.5.1 (massless linear springs, no compression) against
// hand calculations, and the symmetry of the seed's four-line layout.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/mooring/presets.hpp"
#include "fowtsim/mooring/stiffness.hpp"

using namespace fowtsim;
using namespace fowtsim::mooring;

namespace {

// One spring: anchor (−30, 0, −40) m, L = 49 m, EA = 49 MN, so a 50 m chord (3-4-5) is a
// strain of 1/49 and a tension of exactly 1 MN.
MooringParams one_spring(const Vec3& fairlead_body_m) {
  MooringParams p;
  p.model = LineModel::taut;
  LineParams l;
  l.anchor_m = Vec3(-30.0, 0.0, -40.0);
  l.fairlead_body_m = fairlead_body_m;
  l.unstretched_length_m = 49.0;
  l.ea_N = 49e6;
  p.lines.push_back(l);
  return p;
}

QuasiStaticMooring::Output at(const MooringParams& p, const Vec3& position, const Mat3& orientation) {
  QuasiStaticMooring::State s = QuasiStaticMooring::make_state(p);
  QuasiStaticMooring::Input u;
  u.platform.position_m = position;
  u.platform.orientation = orientation;
  return QuasiStaticMooring::evaluate(p, u, s);
}

}  // namespace

TEST_CASE("taut spring: force and moment on a displaced and rotated platform by hand", "[verification][mooring]") {
  // Exact arithmetic cases; tolerances are rounding only.
  SECTION("fairlead at the reference point: T = 1 MN along the 3-4-5 chord, no moment") {
    const auto y = at(one_spring(Vec3::Zero()), Vec3::Zero(), Mat3::Identity());
    CHECK(y.lines[0].fairlead_tension_N == Approx(1e6).epsilon(1e-14));
    CHECK((y.force_N - Vec3(-6e5, 0.0, -8e5)).norm() <= 1e-8);
    CHECK(y.moment_N_m.norm() <= 1e-8);
    CHECK(y.lines[0].fairlead_h_N == Approx(6e5).epsilon(1e-14));
    CHECK(y.lines[0].fairlead_v_N == Approx(8e5).epsilon(1e-14));
  }
  SECTION("heave +10 m with the fairlead 10 m below the reference point: M_y = r_z F_x = 6 MN·m") {
    const auto y = at(one_spring(Vec3(0.0, 0.0, -10.0)), Vec3(0.0, 0.0, 10.0), Mat3::Identity());
    CHECK((y.force_N - Vec3(-6e5, 0.0, -8e5)).norm() <= 1e-8);
    CHECK((y.moment_N_m - Vec3(0.0, 6e6, 0.0)).norm() <= 1e-7);
  }
  SECTION("surge +10 m and pitch +90°: the fairlead swings to the origin, M_y = −r_x F_z = −8 MN·m") {
    const auto y = at(one_spring(Vec3(0.0, 0.0, -10.0)), Vec3(10.0, 0.0, 0.0),
                      euler123_to_matrix(Vec3(0.0, std::numbers::pi / 2, 0.0)));
    CHECK((y.force_N - Vec3(-6e5, 0.0, -8e5)).norm() <= 1e-6);
    CHECK((y.moment_N_m - Vec3(0.0, -8e6, 0.0)).norm() <= 1e-5);
  }
  SECTION("a chord shorter than the unstretched length carries nothing (no compression)") {
    const auto y = at(one_spring(Vec3::Zero()), Vec3(-10.0, 0.0, -10.0), Mat3::Identity());  // chord 36.1 m < 49 m
    CHECK(y.lines[0].slack);
    CHECK(y.lines[0].fairlead_tension_N == 0.0);
    CHECK(y.force_N.norm() == 0.0);
  }
}

TEST_CASE("seed four-line taut layout: no net horizontal force at zero offset, restoring in surge",
          "[verification][mooring]") {
  // Fairleads 93.2 m deep on the 9.4 m spar (radius 4.7 m): horizontal chord 800 m, vertical
  // 226.8 m; pretension 400 kN sets L. Hand values from the chord lengths.
  const MooringParams p = seed_taut_mooring(-93.2, 4.7, 4.0e5);
  const double ea = 384'243'000.0, chord0 = std::hypot(800.0, 226.8), l0 = chord0 / (1.0 + 4.0e5 / ea);
  const auto rest = at(p, Vec3::Zero(), Mat3::Identity());
  for (std::size_t i = 0; i < 4; ++i) CHECK(rest.lines[i].fairlead_tension_N == Approx(4.0e5).epsilon(1e-12));
  CHECK(std::hypot(rest.force_N.x(), rest.force_N.y()) <= 1e-9 * 4.0e5);  // symmetric: rounding only
  CHECK(rest.force_N.z() == Approx(-4.0 * 4.0e5 * 226.8 / chord0).epsilon(1e-12));
  CHECK(rest.moment_N_m.norm() <= 1e-9 * 4.0e5 * 93.2);

  // Surge +10 m: chords (−790, 0, 226.8), (810, 0, 226.8) and (10, ∓800, 226.8). The upstream
  // line's chord (821.9 m) is now shorter than L (830.7 m): it goes slack, carrying nothing.
  const auto y = at(p, Vec3(10.0, 0.0, 0.0), Mat3::Identity());
  const auto tension = [&](double cx, double cy) {
    return std::max(0.0, ea * (std::sqrt(cx * cx + cy * cy + 226.8 * 226.8) - l0) / l0);
  };
  const auto fx = [&](double cx, double cy) { return -tension(cx, cy) * cx / std::sqrt(cx * cx + cy * cy + 226.8 * 226.8); };
  const double fx_hand = fx(-790.0, 0.0) + fx(810.0, 0.0) + 2.0 * fx(10.0, 800.0);
  CHECK(y.force_N.x() == Approx(fx_hand).epsilon(1e-10));
  CHECK(y.force_N.x() < 0.0);  // restoring
  CHECK(std::abs(y.force_N.y()) <= 1e-9 * std::abs(fx_hand));
  CHECK(y.lines[0].slack);
  CHECK(tension(-790.0, 0.0) == 0.0);
}

TEST_CASE("taut stiffness: analytic equals central differences and is symmetric at zero offset", "[verification][mooring]") {
  // As the OC3 stiffness test: measured ≤ 7.7e-11 of each block, tolerance 1e-9; symmetric at
  // zero offset to rounding (measured 1e-18).
  const MooringParams p = seed_taut_mooring(-93.2, 4.7, 4.0e5);
  QuasiStaticMooring::State s = QuasiStaticMooring::make_state(p);
  for (const Vec3& offset : {Vec3(0.0, 0.0, 0.0), Vec3(12.0, -5.0, 1.0)}) {
    QuasiStaticMooring::Input u;
    u.platform.position_m = offset;
    u.platform.orientation = euler123_to_matrix(offset.norm() > 0.0 ? Vec3(0.02, -0.07, 0.1) : Vec3::Zero());
    const Mat6 k = linearized_stiffness(p, u, s);
    const Mat6 fd = linearized_stiffness_finite_difference(p, u, s);
    for (int bi = 0; bi < 2; ++bi) {
      for (int bj = 0; bj < 2; ++bj) {
        const double scale = k.block<3, 3>(3 * bi, 3 * bj).cwiseAbs().maxCoeff();
        CHECK((k - fd).block<3, 3>(3 * bi, 3 * bj).cwiseAbs().maxCoeff() <= 1e-9 * scale);
      }
    }
    if (offset.norm() == 0.0) CHECK((k - k.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * k.cwiseAbs().maxCoeff());
  }
  // Hand: K11 at zero offset = Σ EA/L u_x² + T/|d| (1 − u_x²) over the four lines.
  const double ea = 384'243'000.0, chord0 = std::hypot(800.0, 226.8), l0 = chord0 / (1.0 + 4.0e5 / ea);
  const double ux2 = 800.0 * 800.0 / (chord0 * chord0);
  const double k11 = 2.0 * (ea / l0 * ux2 + 4.0e5 / chord0 * (1.0 - ux2)) + 2.0 * 4.0e5 / chord0;
  CHECK(linearized_stiffness(p, QuasiStaticMooring::Input{}, s)(0, 0) == Approx(k11).epsilon(1e-12));
}
