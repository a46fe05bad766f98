#include "fowtsim/aero/benchmarks.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "fowtsim/aero/aero.hpp"
#include "fowtsim/aero/rigid_rotor.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::aero::benchmarks {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

BenchRow time_rotor(const std::string& name, const Params& params, int repeats) {
  const RigidRotor rotor{Vec3(-5.0, 0.0, 90.0), 0.0, 5.0 * kDegree, 2.5 * kDegree, 1.5};
  const double speed = 11.87 * std::numbers::pi / 30.0;
  Aero::Input in = make_input(params);
  Aero::Output out = make_output(params);
  in.inflow_velocity_m_s.colwise() = Vec3(11.0, 0.0, 0.0);
  long calls = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < repeats; ++i) {
    place_rigid_rotor(params, rotor, 2.0 * std::numbers::pi * i / repeats, speed, 0.0, in);
    evaluate(params, in, Aero::State{}, out);
    for (const NodeResult& n : out.nodes) calls += n.section.residual_evaluations;
  }
  const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  BenchRow row;
  row.name = name;
  row.blades = params.number_of_blades;
  row.nodes_per_blade = nodes_per_blade(params);
  row.us_per_evaluation = us / repeats;
  row.us_per_node = row.us_per_evaluation / node_count(params);
  row.residual_calls_per_node = static_cast<double>(calls) / (static_cast<double>(repeats) * node_count(params));
  row.power_W = out.rotor.power_W;
  return row;
}

}  // namespace

Params resample_blade(const Params& params, int nodes) {
  if (nodes < 2 || params.blade.size() < 2) {
    throw InputError({"aero", std::nullopt, "nodes", "ask for at least 2 nodes"},
                     fmt::format("cannot resample a blade of {} nodes to {} nodes", params.blade.size(), nodes));
  }
  Params out = params;
  out.blade.clear();
  out.output_nodes.clear();
  const std::vector<BladeNodeParams>& b = params.blade;
  const double s0 = b.front().span_m, s1 = b.back().span_m;
  std::size_t j = 0;
  for (int k = 0; k < nodes; ++k) {
    const double s = s0 + (s1 - s0) * k / (nodes - 1);
    while (j + 2 < b.size() && b[j + 1].span_m < s) ++j;
    const BladeNodeParams &p = b[j], &q = b[j + 1];
    const double w = std::clamp((s - p.span_m) / (q.span_m - p.span_m), 0.0, 1.0);
    auto lin = [w](double x, double y) { return x + w * (y - x); };
    BladeNodeParams n;
    n.span_m = s;
    n.curve_ac_m = lin(p.curve_ac_m, q.curve_ac_m);
    n.sweep_ac_m = lin(p.sweep_ac_m, q.sweep_ac_m);
    n.curve_angle_rad = lin(p.curve_angle_rad, q.curve_angle_rad);
    n.twist_rad = lin(p.twist_rad, q.twist_rad);
    n.chord_m = lin(p.chord_m, q.chord_m);
    n.airfoil = w < 0.5 ? p.airfoil : q.airfoil;
    out.blade.push_back(n);
  }
  return out;
}

std::vector<BenchRow> rotor_evaluation_bench(const Params& params, int repeats) {
  return {time_rotor("3 blades x 17 nodes (AeroDyn v13 5MW count)", resample_blade(params, 17), repeats),
          time_rotor(fmt::format("3 blades x {} nodes (deck)", params.blade.size()), params, repeats),
          time_rotor("3 blades x 49 nodes", resample_blade(params, 49), repeats)};
}

}  // namespace fowtsim::aero::benchmarks
