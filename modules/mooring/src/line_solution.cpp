#include "line_solution.hpp"

#include <cmath>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"

namespace fowtsim::mooring::detail {
namespace {

// Massless linear spring along the chord (seed 000 §4.4: "each taut-leg mooring line as a
// massless linear spring along the axis of the line"): T = EA (|d| − L)/L, none in compression.
SolvedLine taut_line(const LineParams& line, const LineGeometry& g) {
  SolvedLine solved;
  LineOutput& out = solved.output;
  const double length = g.chord_m.norm();
  const double strain = (length - line.unstretched_length_m) / line.unstretched_length_m;
  out.slack = strain <= 0.0;
  const double tension = out.slack ? 0.0 : line.ea_N * strain;
  const Vec3 unit = length > 0.0 ? Vec3(g.chord_m / length) : Vec3::Zero();
  out.force_N = -tension * unit;  // pulls the fairlead towards the anchor
  out.fairlead_tension_N = out.anchor_tension_N = tension;
  out.fairlead_h_N = out.anchor_h_N = tension * std::hypot(unit.x(), unit.y());
  out.fairlead_v_N = out.anchor_v_N = tension * unit.z();
  return solved;
}

[[noreturn]] void no_equilibrium(std::size_t index, const LineGeometry& g, const CatenarySolution& sol,
                                 std::optional<double> time_s) {
  const bool buried = g.span_z_m < 0.0;
  throw NumericalError(
      {"mooring", time_s, fmt::format("line {} fairlead tension (H, V)", index + 1),
       buried ? "the pose puts the fairlead below the seabed; check the platform motion (heave, pitch) "
                "or the line's fairlead_body_m and anchor_m"
              : "check the line properties; loosen mooring.solver.tolerance or raise its iteration caps"},
      fmt::format("no catenary equilibrium for line {}: horizontal span X = {:.9g} m, vertical span Z = {:.9g} m, "
                  "residual {:.3g} m after {} iterations{}",
                  index + 1, g.span_x_m, g.span_z_m, sol.residual_m, sol.iterations,
                  buried ? " (fairlead below the seabed)" : ""));
}

}  // namespace

LineGeometry line_geometry(const MooringParams& p, std::size_t index, const FrameMotion& pose) {
  const LineParams& line = p.lines[index];
  LineGeometry g;
  g.lever_m = pose.orientation * line.fairlead_body_m;
  g.fairlead_m = pose.position_m + g.lever_m;
  g.chord_m = g.fairlead_m - line.anchor_m;
  g.span_x_m = std::hypot(g.chord_m.x(), g.chord_m.y());
  g.span_z_m = g.chord_m.z();
  if (g.span_x_m > 0.0) g.horizontal_unit = Vec3(g.chord_m.x() / g.span_x_m, g.chord_m.y() / g.span_x_m, 0.0);
  return g;
}

SolvedLine solve_line(const MooringParams& p, std::size_t index, const LineGeometry& g,
                      const QuasiStaticMooring::LineWarmStart& warm, std::optional<double> time_s) {
  if (p.model == LineModel::taut) return taut_line(p.lines[index], g);
  const CatenaryLine line = catenary_line(p, index);
  const CatenaryGuess guess{warm.h_N, warm.v_N};
  SolvedLine solved;
  solved.catenary = solve_catenary(line, g.span_x_m, g.span_z_m, warm.valid ? &guess : nullptr, p.solver);
  const CatenarySolution& sol = solved.catenary;
  if (!sol.converged) no_equilibrium(index, g, sol, time_s);
  LineOutput& out = solved.output;
  out.fairlead_h_N = sol.fairlead_h_N;
  out.fairlead_v_N = sol.fairlead_v_N;
  out.anchor_h_N = sol.anchor_h_N;
  out.anchor_v_N = sol.anchor_v_N;
  out.fairlead_tension_N = std::hypot(sol.fairlead_h_N, sol.fairlead_v_N);
  out.anchor_tension_N = std::hypot(sol.anchor_h_N, sol.anchor_v_N);
  out.grounded_length_m = sol.grounded_length_m;
  out.regime = sol.regime;
  out.iterations = sol.iterations;
  out.force_N = -sol.fairlead_h_N * g.horizontal_unit - sol.fairlead_v_N * Vec3::UnitZ();
  return solved;
}

void check_pose(const FrameMotion& pose, std::optional<double> time_s) {
  if (!pose.position_m.allFinite() || !pose.orientation.allFinite()) {
    throw NumericalError({"mooring", time_s, "platform pose (position_m, orientation)",
                          "the platform motion diverged upstream; reduce the time step"},
                         "non-finite platform pose handed to the mooring");
  }
}

double platform_yaw_rad(const Mat3& orientation) { return matrix_to_euler123(orientation).z(); }

}  // namespace fowtsim::mooring::detail
