// A Bladed-style DISCON controller built from fowtsim's own baseline law (baseline_law.cpp and
// presets.cpp are compiled into this shared library), for testing the external-controller
// interface: driven through the swap array it must reproduce BaselineController's time series.
//
// accInfile names the parameter set: "nrel5mw_land" or "oc3_hywind" (presets.hpp); any other name
// fails the first call with aviFAIL = −1 and a message, which the tests use to check the error path.
// With the suffix "+trip" it also trips on overspeed: above kTripSpeed it opens the generator
// contactor (record 35 = 0) and applies the shaft brake (record 36 = 1), latched. Every call it
// echoes the contactor and brake records it received into the first two logging records (165, 166).
// With "+pitch_override" or "+torque_override" it requests the simulator's built-in override
// (record 55 or 56 = 1) from t = 1 s on.
// Like any DISCON it keeps its state in static variables between calls.
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "fowtsim/control/baseline_law.hpp"
#include "fowtsim/control/presets.hpp"
#include "fowtsim/control/swap_records.hpp"

namespace {

using namespace fowtsim::control;

constexpr float kTripSpeed = 130.0f;  // generator speed of the "+trip" overspeed trip [rad/s]

struct Controller {
  BaselineParams params;
  TorqueCurve curve;
  BaselineState state;
  bool trips = false;    // "+trip" given
  bool tripped = false;  // the overspeed trip has fired
  int override_record = 0;  // 55 or 56 with "+pitch_override" / "+torque_override", else 0
};
std::optional<Controller> controller;  // the DISCON's state between calls

float& at(float* swap_array, int record) { return swap_array[record - 1]; }

void set_message(float* swap_array, char* message, const std::string& text) {
  const int capacity = static_cast<int>(std::lround(at(swap_array, swap::message_capacity)));
  if (capacity > 0) std::snprintf(message, static_cast<std::size_t>(capacity), "%s", text.c_str());
}

}  // namespace

extern "C" __attribute__((visibility("default"))) void DISCON(float* avrSWAP, int* aviFAIL, const char* accInfile,
                                                             char* /*avcOutname*/, char* avcMsg) {
  const int status = static_cast<int>(std::lround(at(avrSWAP, swap::status)));
  *aviFAIL = 0;
  if (status == -1) {  // final call: nothing to close
    controller.reset();
    return;
  }
  if (status == 0) {
    std::string name = accInfile;
    int override_record = 0;
    for (const auto& [suffix, record] : {std::pair{std::string("+pitch_override"), swap::pitch_override},
                                         std::pair{std::string("+torque_override"), swap::torque_override}})
      if (name.ends_with(suffix)) {
        override_record = record;
        name.resize(name.size() - suffix.size());
      }
    const bool trips = name.size() > 5 && name.ends_with("+trip");
    if (trips) name.resize(name.size() - 5);
    const std::optional<BaselineParams> params = baseline_preset(name);
    if (!params) {
      set_message(avrSWAP, avcMsg, std::string("test DISCON: unknown parameter set '") + accInfile +
                                       "' (expected nrel5mw_land or oc3_hywind)");
      *aviFAIL = -1;
      return;
    }
    controller = Controller{*params, torque_curve(*params), BaselineState{}, trips, false, override_record};
  }
  if (!controller) {
    set_message(avrSWAP, avcMsg, "test DISCON: called before its first call (status 0)");
    *aviFAIL = -1;
    return;
  }
  Measurements m;
  m.generator_speed_rad_s = at(avrSWAP, swap::generator_speed);
  m.blade_pitch_rad = {at(avrSWAP, swap::blade1_pitch), at(avrSWAP, swap::blade2_pitch),
                       at(avrSWAP, swap::blade3_pitch)};
  baseline_update(controller->params, controller->curve, m, at(avrSWAP, swap::time), controller->state);

  const BaselineState& s = controller->state;
  at(avrSWAP, swap::generator_torque_demand) = static_cast<float>(s.torque_demand_N_m);
  for (int b = 0; b < kBladeCount; ++b) at(avrSWAP, swap::blade1_pitch_demand + b) = static_cast<float>(s.pitch_demand_rad[b]);
  at(avrSWAP, swap::collective_pitch_demand) = static_cast<float>(s.pitch_demand_rad[0]);
  at(avrSWAP, swap::pitch_rate_demand) = 0.0f;
  at(avrSWAP, swap::logging_count) = 2.0f;
  at(avrSWAP, static_cast<int>(std::lround(at(avrSWAP, swap::logging_start)))) = at(avrSWAP, swap::generator_contactor);
  at(avrSWAP, static_cast<int>(std::lround(at(avrSWAP, swap::logging_start))) + 1) = at(avrSWAP, swap::shaft_brake);
  if (controller->trips && m.generator_speed_rad_s > kTripSpeed) controller->tripped = true;
  at(avrSWAP, swap::generator_contactor) = controller->tripped ? 0.0f : 1.0f;
  at(avrSWAP, swap::shaft_brake) = controller->tripped ? 1.0f : 0.0f;
  at(avrSWAP, swap::yaw_actuator_torque) = 0.0f;
  at(avrSWAP, swap::yaw_rate_demand) = 0.0f;
  at(avrSWAP, swap::pitch_override) = 0.0f;
  at(avrSWAP, swap::torque_override) = 0.0f;
  if (controller->override_record != 0 && at(avrSWAP, swap::time) >= 1.0f) at(avrSWAP, controller->override_record) = 1.0f;
}
