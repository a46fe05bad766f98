#include "scenes/platform_scene.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "decks/hydro_deck.hpp"
#include "decks/mooring_deck.hpp"
#include "decks/waves_deck.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/core/version.hpp"
#include "fowtsim/hydro/hydro.hpp"
#include "fowtsim/mooring/quasi_static_mooring.hpp"
#include "fowtsim/waves/waves_module.hpp"
#include "run/channel_selection.hpp"
#include "run/output_set.hpp"

namespace fowtsim::driver {
namespace {

using io::Schema;
constexpr double kDegree = 3.14159265358979323846 / 180.0;
const char* const kDofNames[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};

Schema motion_schema() {
  const Schema harmonic = Schema::map({
      {"dof", Schema::choice({"surge", "sway", "heave", "roll", "pitch", "yaw"}).doc("platform DOF")},
      {"amplitude", Schema::number().doc("amplitude [m for surge, sway, heave; deg for roll, pitch, yaw]")},
      {"period_s", Schema::number().greater_than(0.0).doc("period")},
      {"phase_deg", Schema::number().default_value(0.0).doc("phase: amplitude · sin(2π t/T + phase)")},
  });
  return Schema::map({
      {"offset_m", number_vector(3, "constant surge, sway, heave of the reference point").optional()},
      {"euler_123_deg", number_vector(3, "constant roll, pitch, yaw (Euler 1-2-3)").optional()},
      {"harmonic", Schema::sequence(harmonic).optional().doc("harmonic motions added to the offsets")},
  });
}

// Prescribed platform DOFs q(t) = q0 + Σ a sin(ω t + φ) and their rates [m, rad].
struct Trajectory {
  Vec6 mean = Vec6::Zero();
  struct Harmonic {
    int dof;
    double amplitude, omega, phase;
  };
  std::vector<Harmonic> harmonics;

  void at(double t, Vec6& q, Vec6& q_dot) const {
    q = mean;
    q_dot.setZero();
    for (const Harmonic& h : harmonics) {
      q[h.dof] += h.amplitude * std::sin(h.omega * t + h.phase);
      q_dot[h.dof] += h.amplitude * h.omega * std::cos(h.omega * t + h.phase);
    }
  }
};

Trajectory read_trajectory(const io::ValidatedDeck& d) {
  Trajectory tr;
  if (d.has("offset_m")) tr.mean.head<3>() = vec3(d, "offset_m");
  if (d.has("euler_123_deg")) tr.mean.tail<3>() = kDegree * vec3(d, "euler_123_deg");
  if (d.has("harmonic")) {
    for (std::size_t i = 0; i < d.size("harmonic"); ++i) {
      const io::ValidatedDeck h = d.section(fmt::format("harmonic[{}]", i));
      const std::string dof = h.string("dof");
      int k = 0;
      while (dof != kDofNames[k]) ++k;
      const double unit = k < 3 ? 1.0 : kDegree;
      tr.harmonics.push_back({k, unit * h.number("amplitude"), 2.0 * 3.14159265358979323846 / h.number("period_s"),
                              kDegree * h.number("phase_deg")});
    }
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

// Wave kinematics at the hydro strip nodes: precomputed once at the nodes' positions for the
// mean pose (HydroDyn's default: kinematics at the undisplaced nodes), looked up by node index.
struct HydroWaves {
  std::unique_ptr<waves::PrecomputedKinematics> nodes;

  HydroWaves(const waves::WaveField& field, const hydro::Params& hp, const FrameMotion& mean_pose) {
    hydro::Points points(3, hydro::node_count(hp));
    const VecX calm = VecX::Zero(static_cast<Eigen::Index>(hp.members.size()));
    hydro::strip_points(hp, mean_pose, calm, points);
    std::vector<Vec3> list;
    for (Eigen::Index i = 0; i < points.cols(); ++i) list.emplace_back(points.col(i));
    nodes = std::make_unique<waves::PrecomputedKinematics>(field, list);
  }

  void fill(double t, hydro::Hydro::Input& in) const {
    for (std::size_t i = 0; i < nodes->size(); ++i) {
      const waves::WaveKinematics k = nodes->at(i, t);
      in.fluid_velocity_m_s.col(static_cast<Eigen::Index>(i)) = k.velocity_m_s;
      in.fluid_acceleration_m_s2.col(static_cast<Eigen::Index>(i)) = k.acceleration_m_s2;
      in.dynamic_pressure_Pa[static_cast<Eigen::Index>(i)] = k.dynamic_pressure_Pa;
    }
  }
};

}  // namespace

Schema platform_scene_schema() {
  return Schema::map({
      {"simulation", Schema::map({
                         {"t_max_s", Schema::number().unit("s").greater_than(0.0).default_value(600.0).doc("simulated time")},
                         {"dt_s", Schema::number().unit("s").greater_than(0.0).default_value(0.05).doc("time step")},
                     }).doc("time span and step")},
      {"output", Schema::map({
                     {"format", Schema::choice({"h5", "out", "both"}).default_value("h5").doc("HDF5, OpenFAST text .out, or both")},
                     {"decimation", Schema::integer().at_least(1).default_value(1).doc("write every k-th step")},
                     {"channels", Schema::sequence(Schema::string()).optional().doc("channel names; absent = all")},
                 }).optional().doc("what to write")},
      {"platform_motion", motion_schema().doc("prescribed platform motion (reference point at SWL)")},
      {"waves", waves_schema().optional().doc("incident sea; absent = still water")},
      {"hydro", hydro_schema().optional().doc("Morison strips, hydrostatics, linear extras; absent = none")},
      {"mooring", mooring_schema().optional().doc("mooring lines; absent = none")},
  });
}

bool is_platform_scene(const std::filesystem::path& deck) {
  return io::load_deck(deck).root.find("platform_motion") != nullptr;
}

RunReport run_platform_scene(const RunRequest& request, const ProgressCallback& progress) {
  const io::ValidatedDeck deck = io::read_deck(platform_scene_schema(), request.deck_path);
  const Trajectory trajectory = read_trajectory(deck.section("platform_motion"));
  const double t_max = request.t_max_s.value_or(deck.number("simulation.t_max_s"));
  const double dt = deck.number("simulation.dt_s");

  // Modules the deck names, with their parameters validated before the run.
  const waves::WaveParams wave_params_in = deck.has("waves") ? wave_params(deck.section("waves")) : waves::WaveParams{};
  const waves::Waves::Params sea = waves::Waves::make_params(wave_params_in);
  std::optional<hydro::Params> hydro_p;
  if (deck.has("hydro")) hydro_p = hydro_params(deck.section("hydro"));
  std::optional<mooring::MooringParams> mooring_p;
  if (deck.has("mooring")) mooring_p = mooring_params(deck.section("mooring"));

  std::vector<ChannelInfo> all = platform_channels();
  const std::size_t wave_first = all.size();
  for (const ChannelInfo& c : waves::Waves::channels(sea)) all.push_back(c);
  const std::size_t hydro_first = all.size();
  if (hydro_p)
    for (const ChannelInfo& c : hydro::Hydro::channels(*hydro_p)) all.push_back(c);
  const std::size_t mooring_first = all.size();
  if (mooring_p)
    for (const ChannelInfo& c : mooring::QuasiStaticMooring::channels(*mooring_p)) all.push_back(c);
  const std::vector<std::size_t> picked = select_channels(deck, all, "platform");
  std::vector<ChannelInfo> written;
  for (std::size_t i : picked) written.push_back(all[i]);

  Vec6 q, q_dot;
  trajectory.at(0.0, q, q_dot);
  std::optional<HydroWaves> hydro_waves;
  hydro::Hydro::Input hydro_in;
  if (hydro_p) {
    hydro_in = hydro::make_input(*hydro_p);
    if (!sea.field->calm()) hydro_waves.emplace(*sea.field, *hydro_p, platform_motion(trajectory.mean, Vec6::Zero()));
  }
  hydro::Points waterline(3, hydro_p ? static_cast<Eigen::Index>(hydro_p->members.size()) : 0);
  mooring::QuasiStaticMooring::State mooring_state;
  if (mooring_p) mooring_state = mooring::QuasiStaticMooring::make_state(*mooring_p);
  waves::Waves::State wave_state = waves::Waves::make_state(sea);

  const std::string format = request.output_format.value_or(deck.has("output") ? deck.string("output.format") : "h5");
  const long decimation = deck.has("output") ? deck.integer("output.decimation") : 1;
  OutputSet outputs(request.output_base.value_or(std::filesystem::path("runs") / request.deck_path.stem()), format);
  RunReport report;
  report.outputs = outputs.paths();
  report.coupling = "prescribed motion";
  io::RunMetadata metadata;
  metadata.version = kVersion;
  metadata.deck_path = request.deck_path.string();
  metadata.deck_hash = deck.hash();
  if (deck.has("waves")) metadata.seeds = {wave_params_in.seed};
  metadata.dt_s = dt;
  metadata.dt_coupling_s = dt;
  metadata.extra = {{"scene", "platform"}};
  outputs.begin(written, metadata);

  std::vector<double> values(all.size()), row(picked.size());
  auto write_row = [&](double t) {
    for (int k = 0; k < 6; ++k) values[k] = k < 3 ? q[k] : q[k] / kDegree;
    const waves::Waves::Output wo = waves::Waves::outputs(sea, {}, wave_state);
    for (std::size_t k = 0; k < wo.probe_count; ++k) values[wave_first + k] = wo.elevation_m[k];
    const FrameMotion pose = platform_motion(q, q_dot);
    if (hydro_p) {
      hydro_in.platform = pose;
      hydro_in.time_s = t;
      if (hydro_p->surface == hydro::SurfaceModel::wave_elevation) {
        hydro::waterline_points(*hydro_p, pose, waterline);
        for (Eigen::Index m = 0; m < waterline.cols(); ++m)
          hydro_in.surface_elevation_m[m] = sea.field->calm() ? 0.0 : sea.field->elevation(waterline(0, m), waterline(1, m), t);
      }
      if (hydro_waves) hydro_waves->fill(t, hydro_in);
      const auto ho = hydro::Hydro::outputs(*hydro_p, hydro_in, {});
      const auto hv = hydro::channel_values(ho);
      std::copy(hv.begin(), hv.end(), values.begin() + static_cast<long>(hydro_first));
    }
    if (mooring_p) {
      mooring::QuasiStaticMooring::Input mi{pose, t};
      const auto mo = mooring::QuasiStaticMooring::evaluate(*mooring_p, mi, mooring_state);
      mooring::QuasiStaticMooring::channel_values(*mooring_p, mo,
                                                  std::span<double>(values).subspan(mooring_first));
    }
    for (std::size_t k = 0; k < picked.size(); ++k) row[k] = values[picked[k]];
    outputs.append(t, row);
  };

  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const long steps = std::lround(t_max / dt);
  double t = 0.0;
  try {
    write_row(t);
    for (long k = 1; k <= steps; ++k) {
      waves::Waves::advance(sea, {}, t, dt, wave_state);
      t = k * dt;
      trajectory.at(t, q, q_dot);
      if (k % decimation == 0) write_row(t);
      if (progress) progress(t, t_max);
    }
  } catch (const NumericalError& e) {
    outputs.finish({elapsed(), std::string("failed: ") + e.what(), t});
    throw;
  }
  report.wall_s = elapsed();
  report.simulated_s = t;
  report.large_steps = steps;
  outputs.finish({report.wall_s, "completed", t});
  return report;
}

}  // namespace fowtsim::driver
