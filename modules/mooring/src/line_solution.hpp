#pragma once
// Internal: one line solved at one platform pose, shared by the module, the stiffness and the
// profile functions.
#include <cstddef>
#include <optional>

#include "fowtsim/mooring/quasi_static_mooring.hpp"

namespace fowtsim::mooring::detail {

// Where line i sits at a pose.
struct LineGeometry {
  Vec3 lever_m = Vec3::Zero();       // r = T_gb r_b: reference point → fairlead, g [m]
  Vec3 fairlead_m = Vec3::Zero();    // p_F, g [m]
  Vec3 chord_m = Vec3::Zero();       // d = p_F − p_A, g [m]
  Vec3 horizontal_unit = Vec3::UnitX();  // e_h: horizontal unit vector anchor → fairlead (x if vertical)
  double span_x_m = 0.0;             // X = |d_h| [m]
  double span_z_m = 0.0;             // Z = d_z [m]
};

LineGeometry line_geometry(const MooringParams& p, std::size_t index, const FrameMotion& pose);

// A solved line: the per-line outputs and, for the catenary model, the 2-D solution.
struct SolvedLine {
  LineOutput output;
  CatenarySolution catenary;  // meaningful for LineModel::catenary only
};

// Solves line `index` at `geometry`, warm-started from `warm`. Throws NumericalError (with the
// line number, `time_s` and a hint) when the catenary has no converged solution.
SolvedLine solve_line(const MooringParams& p, std::size_t index, const LineGeometry& geometry,
                      const QuasiStaticMooring::LineWarmStart& warm, std::optional<double> time_s);

// Throws NumericalError unless the pose is finite.
void check_pose(const FrameMotion& pose, std::optional<double> time_s);

// Platform yaw ψ (Euler 1-2-3 θ₃ of T_gb) used by the delta-connection yaw spring [rad].
double platform_yaw_rad(const Mat3& orientation);

}  // namespace fowtsim::mooring::detail
