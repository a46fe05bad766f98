// IEC wind events and OpenFAST uniform wind files in a coupled run of the NREL 5MW on OC3-Hywind
// (the steady-wind turbine deck, rigid blades, still water): the runs work, and the probe channel
// Wind1VelX/Y at the hub follows the IEC formula at every output time; bad event inputs and bad
// uniform wind files stop before anything is written, at their file:line.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"
#include "test_helpers.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

constexpr double kPi = std::numbers::pi;
// NREL 5MW: D = 126 m, hub 90 m (Λ1 = 42 m); class I B; 12 m/s: σ1 = 0.14 (0.75 · 12 + 5.6) = 2.044 m/s.
constexpr double kV = 12.0, kStart = 2.0, kSigma1 = 0.14 * (0.75 * kV + 5.6), kRotorFactor = 1.0 + 0.1 * 126.0 / 42.0;

// Runs the steady turbine deck for 14 s with `wind` (YAML flow mapping) and returns its channels.
io::ChannelTable run_with_wind(const std::string& name, const std::string& wind) {
  const auto dir = testing::scratch_dir(name);
  const auto deck = dir / "turbine.yaml";
  std::ofstream(deck) << "include: [" << (testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml").string() << "]\n"
                      << "simulation: {t_max_s: 14.0, dt_s: 0.0125}\noutput: {format: h5, decimation: 4}\n"
                      << "structure: {initial_conditions: {rotor_speed_rpm: 12.1}}\n"
                      << "wind: " << wind << "\n";
  run_scene(run_request(deck, dir / "run", std::nullopt), nullptr);
  return io::read_channels(dir / "run.h5");
}

}  // namespace

// Intent: EOG on the power law: Wind1VelX at the hub = 12 − 0.37 V_gust sin(3πτ/T)(1 − cos(2πτ/T)),
// V_gust = min(1.35 (56 − 12), 3.3 σ1 / 1.3) = 5.18862 m/s, T = 10.5 s, at every output time
// (the wind field is the same pure function of time the module tests check; the channel stores
// doubles: 1e-12 relative is rounding with room); the run reaches t_max with finite rotor speed.
TEST_CASE("a coupled run under an EOG shows the IEC gust at the hub", "[verification][wind][coupled]") {
  const io::ChannelTable t =
      run_with_wind("wind_event_eog", "{model: power_law, speed_m_s: 12.0, reference_height_m: 90.0, shear_exponent: 0.2, "
                                      "event: {type: EOG, start_s: 2.0, rotor_diameter_m: 126.0}}");
  const double v_gust = std::min(1.35 * (0.8 * 1.4 * 50.0 - kV), 3.3 * kSigma1 / kRotorFactor), T = 10.5;
  const auto& time = t.time();
  const auto& u = column(t, "Wind1VelX");
  const auto& w = column(t, "Wind1VelY");
  REQUIRE(time.back() == Approx(14.0));
  double lowest = kV;
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double tau = time[i] - kStart;
    const double gust = tau < 0 || tau > T ? 0.0 : -0.37 * v_gust * std::sin(3 * kPi * tau / T) * (1 - std::cos(2 * kPi * tau / T));
    INFO("t = " << time[i] << " s");
    CHECK(u[i] == Approx(kV + gust).epsilon(1e-12));
    CHECK(w[i] == 0.0);
    lowest = std::min(lowest, u[i]);
  }
  // The dips beside the crown were sampled: the formula's minimum is −0.26806 V_gust (at τ = 0.766 T),
  // −0.26805 at the nearest 0.05 s output row; at least 0.265 V_gust (99 %) must show.
  CHECK(lowest < kV - 0.265 * v_gust);
  for (double speed : column(t, "RotSpeed")) CHECK(std::isfinite(speed));
}

// Intent: EDC (sign −1) on a 10° yaw misalignment: ψ = 10° − 0.5 θ_e (1 − cos(πτ/T)), T = 6 s, θ_e =
// 4 atan(σ1 / (12 · 1.3)) = 29.86°, held after T; Wind1VelX/Y = 12 (cos ψ, −sin ψ) at the hub.
TEST_CASE("a coupled run under an EDC turns the hub wind as IEC 61400-1 says", "[verification][wind][coupled]") {
  const io::ChannelTable t = run_with_wind(
      "wind_event_edc", "{model: steady, speed_m_s: 12.0, reference_height_m: 90.0, direction_deg: 10.0, "
                        "event: {type: EDC, start_s: 2.0, sign: -1, rotor_diameter_m: 126.0}}");
  const double theta_e = 4.0 * std::atan(kSigma1 / (kV * kRotorFactor)), T = 6.0;
  const auto& time = t.time();
  const auto& u = column(t, "Wind1VelX");
  const auto& v = column(t, "Wind1VelY");
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double tau = time[i] - kStart;
    const double theta = tau < 0 ? 0.0 : tau > T ? -theta_e : -0.5 * theta_e * (1 - std::cos(kPi * tau / T));
    const double psi = 10.0 * kPi / 180.0 + theta;
    INFO("t = " << time[i] << " s");
    CHECK(u[i] == Approx(kV * std::cos(psi)).epsilon(1e-12));
    CHECK(v[i] == Approx(-kV * std::sin(psi)).epsilon(1e-12).margin(1e-12));
  }
  CHECK(v.back() == Approx(-kV * std::sin(10.0 * kPi / 180.0 - theta_e)).epsilon(1e-12));  // the turn is kept
}

// Intent: the shipped EOG uniform wind file (inputs/wind/eog_12mps_nrel5mw.hh, rows every 0.1 s, 9
// decimals) gives the same hub wind as the EOG event at its rows: 12 + gust, to the file's printed
// precision (5e-10 m/s) plus the linear interpolation between rows at the output times that fall
// between them (|ΔV''| ≤ 0.37 V_gust (3π/T)²·… ≈ 2 m/s³ times (0.1 s)²/8: 3e-3 m/s; 5e-3).
TEST_CASE("the shipped uniform wind file reproduces the EOG event", "[verification][wind][coupled]") {
  const auto dir = testing::scratch_dir("wind_uniform_eog");
  run_scene(run_request(testing::source_dir() / "inputs/wind/turbine_eog_12mps_uniform_file.yaml", dir / "run", "out"), nullptr);
  const io::ChannelTable t = io::read_channels(dir / "run.out");
  const double v_gust = std::min(1.35 * (0.8 * 1.4 * 50.0 - kV), 3.3 * kSigma1 / kRotorFactor), T = 10.5;
  const auto& time = t.time();
  const auto& u = column(t, "Wind1VelX");
  REQUIRE(time.back() == Approx(60.0));
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double tau = time[i] - 5.0;
    const double gust = tau < 0 || tau > T ? 0.0 : -0.37 * v_gust * std::sin(3 * kPi * tau / T) * (1 - std::cos(2 * kPi * tau / T));
    INFO("t = " << time[i] << " s");
    CHECK(u[i] == Approx(kV + gust).margin(5e-3));
  }
}

// Intent: an event without its rotor diameter, and a uniform wind file with a bad row, stop before
// anything is written: the first at the deck's wind section, the second at the file's line.
TEST_CASE("bad event inputs and bad uniform wind files stop at their file:line", "[unit][wind][run]") {
  const auto dir = testing::scratch_dir("wind_event_input_checks");
  const std::string turbine = (testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml").string();
  std::ofstream(dir / "deck.yaml") << "include: [" << turbine << "]\nwind:\n  event: {type: EDC}\n";
  std::string message;
  try {
    run_scene(run_request(dir / "deck.yaml", dir / "run", std::nullopt), nullptr);
  } catch (const InputError& e) {
    message = e.what();
  }
  CHECK_THAT(message, Catch::Contains("deck.yaml:") && Catch::Contains("wind.event.rotor_diameter_m"));
  std::ofstream(dir / "bad.hh") << "! header\n0 12 0 0 0 0.2 0 0\n10 12 0 0 0 0.2 0\n";
  std::ofstream(dir / "deck.yaml") << "include: [" << turbine << "]\nwind: {model: uniform_file, file: bad.hh, reference_length_m: 126}\n";
  message.clear();
  try {
    run_scene(run_request(dir / "deck.yaml", dir / "run", std::nullopt), nullptr);
  } catch (const InputError& e) {
    message = e.what();
  }
  CHECK_THAT(message, Catch::Contains("bad.hh:3: expected 8 numbers as in the first data row"));
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    CHECK((entry.path().filename() == "deck.yaml" || entry.path().filename() == "bad.hh"));
}
