// The IEC 61400-1 wind conditions: the constants of iec_conditions.hpp against Table 1 and §6.3,
// and each deterministic event (EOG, EDC, ECD, EWS vertical and horizontal) of the wind field
// against the standard's formula, transcribed here independently, at the hub and the rotor disk's
// top, bottom, left and right, before, during and after the event.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/wind/iec_conditions.hpp"
#include "fowtsim/wind/iec_events.hpp"
#include "fowtsim/wind/verification.hpp"
#include "fowtsim/wind/wind_field.hpp"

using namespace fowtsim;
using namespace fowtsim::wind;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
// NREL 5MW on OC3: D = 126 m, z_hub = 90 m (Λ1 = 42 m), class I (V_ref 50 m/s), category B (I_ref 0.14).
constexpr double kD = 126.0, kHub = 90.0, kAlpha = 0.2, kStart = 5.0;

WindParams event_wind(WindEventType type, double v_hub, int sign = 1, double direction_deg = 0.0) {
  WindParams p;
  p.model = WindModel::power_law;
  p.speed_m_s = v_hub;
  p.reference_height_m = kHub;
  p.shear_exponent = kAlpha;
  p.direction_deg = direction_deg;
  p.event.type = type;
  p.event.start_s = kStart;
  p.event.sign = sign;
  p.event.rotor_diameter_m = kD;
  p.event.iec_wind_class = 1;
  p.event.turbulence_class = TurbulenceCategory::B;
  return p;
}

// The standard's quantities, written out from its text (not through the module's functions).
double sigma1(double v) { return 0.14 * (0.75 * v + 5.6); }  // NTM, I_ref = 0.14
const double kLambda1 = 42.0;                                 // z_hub = 90 m > 60 m
double profile(double v, double z) { return v * std::pow(z / kHub, kAlpha); }

// Hub, top, bottom, left (+y) and right (−y) of the rotor disk [m], inertial.
const std::vector<Vec3> kDiskPoints = {Vec3(0, 0, kHub), Vec3(0, 0, kHub + kD / 2), Vec3(0, 0, kHub - kD / 2),
                                       Vec3(0, kD / 2, kHub), Vec3(0, -kD / 2, kHub)};

// Tolerance of the formula checks: the module and the test evaluate the same closed forms in a
// different order of operations (and the turn through a rotation matrix), so they differ by
// rounding only: every check passes at 2e-15 relative / 2e-15 m/s (measured); 2e-14 is 10× that.
void check_velocity(const Vec3& actual, const Vec3& expected) {
  for (int c = 0; c < 3; ++c) CHECK(actual[c] == Approx(expected[c]).epsilon(2e-14).margin(2e-14));
}

}  // namespace

// Intent: Table 1 and §6.3 constants and the extreme / reduced wind speeds of V_ref, exact
// (products of decimal constants; 1e-15 relative is the rounding of one product).
TEST_CASE("IEC 61400-1 wind-condition constants", "[verification][wind][iec]") {
  CHECK(reference_wind_speed(1) == 50.0);
  CHECK(reference_wind_speed(2) == 42.5);
  CHECK(reference_wind_speed(3) == 37.5);
  CHECK(reference_turbulence_intensity(TurbulenceCategory::A) == 0.16);
  CHECK(reference_turbulence_intensity(TurbulenceCategory::B) == 0.14);
  CHECK(reference_turbulence_intensity(TurbulenceCategory::C) == 0.12);
  CHECK(turbulence_scale_parameter(50.0) == Approx(35.0).epsilon(1e-15));  // 0.7 z below 60 m
  CHECK(turbulence_scale_parameter(90.0) == 42.0);
  CHECK(ntm_sigma(TurbulenceCategory::B, 12.0) == Approx(2.044).epsilon(1e-15));
  CHECK(etm_sigma(TurbulenceCategory::B, 1, 12.0) == Approx(3.12256).epsilon(1e-15));
  CHECK(ewm_sigma(50.0) == Approx(5.5).epsilon(1e-15));
  CHECK(ewm_steady_50yr_speed(1) == Approx(70.0).epsilon(1e-15));   // V_e50 = 1.4 V_ref
  CHECK(ewm_steady_1yr_speed(1) == Approx(56.0).epsilon(1e-15));    // V_e1 = 0.8 V_e50
  CHECK(ewm_turbulent_50yr_speed(2) == 42.5);                       // V_50 = V_ref
  CHECK(ewm_turbulent_1yr_speed(2) == Approx(34.0).epsilon(1e-15)); // V_1 = 0.8 V_50
  CHECK(reduced_50yr_speed(3) == Approx(41.25).epsilon(1e-15));     // V_red50 = 1.1 V_ref
  CHECK(reduced_1yr_speed(3) == Approx(33.0).epsilon(1e-15));       // V_red1 = 0.8 V_red50
  CHECK(ewm_profile_speed(70.0, 45.0, 90.0) == Approx(70.0 * std::pow(0.5, 0.11)).epsilon(1e-15));
}

// Intent: the event amplitudes by hand for the NREL 5MW at 12 m/s, class I B (σ1 = 2.044 m/s,
// D/Λ1 = 3): V_gust = min(1.35 (56 − 12), 3.3 · 2.044 / 1.3) = 5.18862 m/s; θ_e = 4 atan(2.044 /
// (12 · 1.3)) = 29.8588°; θ_cg = 60°; EWS 2.5 + 0.2 · 6.4 · 2.044 · 3^¼ = 5.94327 m/s; and the
// branches: the 1.35 (V_e1 − V_hub) term near V_e1, θ_e bounded to 180°, θ_cg = 180° below 4 m/s.
// Hand values to 6 digits: tolerance 1e-5 relative.
TEST_CASE("IEC event amplitudes by hand", "[verification][wind][iec]") {
  const auto B = TurbulenceCategory::B;
  CHECK(eog_gust_speed(12.0, kD, kHub, 1, B) == Approx(5.18862).epsilon(1e-5));
  CHECK(edc_direction_change(12.0, kD, kHub, B) / kDeg == Approx(29.8588).epsilon(1e-5));
  CHECK(ecd_direction_change(12.0) / kDeg == Approx(60.0).epsilon(1e-14));
  CHECK(ews_shear_speed(12.0, kD, kHub, B) == Approx(5.94327).epsilon(1e-5));
  CHECK(eog_gust_speed(53.0, kD, kHub, 1, B) == Approx(1.35 * 3.0).epsilon(1e-13));  // 1.35 (56 − 53) < 16.1
  CHECK(edc_direction_change(0.5, kD, kHub, B) == kPi);  // 4 atan(1.287) = 208.6° > 180°
  CHECK(ecd_direction_change(3.0) == kPi);
  CHECK(ecd_direction_change(4.0) == Approx(kPi).epsilon(1e-15));  // continuous at 4 m/s
}

// Intent: EOG, V(z, t) = V(z) − 0.37 V_gust sin(3πτ/T)(1 − cos(2πτ/T)), T = 10.5 s, on the power law,
// at the five disk points; nothing before the start or after T.
TEST_CASE("EOG follows IEC 61400-1 at the hub and the rotor disk", "[verification][wind][iec]") {
  const double v = 12.0, T = 10.5;
  const double v_gust = std::min(1.35 * (0.8 * 1.4 * 50.0 - v), 3.3 * sigma1(v) / (1.0 + 0.1 * kD / kLambda1));
  const WindField field(event_wind(WindEventType::EOG, v));
  for (double t : {0.0, 4.99, kStart, 6.3, 9.0, 10.25, 13.4, kStart + T, 16.0, 200.0})
    for (const Vec3& p : kDiskPoints) {
      const double tau = t - kStart;
      const double gust = tau < 0 || tau > T ? 0.0
                                             : -0.37 * v_gust * std::sin(3 * kPi * tau / T) * (1 - std::cos(2 * kPi * tau / T));
      INFO("t = " << t << " s, z = " << p.z() << " m, y = " << p.y() << " m");
      check_velocity(field.velocity(p, t), Vec3(profile(v, p.z()) + gust, 0, 0));
    }
  // The gust's peak, −0.37·V_gust·sin(3π/2)·(1 − cos π) = +0.74 V_gust at τ = T/2 (the Mexican hat's crown).
  CHECK(field.velocity(Vec3(0, 0, kHub), kStart + T / 2).x() == Approx(v + 0.74 * v_gust).epsilon(1e-12));
}

// Intent: EDC, θ(t) = 0.5 θ_e (1 − cos(πτ/T)), T = 6 s, θ_e held after T, both signs, with the deck's
// yaw misalignment (direction 20°) underneath: u = V(z) (cos ψ, −sin ψ, 0), ψ = 20° + θ(t).
TEST_CASE("EDC turns the inflow as IEC 61400-1 says, on top of a yaw misalignment", "[verification][wind][iec]") {
  const double v = 12.0, T = 6.0;
  const double theta_e = 4.0 * std::atan(sigma1(v) / (v * (1.0 + 0.1 * kD / kLambda1)));
  for (int sign : {1, -1}) {
    const WindField field(event_wind(WindEventType::EDC, v, sign, 20.0));
    for (double t : {0.0, kStart, 6.0, 8.0, 10.5, kStart + T, 30.0})
      for (const Vec3& p : kDiskPoints) {
        const double tau = t - kStart;
        const double theta = tau < 0 ? 0.0 : tau > T ? sign * theta_e : 0.5 * sign * theta_e * (1 - std::cos(kPi * tau / T));
        const double psi = 20.0 * kDeg + theta;
        INFO("sign " << sign << ", t = " << t << " s, point (" << p.transpose() << ")");
        check_velocity(field.velocity(p, t), profile(v, p.z()) * Vec3(std::cos(psi), -std::sin(psi), 0));
      }
  }
}

// Intent: ECD, V(z) + 0.5 V_cg (1 − cos(πτ/T)) and θ = ±0.5 θ_cg (1 − cos(πτ/T)), V_cg = 15 m/s,
// T = 10 s, θ_cg = 720°/V_hub, both held after T.
TEST_CASE("ECD follows IEC 61400-1 at the hub and the rotor disk", "[verification][wind][iec]") {
  const double v = 10.0, T = 10.0, v_cg = 15.0, theta_cg = 720.0 / v * kDeg;
  for (int sign : {1, -1}) {
    const WindField field(event_wind(WindEventType::ECD, v, sign));
    for (double t : {1.0, kStart, 7.5, 10.0, 14.0, kStart + T, 60.0})
      for (const Vec3& p : kDiskPoints) {
        const double tau = t - kStart;
        const double ramp = tau < 0 ? 0.0 : tau > T ? 1.0 : 0.5 * (1 - std::cos(kPi * tau / T));
        const double speed = profile(v, p.z()) + v_cg * ramp, theta = sign * theta_cg * ramp;
        INFO("sign " << sign << ", t = " << t << " s, point (" << p.transpose() << ")");
        check_velocity(field.velocity(p, t), speed * Vec3(std::cos(theta), -std::sin(theta), 0));
      }
  }
}

// Intent: EWS, V(z, t) = V_hub (z/z_hub)^α ± ((z − z_hub)/D)(2.5 + 0.2 β σ1 (D/Λ1)^¼)(1 − cos(2πτ/T))
// (eq. 26) and the same with y for z − z_hub (eq. 27), T = 12 s, β = 6.4; the horizontal one with a
// yaw misalignment of 20°: y is the wind frame's lateral coordinate, x sin 20° + y cos 20°.
TEST_CASE("EWS vertical and horizontal follow IEC 61400-1 eqs. 26-27", "[verification][wind][iec]") {
  const double v = 12.0, T = 12.0, beta = 6.4;
  const double amplitude = 2.5 + 0.2 * beta * sigma1(v) * std::pow(kD / kLambda1, 0.25);
  for (int sign : {1, -1}) {
    const WindField vertical(event_wind(WindEventType::EWS_vertical, v, sign));
    const double psi = 20.0 * kDeg;
    const WindField horizontal(event_wind(WindEventType::EWS_horizontal, v, sign, 20.0));
    for (double t : {0.0, kStart, 8.0, 11.0, 14.5, kStart + T, 40.0})
      for (const Vec3& p : kDiskPoints) {
        const double tau = t - kStart;
        const double shape = tau < 0 || tau > T ? 0.0 : 1 - std::cos(2 * kPi * tau / T);
        const double y_wind = p.x() * std::sin(psi) + p.y() * std::cos(psi);
        INFO("sign " << sign << ", t = " << t << " s, point (" << p.transpose() << ")");
        check_velocity(vertical.velocity(p, t),
                       Vec3(profile(v, p.z()) + sign * (p.z() - kHub) / kD * amplitude * shape, 0, 0));
        const double u = profile(v, p.z()) + sign * y_wind / kD * amplitude * shape;
        check_velocity(horizontal.velocity(p, t), u * Vec3(std::cos(psi), -std::sin(psi), 0));
      }
  }
}

// Intent: `fowtsim verify wind`'s transcription of the events (verification.cpp) agrees as well:
// every event, both signs, with and without a yaw misalignment, 10× the measured 2e-15.
TEST_CASE("the verify command's event check", "[verification][wind][iec]") {
  for (WindEventType type : {WindEventType::EOG, WindEventType::EDC, WindEventType::ECD, WindEventType::EWS_vertical,
                             WindEventType::EWS_horizontal})
    for (int sign : {1, -1})
      for (double direction : {0.0, 20.0}) {
        INFO("event " << static_cast<int>(type) << ", sign " << sign << ", direction " << direction);
        CHECK(verification::iec_event_worst_deviation(type, sign, direction) < 2e-14);
      }
}

// Intent: the probe channel shows the turn: Wind1VelY = −V sin θ at the hub after an EDC.
TEST_CASE("the probe channel shows an event's turn", "[unit][wind][iec]") {
  WindParams p = event_wind(WindEventType::EDC, 12.0);
  p.model = WindModel::steady;
  p.probe_point_m = Vec3(0, 0, kHub);
  const Wind::Params params{std::make_shared<const WindField>(p)};
  Wind::State s = Wind::make_state(params);
  Wind::advance(params, {}, kStart + 6.0, 1.0, s);
  const double theta_e = 4.0 * std::atan(sigma1(12.0) / (12.0 * (1.0 + 0.1 * kD / kLambda1)));
  const Vec3 v = Wind::outputs(params, {}, s).probe_velocity_m_s;
  CHECK(v.x() == Approx(12.0 * std::cos(theta_e)).epsilon(1e-12));
  CHECK(v.y() == Approx(-12.0 * std::sin(theta_e)).epsilon(1e-12));
}

// Intent: the event adds to a full field (turbulent or .bts) as to the profiles: a uniform 7 m/s grid
// plus the EOG's ΔV at the hub, mid-event.
TEST_CASE("an event adds to a full field", "[unit][wind][iec]") {
  auto f = std::make_shared<FullField>();
  f->ny = f->nz = 3;
  f->nt = 4;
  f->dy_m = f->dz_m = 50.0;
  f->dt_s = 1.0;
  f->z_bottom_m = 40.0;
  f->z_hub_m = kHub;
  f->u_hub_m_s = 7.0;
  f->periodic = true;
  f->grid.assign(3 * 3 * 4 * 3, 0.0f);
  for (std::size_t i = 0; i < f->grid.size(); i += 3) f->grid[i] = 7.0f;
  WindParams p = event_wind(WindEventType::EOG, 7.0);
  p.model = WindModel::bts;
  p.file = "in-memory";
  const WindField field(p, f);
  const double tau = 4.0, T = 10.5;
  const double v_gust = std::min(1.35 * (56.0 - 7.0), 3.3 * sigma1(7.0) / (1.0 + 0.1 * kD / kLambda1));
  check_velocity(field.velocity(Vec3(0, 0, kHub), kStart + tau),
                 Vec3(7.0 - 0.37 * v_gust * std::sin(3 * kPi * tau / T) * (1 - std::cos(2 * kPi * tau / T)), 0, 0));
}

// Intent: a missing or invalid event input stops at its key with what was expected.
TEST_CASE("bad event inputs name their key", "[unit][wind][iec]") {
  WindParams p = event_wind(WindEventType::EOG, 12.0);
  p.event.rotor_diameter_m = 0.0;
  CHECK_THROWS_WITH(validate(p), Catch::Contains("wind.event.rotor_diameter_m") && Catch::Contains("required"));
  p = event_wind(WindEventType::EDC, 12.0, 0);
  CHECK_THROWS_WITH(validate(p), Catch::Contains("wind.event.sign: expected 1 or -1"));
  p = event_wind(WindEventType::EOG, 57.0);  // above V_e1 = 56 m/s
  CHECK_THROWS_WITH(WindField(p), Catch::Contains("V_e1"));
  p = event_wind(WindEventType::ECD, 51.0);  // above V_ref = 50 m/s
  CHECK_THROWS_WITH(validate(p), Catch::Contains("V_ref"));
  p = event_wind(WindEventType::EWS_vertical, 0.0);
  CHECK_THROWS_WITH(validate(p), Catch::Contains("wind.speed_m_s"));
  p = event_wind(WindEventType::none, 12.0);
  p.event.rotor_diameter_m = 0.0;  // not needed without an event
  CHECK_NOTHROW(validate(p));
  CHECK(parse_wind_event_type("EWS_horizontal") == WindEventType::EWS_horizontal);
  CHECK_THROWS_WITH(parse_wind_event_type("EOGX"), Catch::Contains("wind.event.type"));
}
