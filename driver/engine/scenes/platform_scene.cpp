#include "scenes/platform_scene.hpp"

#include <cmath>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "decks/hydro_deck.hpp"
#include "decks/mooring_deck.hpp"
#include "decks/waves_deck.hpp"
#include "fowtsim/core/rotation.hpp"
#include "run/channel_selection.hpp"
#include "scenes/scene_runner.hpp"
#include "scenes/record_length_warnings.hpp"
#include "scenes/sea_modules.hpp"

namespace fowtsim::driver {
namespace {

using io::Schema;
constexpr double kDegree = 3.14159265358979323846 / 180.0;
const char* const kDofNames[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};

// The platform_motion keys as written, each once with the field it fills (decks/deck_section.hpp);
// read_trajectory turns them into a Trajectory (an amplitude's unit depends on its DOF).
struct HarmonicKeys {
  std::string dof;
  double amplitude = 0.0, period_s = 1.0, phase_deg = 0.0;
};
struct MotionKeys {
  Vec3 offset_m = Vec3::Zero();
  Vec3 euler_123_deg = Vec3::Zero();
  std::optional<std::vector<HarmonicKeys>> harmonic;
};

const DeckSection<MotionKeys>& motion_section() {
  static const DeckSection<MotionKeys> section = [] {
    DeckSection<HarmonicKeys> harmonic;
    harmonic.key("dof", Schema::choice({"surge", "sway", "heave", "roll", "pitch", "yaw"}).doc("platform DOF"), &HarmonicKeys::dof)
        .key("amplitude", Schema::number().doc("amplitude [m for surge, sway, heave; deg for roll, pitch, yaw]"),
             &HarmonicKeys::amplitude)
        .key("period_s", Schema::number().greater_than(0.0).doc("period"), &HarmonicKeys::period_s)
        .key("phase_deg", Schema::number().default_value(0.0).doc("phase: amplitude · sin(2π t/T + phase)"), &HarmonicKeys::phase_deg);
    DeckSection<MotionKeys> m;
    m.key("offset_m", number_vector(3, "constant surge, sway, heave of the reference point").optional(), &MotionKeys::offset_m)
        .key("euler_123_deg", number_vector(3, "constant roll, pitch, yaw (Euler 1-2-3)").optional(), &MotionKeys::euler_123_deg)
        .list("harmonic", harmonic, &MotionKeys::harmonic, 0, "harmonic motions added to the offsets");
    return m;
  }();
  return section;
}

// Prescribed platform DOFs q(t) = q0 + Σ a sin(ω t + φ) and their rates [m, rad].
struct Trajectory {
  Vec6 mean = Vec6::Zero();
  struct Harmonic {
    int dof;
    double amplitude, omega, phase;
  };
  std::vector<Harmonic> harmonics;

  void at(double t, Vec6& q, Vec6& q_dot, Vec6& q_ddot) const {
    q = mean;
    q_dot.setZero();
    q_ddot.setZero();
    for (const Harmonic& h : harmonics) {
      q[h.dof] += h.amplitude * std::sin(h.omega * t + h.phase);
      q_dot[h.dof] += h.amplitude * h.omega * std::cos(h.omega * t + h.phase);
      q_ddot[h.dof] -= h.amplitude * h.omega * h.omega * std::sin(h.omega * t + h.phase);
    }
  }
};

Trajectory read_trajectory(const io::ValidatedDeck& d) {
  MotionKeys keys;
  motion_section().read_into(d, keys);
  Trajectory tr;
  tr.mean.head<3>() = keys.offset_m;
  tr.mean.tail<3>() = kDegree * keys.euler_123_deg;
  for (const HarmonicKeys& h : keys.harmonic.value_or(std::vector<HarmonicKeys>{})) {
    int k = 0;
    while (h.dof != kDofNames[k]) ++k;
    const double unit = k < 3 ? 1.0 : kDegree;
    tr.harmonics.push_back({k, unit * h.amplitude, 2.0 * 3.14159265358979323846 / h.period_s, kDegree * h.phase_deg});
  }
  return tr;
}

// Pose and velocities of the platform for prescribed DOFs: T_gb from Euler 1-2-3, ω in the body
// frame from the angle rates (FrameMotion convention).
FrameMotion platform_motion(const Vec6& q, const Vec6& q_dot) {
  FrameMotion m;
  m.position_m = q.head<3>();
  m.orientation = euler123_to_matrix(q.tail<3>());
  m.velocity_m_s = q_dot.head<3>();
  m.angular_velocity_rad_s = euler123_rate_matrix(q.tail<3>()) * q_dot.tail<3>();
  return m;
}

std::vector<ChannelInfo> platform_channels() {
  return {{"PtfmSurge", "m", "platform surge of the reference point, inertial x", "platform"},
          {"PtfmSway", "m", "platform sway, inertial y", "platform"},
          {"PtfmHeave", "m", "platform heave, inertial z", "platform"},
          {"PtfmRoll", "deg", "platform roll, Euler 1-2-3 angle 1", "platform"},
          {"PtfmPitch", "deg", "platform pitch, Euler 1-2-3 angle 2", "platform"},
          {"PtfmYaw", "deg", "platform yaw, Euler 1-2-3 angle 3", "platform"}};
}

}  // namespace

Schema platform_scene_schema() {
  return Schema::map({
      {"simulation", simulation_schema("time step").doc("time span and step")},
      {"output", output_schema().optional().doc("what to write")},
      {"platform_motion", motion_section().schema().doc("prescribed platform motion (reference point at SWL)")},
      {"report_mooring_stiffness", Schema::boolean().default_value(false)
                                       .doc("write the linearised 6×6 mooring stiffness at the mean pose to the summary and metadata")},
      {"waves", waves_schema().optional().doc("incident sea; absent = still water")},
      {"hydro", hydro_schema().optional().doc("Morison strips, hydrostatics, linear extras, WAMIT potential flow; absent = none")},
      {"mooring", mooring_schema().optional().doc("mooring lines; absent = none")},
  });
}

RunReport run_platform_scene(const RunRequest& request, const ProgressCallback& progress) {
  const io::ValidatedDeck deck = io::read_deck(platform_scene_schema(), request.deck_path, request.deck_settings);
  const Trajectory trajectory = read_trajectory(deck.section("platform_motion"));
  // Wave kinematics at the strip nodes of the mean pose.
  SeaModules sea(deck, platform_motion(trajectory.mean, Vec6::Zero()), simulation_keys(deck).dt_s);

  std::vector<ChannelInfo> all = platform_channels();
  for (const ChannelInfo& c : sea.channels()) all.push_back(c);
  const std::vector<std::size_t> picked = select_channels(deck, all, "platform");

  FixedStepScene scene;
  for (std::size_t i : picked) scene.written.push_back(all[i]);
  scene.metadata.seeds = sea.seeds();
  scene.metadata.extra = {{"scene", "platform"}};
  std::vector<double> values(all.size());
  SeaModules::Data sea_data = sea.initial_data();  // the scene's state: the motion is prescribed
  // The motion is prescribed: a step only evaluates the sea at its end, every step, so the
  // mooring solver's warm starts — and the results — do not depend on output decimation; a row
  // reads the evaluation of its time.
  // A step first moves the radiation memory (potential flow) to its end.
  auto evaluate = [&](double t, bool end_of_step) {
    Vec6 q, q_dot, q_ddot;
    trajectory.at(t, q, q_dot, q_ddot);
    for (int k = 0; k < 6; ++k) values[k] = k < 3 ? q[k] : q[k] / kDegree;
    if (end_of_step) sea.advance(t, platform_motion(q, q_dot), sea_data);
    sea.evaluate(t, platform_motion(q, q_dot), sea_data);
    // The angle rates stand for ω, as in platform_motion (small rotations about the mean).
    sea.channel_values(t, sea_data, q_ddot, std::span<double>(values).subspan(6));
  };
  evaluate(0.0, false);
  scene.step = [&](double t, double dt) { evaluate(t + dt, true); };
  scene.row = [&](double, std::span<double> row) {
    for (std::size_t k = 0; k < picked.size(); ++k) row[k] = values[picked[k]];
  };
  std::vector<std::string> stiffness_rows;
  if (deck.boolean("report_mooring_stiffness")) {
    const Mat6 k = sea.mooring_stiffness(platform_motion(trajectory.mean, Vec6::Zero()));
    std::string flat;
    for (int r = 0; r < 6; ++r) {
      stiffness_rows.push_back(fmt::format("  {:>12.5g} {:>12.5g} {:>12.5g} {:>12.5g} {:>12.5g} {:>12.5g}", k(r, 0), k(r, 1), k(r, 2),
                                           k(r, 3), k(r, 4), k(r, 5)));
      for (int c = 0; c < 6; ++c) flat += fmt::format("{}{:.10g}", flat.empty() ? "" : " ", k(r, c));
    }
    scene.metadata.extra.push_back({"mooring_stiffness_6x6", flat});
  }
  scene.input_warnings = record_length_warnings(nullptr, 0.0, sea.incident_waves(), request.t_max_s.value_or(simulation_keys(deck).t_max_s));
  RunReport report = run_fixed_steps(request, deck, std::move(scene), progress);
  report.coupling = "prescribed motion";
  if (!stiffness_rows.empty()) {
    report.results.push_back("mooring stiffness at the mean pose (N/m, N/rad, N·m/m, N·m/rad; surge … yaw):");
    for (const std::string& row : stiffness_rows) report.results.push_back(row);
  }
  return report;
}

}  // namespace fowtsim::driver
