#include "fowtsim/control/verification.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "fowtsim/control/external_controller.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::control::verification {
namespace {

constexpr int kRows = 12;     // λ = 3.0, 3.5, …, 8.5
constexpr int kColumns = 60;  // θ = −5.0, −4.5, …, 24.5 deg
constexpr double kTsr0 = 3.0, kPitch0 = -5.0, kSpacing = 0.5;
constexpr double kCp[kRows * kColumns] = {
#include "cp_table.inc"
};

}  // namespace

double Rotor::power_coefficient(double tsr, double pitch_deg) const {
  const double x = (tsr - kTsr0) / kSpacing, y = (pitch_deg - kPitch0) / kSpacing;
  if (!(x >= 0.0 && x <= kRows - 1 && y >= 0.0 && y <= kColumns - 1)) {
    throw InputError({"control.verification", std::nullopt, "Cp table", "stay within λ ∈ [3, 8.5], θ ∈ [−5, 24.5] deg"},
                     "Cp table: λ = " + std::to_string(tsr) + ", θ = " + std::to_string(pitch_deg) + " deg outside the table");
  }
  const int i = std::min(static_cast<int>(x), kRows - 2), j = std::min(static_cast<int>(y), kColumns - 2);
  const double fx = x - i, fy = y - j;
  const auto c = [](int r, int col) { return kCp[r * kColumns + col]; };
  return (1 - fx) * ((1 - fy) * c(i, j) + fy * c(i, j + 1)) + fx * ((1 - fy) * c(i + 1, j) + fy * c(i + 1, j + 1));
}

double Rotor::aero_torque_N_m(double wind, double omega, double pitch_rad) const {
  const double area = std::numbers::pi * radius_m * radius_m;
  const double cp = power_coefficient(omega * radius_m / wind, pitch_rad * 180.0 / std::numbers::pi);
  return 0.5 * air_density_kg_m3 * area * wind * wind * wind * cp / omega;
}

double pitch_for_cp_deg(const Rotor& r, double tsr, double cp) {
  double lo = 0.0, hi = 24.5;  // bracket: the peak column (Cp above target) and the last column
  for (double th = 0.0; th <= 24.5; th += 0.5) {
    if (r.power_coefficient(tsr, th) > r.power_coefficient(tsr, lo)) lo = th;
  }
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (r.power_coefficient(tsr, mid) > cp ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double equilibrium_pitch_rad(const Rotor& r, double wind, double omega, double power_W) {
  const double cp = power_W / (0.5 * r.air_density_kg_m3 * std::numbers::pi * r.radius_m * r.radius_m * wind * wind * wind);
  return pitch_for_cp_deg(r, omega * r.radius_m / wind, cp) * std::numbers::pi / 180.0;
}

template <class Controller>
void run_loop(const Rotor& rotor, const typename Controller::Params& p, typename Controller::State& s,
              const std::function<double(double)>& wind, double omega0, double pitch0, double dt, double t_end,
              const std::function<void(const LoopSample&)>& observe) {
  double omega = omega0;
  ControllerInput u;
  u.blade_pitch_rad = {pitch0, pitch0, pitch0};
  const int steps = static_cast<int>(std::lround(t_end / dt));
  for (int k = 0; k <= steps; ++k) {
    const double t = k * dt;
    u.generator_speed_rad_s = rotor.gearbox_ratio * omega;
    u.rotor_speed_rad_s = omega;
    u.hub_wind_speed_m_s = wind(t);
    Controller::advance(p, u, t, dt, s);
    const ControllerOutput y = Controller::outputs(p, u, s);
    observe({t, u.hub_wind_speed_m_s, omega, y});
    // RK4 of J Ω̇ = Q_aero(U(t), Ω, θ) − N T over [t, t + dt] with T, θ held (ideal actuator).
    const double theta = y.blade_pitch_rad[0];
    const auto rate = [&](double time, double w) {
      return (rotor.aero_torque_N_m(wind(time), w, theta) - rotor.gearbox_ratio * y.generator_torque_N_m) /
             rotor.inertia_kg_m2;
    };
    const double k1 = rate(t, omega), k2 = rate(t + dt / 2, omega + dt / 2 * k1);
    const double k3 = rate(t + dt / 2, omega + dt / 2 * k2), k4 = rate(t + dt, omega + dt * k3);
    omega += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    u.blade_pitch_rad = y.blade_pitch_rad;
  }
}

SteadyLoop settle_closed_loop(const Rotor& rotor, const BaselineParams& p, double wind, double t_end) {
  constexpr double kDeg = 180.0 / std::numbers::pi, kRpm = 30.0 / std::numbers::pi;
  BaselineController::State s = BaselineController::make_state(p);
  SteadyLoop out;
  double n = 0, lo = 1e9, hi = -1e9;
  run_loop<BaselineController>(rotor, p, s, [wind](double) { return wind; }, 12.1 / kRpm, 0.0, 0.0125, t_end,
                               [&](const LoopSample& x) {
                                 if (x.time_s < t_end - 20.0) return;
                                 const double th = x.demand.blade_pitch_rad[0] * kDeg;
                                 out.pitch_deg += th;
                                 out.rotor_speed_rpm += x.rotor_speed_rad_s * kRpm;
                                 lo = std::min(lo, th);
                                 hi = std::max(hi, th);
                                 ++n;
                               });
  out.pitch_deg /= n;
  out.rotor_speed_rpm /= n;
  out.pitch_drift_deg = hi - lo;
  return out;
}

double settled_torque(const BaselineParams& p, double w, double pitch_rad) {
  BaselineController::State s = BaselineController::make_state(p);
  ControllerInput u;
  u.generator_speed_rad_s = w;
  u.blade_pitch_rad = {pitch_rad, pitch_rad, pitch_rad};
  for (int k = 0; k <= 4800; ++k) BaselineController::advance(p, u, 0.0125 * k, 0.0125, s);
  return BaselineController::outputs(p, u, s).generator_torque_N_m;
}

double filter_step_response_error(const BaselineParams& p) {
  BaselineController::State s = BaselineController::make_state(p);
  ControllerInput u;
  u.generator_speed_rad_s = 100.0;
  BaselineController::advance(p, u, 0.0, 0.01, s);  // seeds ω_f = 100
  u.generator_speed_rad_s = 110.0;
  double t = 0.0, worst = 0.0;
  for (double step : {0.01, 0.0125, 0.03, 0.2, 0.5}) {
    t += step;
    BaselineController::advance(p, u, t, step, s);
    const double expected = 110.0 - 10.0 * std::exp(-p.filter_corner_rad_s * t);
    worst = std::max(worst, std::abs(s.filtered_speed_rad_s - expected) / 110.0);
  }
  return worst;
}

template void run_loop<BaselineController>(const Rotor&, const BaselineController::Params&, BaselineController::State&,
                                           const std::function<double(double)>&, double, double, double, double,
                                           const std::function<void(const LoopSample&)>&);
template void run_loop<ExternalController>(const Rotor&, const ExternalController::Params&, ExternalController::State&,
                                           const std::function<double(double)>&, double, double, double, double,
                                           const std::function<void(const LoopSample&)>&);

}  // namespace fowtsim::control::verification
