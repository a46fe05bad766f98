#include "fowtsim/mooring/quasi_static_mooring.hpp"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "line_solution.hpp"

namespace fowtsim::mooring {

using Mooring = QuasiStaticMooring;

Mooring::State Mooring::make_state(const Params& p) {
  validate(p);
  return {};
}

Mooring::Output Mooring::evaluate(const Params& p, const Input& u, State& s) {
  detail::check_pose(u.platform, u.time_s);
  Output y;
  y.line_count = p.lines.size();
  for (std::size_t i = 0; i < p.lines.size(); ++i) {
    const detail::LineGeometry g = detail::line_geometry(p, i, u.platform);
    const detail::SolvedLine solved = detail::solve_line(p, i, g, s.lines[i], u.time_s);
    y.lines[i] = solved.output;
    y.lines[i].fairlead_m = g.fairlead_m;
    y.force_N += solved.output.force_N;
    y.moment_N_m += g.lever_m.cross(solved.output.force_N);
    if (p.model == LineModel::catenary) {
      s.lines[i] = {solved.catenary.fairlead_h_N, solved.catenary.fairlead_v_N, true};
    }
  }
  if (p.delta_yaw_stiffness_N_m_rad > 0.0) {
    y.yaw_spring_moment_N_m = -p.delta_yaw_stiffness_N_m_rad * detail::platform_yaw_rad(u.platform.orientation);
    y.moment_N_m.z() += y.yaw_spring_moment_N_m;
  }
  return y;
}

void Mooring::advance(const Params& p, const Input& u, double t, double dt, State& s) {
  Input dated = u;
  dated.time_s = t + dt;
  evaluate(p, dated, s);
}

Mooring::Output Mooring::outputs(const Params& p, const Input& u, const State& s) {
  State scratch = s;
  return evaluate(p, u, scratch);
}

std::vector<ChannelInfo> Mooring::channels(const Params& p) {
  std::vector<ChannelInfo> all = {
      {"MoorFxi", "N", "total mooring force on the platform, inertial x", "mooring"},
      {"MoorFyi", "N", "total mooring force on the platform, inertial y", "mooring"},
      {"MoorFzi", "N", "total mooring force on the platform, inertial z (up)", "mooring"},
      {"MoorMxi", "N-m", "total mooring moment about the platform reference point, inertial x", "mooring"},
      {"MoorMyi", "N-m", "total mooring moment about the platform reference point, inertial y", "mooring"},
      {"MoorMzi", "N-m", "total mooring moment about the platform reference point, inertial z (incl. yaw spring)",
       "mooring"}};
  for (std::size_t i = 1; i <= p.lines.size(); ++i) {
    all.push_back({fmt::format("FAIRTEN{}", i), "N", fmt::format("line {} tension at the fairlead", i), "mooring"});
    all.push_back({fmt::format("ANCHTEN{}", i), "N", fmt::format("line {} tension at the anchor", i), "mooring"});
    all.push_back({fmt::format("FAIRH{}", i), "N", fmt::format("line {} horizontal tension at the fairlead", i),
                   "mooring"});
    all.push_back({fmt::format("FAIRV{}", i), "N",
                   fmt::format("line {} vertical tension at the fairlead (positive pulling down)", i), "mooring"});
  }
  return all;
}

void Mooring::channel_values(const Params& p, const Output& y, std::span<double> values) {
  const std::size_t expected = 6 + 4 * p.lines.size();
  if (values.size() != expected || y.line_count != p.lines.size()) {
    throw InputError({"mooring", std::nullopt, "channel values", "size values as channels(params)"},
                     fmt::format("values.size() = {} but channels(params).size() = {} (output has {} lines, "
                                 "params {})",
                                 values.size(), expected, y.line_count, p.lines.size()));
  }
  for (int k = 0; k < 3; ++k) {
    values[k] = y.force_N[k];
    values[3 + k] = y.moment_N_m[k];
  }
  for (std::size_t i = 0; i < p.lines.size(); ++i) {
    const LineOutput& l = y.lines[i];
    values[6 + 4 * i] = l.fairlead_tension_N;
    values[7 + 4 * i] = l.anchor_tension_N;
    values[8 + 4 * i] = l.fairlead_h_N;
    values[9 + 4 * i] = l.fairlead_v_N;
  }
}

}  // namespace fowtsim::mooring
