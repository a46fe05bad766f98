#pragma once
// Record numbers of the Bladed-style swap array avrSWAP exchanged with a DISCON controller
// (Bladed User Manual, App. A "external controller interface"; as listed by OpenFAST ServoDyn's
// summary "Legacy Bladed DLL interface channel usage"). 1-based, as documented; index the C array
// with record − 1. "→" the simulator writes it, "←" the controller does, "↔" both.
namespace fowtsim::control::swap {

inline constexpr int status = 1;                      // → 0 first call, 1 later calls, −1 final call [-]
inline constexpr int time = 2;                        // → current time [s] (single precision)
inline constexpr int communication_interval = 3;      // → time between calls [s]
inline constexpr int blade1_pitch = 4;                // → measured blade 1 pitch [rad]
inline constexpr int below_rated_pitch = 5;           // → below-rated pitch set-point [rad]
inline constexpr int min_pitch = 6;                   // → minimum pitch [rad]
inline constexpr int max_pitch = 7;                   // → maximum pitch [rad]
inline constexpr int min_pitch_rate = 8;              // → minimum (most negative) pitch rate [rad/s]
inline constexpr int max_pitch_rate = 9;              // → maximum pitch rate [rad/s]
inline constexpr int pitch_actuator_type = 10;        // → 0 = position actuator [-]
inline constexpr int current_pitch_demand = 11;       // → previous blade 1 pitch demand [rad]
inline constexpr int current_pitch_rate_demand = 12;  // → demanded pitch rate, 0 for a position actuator [rad/s]
inline constexpr int demanded_power = 13;             // → demanded power [W]
inline constexpr int measured_shaft_power = 14;       // → previous torque demand × measured generator speed [W]
inline constexpr int measured_electrical_power = 15;  // → the same × generator efficiency [W]
inline constexpr int optimal_mode_gain = 16;          // → optimal-mode gain [N·m/(rad/s)²]
inline constexpr int min_generator_speed = 17;        // → minimum generator speed [rad/s]
inline constexpr int optimal_mode_max_speed = 18;     // → optimal-mode maximum speed [rad/s]
inline constexpr int demanded_speed_above_rated = 19; // → demanded generator speed above rated [rad/s]
inline constexpr int generator_speed = 20;            // → measured generator (HSS) speed [rad/s]
inline constexpr int rotor_speed = 21;                // → measured rotor (LSS) speed [rad/s]
inline constexpr int demanded_torque_above_rated = 22;// → demanded generator torque above rated [N·m]
inline constexpr int measured_generator_torque = 23;  // → previous torque demand [N·m]
inline constexpr int yaw_error = 24;                  // → measured yaw error [rad]
inline constexpr int torque_table_start = 25;         // → start record of the torque-speed table (none: 0)
inline constexpr int torque_table_points = 26;        // → points in the torque-speed table (none: 0)
inline constexpr int hub_wind_speed = 27;             // → hub wind speed [m/s]
inline constexpr int pitch_control_mode = 28;         // → 0 collective, 1 individual [-]
inline constexpr int yaw_control_mode = 29;           // → 0 yaw rate [-]
inline constexpr int blade1_root_oop_moment = 30;     // → blade root out-of-plane moments, blades 1–3 [N·m] (30–32)
inline constexpr int blade2_pitch = 33;               // → measured blade 2 pitch [rad]
inline constexpr int blade3_pitch = 34;               // → measured blade 3 pitch [rad]
inline constexpr int generator_contactor = 35;        // ↔ generator contactor, 1 = main generator on [-]
inline constexpr int shaft_brake = 36;                // ↔ shaft brake status, 0 = off [-]
inline constexpr int nacelle_yaw = 37;                // → nacelle yaw from North [rad]
inline constexpr int yaw_actuator_torque = 41;        // ← demanded yaw actuator torque [N·m]
inline constexpr int blade1_pitch_demand = 42;        // ← individual pitch demands, blades 1–3 [rad] (42–44)
inline constexpr int collective_pitch_demand = 45;    // ← collective pitch demand [rad]
inline constexpr int pitch_rate_demand = 46;          // ← demanded pitch rate [rad/s]
inline constexpr int generator_torque_demand = 47;    // ← demanded generator torque [N·m]
inline constexpr int yaw_rate_demand = 48;            // ← demanded nacelle yaw rate [rad/s]
inline constexpr int message_capacity = 49;           // → characters avcMsg can hold (incl. the NUL) [-]
inline constexpr int infile_length = 50;              // → characters of accInfile (incl. the NUL) [-]
inline constexpr int outname_length = 51;             // → characters of avcOutname (incl. the NUL) [-]
inline constexpr int pitch_override = 55;             // ← built-in pitch override requested, 0 = none (≠ 0 refused) [-]
inline constexpr int torque_override = 56;            // ← built-in torque override requested, 0 = none (≠ 0 refused) [-]
inline constexpr int rotor_azimuth = 60;              // → rotor azimuth [rad]
inline constexpr int blade_count = 61;                // → number of blades [-]
inline constexpr int logging_capacity = 62;           // → maximum number of logging values [-]
inline constexpr int logging_start = 63;              // → first record of the logging values [-]
inline constexpr int outname_capacity = 64;           // → characters avcOutname can hold (incl. the NUL) [-]
inline constexpr int logging_count = 65;              // ← number of logging values returned [-]
inline constexpr int swap_size = 129;                 // → size of the avrSWAP array [-]

}  // namespace fowtsim::control::swap
