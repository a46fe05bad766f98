#pragma once
// The NREL 5-MW baseline controller as a fowtsim module (DESIGN.md §2), run by the driver at the
// large step ΔT (DESIGN.md §4). Sample-and-hold semantics:
//   advance(p, u, t, dt, s)  samples the measurements u taken at time t; the law (baseline_law.hpp)
//                            filters the speed and, when its sample time has elapsed since its last
//                            update, recomputes the demands; they are then held over [t, t + dt].
//                            dt only has to be finite and > 0: the law uses the time actually
//                            elapsed since its last update (the DISCON "LastTime" logic).
//   outputs(p, u, s)         the held demands; before the first advance, those the first call would
//                            set (torque from the schedule at the measured speed, pitch as measured).
// Channels (OpenFAST ServoDyn/ElastoDyn names and units): GenTq [kN·m], GenPwr [kW],
// BlPitchC1–3 [deg] (the pitch command; the blades' own pitch BldPitch· is the structure's), GenSpeed [rpm].
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "fowtsim/control/baseline_law.hpp"
#include "fowtsim/control/baseline_params.hpp"
#include "fowtsim/core/channels.hpp"

namespace fowtsim::control {

// Measurements handed to a controller (the built-in law and the DLL interface share it).
struct ControllerInput {
  double generator_speed_rad_s = 0.0;                 // ω: generator (HSS) speed [rad/s]
  double rotor_speed_rad_s = 0.0;                     // Ω: rotor (LSS) speed [rad/s]; DLL record 21, unused by the baseline law
  std::array<double, kBladeCount> blade_pitch_rad{};  // measured blade pitch angles [rad]
  double hub_wind_speed_m_s = 0.0;                    // hub-height wind speed [m/s]; DLL record 27, unused by the baseline law
  int generator_contactor = 1;                        // the turbine's contactor, 1 on / 0 off (DLL record 35 sent; events.hpp)
  int shaft_brake = 0;                                // the turbine's HSS brake, 0 off / 1 on (DLL record 36 sent)
};

// What a controller hands back (the built-in law and the DLL interface share it).
struct ControllerOutput {
  double generator_torque_N_m = 0.0;                  // generator-torque demand, HSS [N·m] (applied as is: no generator dynamics)
  std::array<double, kBladeCount> blade_pitch_rad{};  // blade-pitch demands [rad]
  double generator_power_W = 0.0;                     // electrical power T ω η [W] with the measured ω (OpenFAST GenPwr)
  double generator_speed_rad_s = 0.0;                 // measured generator speed [rad/s] (copied, for the GenSpeed channel)
  int generator_contactor = 1;                        // the law's request (DLL record 35 returned), then the turbine's state: 1 on, 0 off
  int shaft_brake = 0;                                // the law's request (DLL record 36 returned), then the turbine's: 0 off, 1 on
};

// GenTq, GenPwr, BlPitchC1–3, GenSpeed (module name `module`).
std::vector<ChannelInfo> controller_channels(const char* module);

// Values of controller_channels() in that order and in the channel units; values.size() must be 6
// (InputError otherwise).
void controller_channel_values(const ControllerOutput& y, std::span<double> values);

struct BaselineController {
  using Params = BaselineParams;
  using State = BaselineState;
  using Input = ControllerInput;
  using Output = ControllerOutput;

  // Validates p (InputError) and returns the state of a controller not yet called.
  static State make_state(const Params& p);

  // Samples u at time t and holds the demands over [t, t + dt] (see the header comment). Throws
  // NumericalError (module "control", time t, the quantity, a hint) on non-finite measurements or
  // results, or when t is earlier than the previous call.
  static void advance(const Params& p, const Input& u, double t, double dt, State& s);

  static Output outputs(const Params& p, const Input& u, const State& s);
  static std::vector<ChannelInfo> channels(const Params& p);
  static void channel_values(const Params& p, const Output& y, std::span<double> values);
};

}  // namespace fowtsim::control
