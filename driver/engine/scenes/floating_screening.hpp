#pragma once
// Frequency-domain screening of a floating-turbine deck (`fowtsim screen DECK`, `fowtsim sweep SPEC
// --frequency-domain`; issue 25, "Beyond the seed"): the deck's own scene (FloatingScene) in still
// water and the steady mean wind of its `wind` section is brought to its operating point by a
// static balance — every acceleration zero, the rotor's torque balanced by the controller's steady
// law: region 2 the torque schedule at the rotor speed it finds, region 3 the PI's reference speed
// and the pitch it finds — then linearised there (FloatingScene::linearised_system, and the input
// and output derivatives by central differences of FloatingScene::accelerations and row), closed
// with the controller's linearised dynamics (the generator-speed filter, the gain-scheduled PI
// pitch loop, the torque law's slope: what sets the sign of the platform-pitch damping above rated,
// Larsen & Hanson 2007, Jonkman NREL/TP-500-47266 §7), and solved at each frequency with
//   - WAMIT's A(ω) − A(∞) and B(ω) on the platform, or Morison's constant added mass,
//   - the members' drag linearised stochastically, c = ½ρ C_d D √(8/π) σ_{u_r} per strip, iterated
//     on the relative velocity's σ (Borgman 1967; the seed's √(8/π) σ rule),
//   - the first-order wave excitation (WAMIT's .3 table, or Morison inertia and dynamic pressure),
//   - the rotor-effective longitudinal wind of the deck's IEC Kaimal turbulence (screening_inputs.hpp)
//     through the thrust and torque derivatives the rotor's BEM gives (∂/∂U of the rotor loads).
// The responses are transfer functions (RAOs) of channels the time domain writes under the same
// names and definitions (the scene's row(), linearised): their PSDs and standard deviations.
//
// Not in the model: second-order wave forces (mean drift, slow drift, sum frequency), the
// nonlinearity of drag beyond its equivalent linear damping, the controller's switching between
// regions and its limits, the rotor's periodic (nP) loads and the lateral and vertical turbulence.
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace fowtsim::driver {

struct ScreeningOptions {
  double min_frequency_hz = 1.0 / 600.0;  // lowest frequency: a ten-minute record's resolution [Hz]
  double max_frequency_hz = 1.0;          // highest [Hz]: above the tower's first modes and the waves
  int frequencies = 1200;                 // log-spaced: 0.5 % apart, ≥ 3 points in a 1 %-damped peak
  int max_drag_iterations = 20;           // the drag linearisation stops at 1 % change of every strip's σ
};

struct ScreeningOperatingPoint {
  std::string region;               // "parked", "region 2", "region 3" or "free rotor"
  double wind_speed_m_s = 0.0;      // mean hub-height wind (0 without aerodynamics)
  double rotor_speed_rpm = 0.0;
  double pitch_deg = 0.0;
  double generator_torque_N_m = 0.0;  // HSS
  double platform[6] = {};          // surge, sway, heave [m]; roll, pitch, yaw [deg]
  int newton_iterations = 0;
};

// `--set` settings that start a time-domain run of the same deck at this operating point (rotor speed,
// pitch, surge, heave and pitch of the platform) for `t_max_s`, writing PtfmHeave, PtfmPitch and
// TwrBsMyt: the FD/TD comparisons of the tests and of `fowtsim verify screening`.
std::vector<std::string> time_domain_settings(const ScreeningOperatingPoint& op, double t_max_s);

struct ScreeningMode {
  double frequency_hz = 0.0;   // undamped natural frequency |λ|/2π of the coupled closed-loop model
  double damping_ratio = 0.0;  // −Re λ/|λ|, radiation and drag damping at the mode's own frequency
  std::string dominant;        // the coordinate with the largest entry of the eigenvector
  Eigen::VectorXd shape;       // its displacement part (ScreeningResult::coordinates), phase-aligned on that entry, which is 1
};

struct ScreeningResult {
  ScreeningOperatingPoint operating_point;
  std::vector<ScreeningMode> modes;                 // by frequency
  std::vector<std::string> coordinates;             // of the mode shapes: PtfmSurge … (m, rad), Azimuth, tower modes
  std::vector<std::string> outputs, units;          // channel names (the time domain's) and units
  std::vector<double> mean;                         // the channels at the operating point
  std::vector<double> frequency_hz;
  std::vector<double> wave_spectrum;                // S_ζ(f) [m²/Hz]
  std::vector<double> wind_spectrum;                // rotor-effective S_U(f) [m²/s² per Hz]
  Eigen::MatrixXcd wave_rao;                        // outputs × frequencies, per metre of wave amplitude
  Eigen::MatrixXcd wind_rao;                        // per m/s of rotor-effective wind
  Eigen::MatrixXd psd;                              // one-sided, unit²/Hz: waves and wind (uncorrelated)
  std::vector<double> std_waves, std_wind, std_total;
  double hs_m = 0.0, tp_s = 0.0, sigma_u_m_s = 0.0;  // the sea and the turbulence screened
  int drag_iterations = 0;
  double seconds_set_up = 0.0, seconds_operating_point = 0.0, seconds_linearisation = 0.0, seconds_solve = 0.0;
  double seconds_total() const { return seconds_set_up + seconds_operating_point + seconds_linearisation + seconds_solve; }
};

// The screening of the deck with `--set` settings applied. InputError for a deck without a floating
// scene, with flexible MBBT blades, an external (DISCON) controller, or a sea without a spectrum.
ScreeningResult screen_floating(const std::filesystem::path& deck, const std::vector<std::string>& settings = {},
                                const ScreeningOptions& options = {});

// The channels screened (those the deck's scene has): PtfmSurge, PtfmHeave, PtfmPitch, TwrBsMyt,
// NcIMUTAxs, then with a rotor RotSpeed and BldPitch1.
std::vector<std::string> screening_channels(bool with_rotor);

}  // namespace fowtsim::driver
