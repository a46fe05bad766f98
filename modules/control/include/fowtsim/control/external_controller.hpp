#pragma once
// A Bladed-style external controller: a shared library exporting
//   void DISCON(float* avrSWAP, int* aviFAIL, const char* accInfile, char* avcOutname, char* avcMsg)
// (Bladed User Manual App. A; the interface of OpenFAST ServoDyn's BladedInterface and of ROSCO),
// loaded with dlopen and called once per advance() with the swap records of swap_records.hpp.
//
// Timing: the library is called at every advance(p, u, t, dt, s) with record 2 = t and record 3 =
// dt; it keeps its own sample-time logic (a DISCON updates when its DT has elapsed since its last
// update). Its demands are held over [t, t + dt], as for BaselineController.
//
// Limits of the interface: the library keeps its own state inside the process (static variables),
// so copying a State does not copy the controller (no retry or checkpoint of an external
// controller), and two ExternalControllers on the same file share one library and its state.
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/core/channels.hpp"

namespace fowtsim::control {

// Signature of the DISCON procedure.
using DisconProcedure = void (*)(float* avrSWAP, int* aviFAIL, const char* accInfile, char* avcOutname, char* avcMsg);

// An open shared library and its DISCON procedure; closes the library when destroyed.
class DisconLibrary {
 public:
  // Opens `path` and looks up `procedure`; throws InputError naming the path (and the symbol)
  // with the loader's message when either fails.
  DisconLibrary(const std::string& path, const std::string& procedure);
  ~DisconLibrary();
  DisconLibrary(const DisconLibrary&) = delete;
  DisconLibrary& operator=(const DisconLibrary&) = delete;

  DisconProcedure procedure() const { return procedure_; }
  const std::string& path() const { return path_; }

 private:
  void* handle_ = nullptr;
  DisconProcedure procedure_ = nullptr;
  std::string path_;
};

inline constexpr int kSwapSize = 512;          // avrSWAP length (records up to 129, logging 165…464)
inline constexpr int kLoggingStart = 165;      // record 63
inline constexpr int kLoggingCapacity = 300;   // record 62
inline constexpr int kStringCapacity = 1024;   // avcOutname and avcMsg buffers, incl. the NUL

// Deck values of an external controller (`controller: {type: dll, …}`).
struct ExternalSettings {
  std::string library_path;              // shared library file (.so)
  std::string procedure = "DISCON";      // exported procedure name (ServoDyn DLL_ProcName)
  std::string infile;                    // accInfile: the controller's own parameter file, passed through
  std::string outname;                   // avcOutname: root name for the controller's own outputs
  bool individual_pitch = false;         // record 28; true: read records 42–44, false: record 45 for every blade
  double min_pitch_rad = 0.0;            // record 6 [rad]
  double max_pitch_rad = 1.570796;       // record 7 [rad]
  double max_pitch_rate_rad_s = 0.1396263;  // records 8 (negated) and 9 [rad/s]
  double below_rated_pitch_rad = 0.0;    // record 5 [rad]
  double demanded_power_W = 0.0;         // record 13 [W] (information for the controller; 0 = none)
  double generator_efficiency = 0.944;   // η for records 15 and GenPwr [-]
};

struct ExternalController {
  struct Params {
    ExternalSettings settings;                       // as in the deck
    std::shared_ptr<const DisconLibrary> library;    // opened once, shared by copies of Params
  };

  struct State {
    int calls = 0;                                   // calls made so far (record 1: 0 on the first)
    double last_call_time_s = 0.0;                   // time of the last call [s]
    std::array<float, kSwapSize> swap{};             // avrSWAP, kept between calls (records 35, 36 are ↔)
    std::array<char, kStringCapacity> outname{};     // avcOutname buffer
    std::array<char, kStringCapacity> message{};     // avcMsg of the last call (a warning when aviFAIL > 0)
    int last_fail = 0;                               // aviFAIL of the last call
    double torque_demand_N_m = 0.0;                  // held record 47 [N·m]
    std::array<double, kBladeCount> pitch_demand_rad{};  // held records 42–44 or 45 [rad]
  };

  using Input = ControllerInput;
  using Output = ControllerOutput;

  // Validates the settings and opens the library (InputError before the run).
  static Params make_params(const ExternalSettings& settings);
  static State make_state(const Params& p);

  // Fills the swap array from u at time t (record 3 = dt), calls the procedure, and holds its
  // demands. Throws NumericalError (module "control.dll", time t, "aviFAIL", the controller's
  // message) when aviFAIL < 0, and as BaselineController on non-finite values.
  static void advance(const Params& p, const Input& u, double t, double dt, State& s);

  // Held demands; before the first call: zero torque and the measured pitch.
  static Output outputs(const Params& p, const Input& u, const State& s);

  // The final call (record 1 = −1) at time t, letting the controller close its files.
  static void finish(const Params& p, double t, State& s);

  static std::vector<ChannelInfo> channels(const Params& p);
  static void channel_values(const Params& p, const Output& y, std::span<double> values);
};

}  // namespace fowtsim::control
