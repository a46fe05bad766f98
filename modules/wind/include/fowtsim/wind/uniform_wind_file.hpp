#pragma once
// OpenFAST InflowWind uniform wind files (WindType 2, `.hh`; formerly "hub-height files"): rows of
//   Time [s], horizontal speed V [m/s], direction δ [deg], vertical speed V_z [m/s], horizontal
//   linear shear H [-], vertical power-law exponent α [-], vertical linear shear L [-], gust V_g [m/s]
//   and optionally upflow φ [deg],
// linearly interpolated in time, held at the first / last row outside them. Lines whose first
// non-blank character is '!' ('#', '%') are comments; blank lines are skipped. As InflowWind
// (OpenFAST modules/inflowwind/src/InflowWind_IO.f90, IfW_UniformWind_Init, and IfW_FlowField.f90,
// UniformField_GetVel), at wind-frame point (x, y, z), z > 0:
//   V1 = V [(z/RefHt)^α + (H (y cos δ + x sin δ) + L (z − RefHt)) / RefLength] + V_g
//   v  = ((cos φ V1 − sin φ V_z) cos δ, −(cos φ V1 − sin φ V_z) sin δ, sin φ V1 + cos φ V_z),
// zero at and below z = 0. δ turns the flow as InflowWind's PropagationDir (+ from +x towards −y);
// the directions are unwrapped on reading so that consecutive rows differ by less than 180°.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "fowtsim/core/types.hpp"

namespace fowtsim::wind {

struct UniformWindRow {
  double time_s = 0.0;
  double speed_m_s = 0.0;              // V, horizontal speed at RefHt
  double direction_rad = 0.0;          // δ, unwrapped
  double vertical_m_s = 0.0;           // V_z
  double horizontal_shear = 0.0;       // H [-] per RefLength
  double power_law_exponent = 0.0;     // α [-]
  double vertical_linear_shear = 0.0;  // L [-] per RefLength
  double gust_m_s = 0.0;               // V_g, added to the horizontal speed everywhere
  double upflow_rad = 0.0;             // φ (0 when the file has 8 columns)
};

struct UniformWindHistory {
  std::string source;                // file name, for messages
  std::vector<UniformWindRow> rows;  // strictly increasing times
  std::vector<std::size_t> lines;    // 1-based line of each row in the file
};

// Parses the text of a uniform wind file; `source` names it in errors. Throws InputError
// "source:line: …" for a row that is not 8 or 9 numbers (all rows as many as the first), a
// non-finite value, a time not after the previous one, or a direction jump of exactly 180°; and
// "source: …" for a file without data rows.
UniformWindHistory parse_uniform_wind(std::string_view text, const std::string& source);
// Reads and parses the file (InputError if it cannot be opened).
UniformWindHistory read_uniform_wind_file(const std::filesystem::path& path);

// The columns at time t [s]: linear between the rows around t, the first / last row outside.
// Binary search, no allocation.
UniformWindRow uniform_wind_at(const UniformWindHistory& history, double time_s);

// Velocity [m/s, wind frame] of `row` at wind-frame point p [m] (formula above).
Vec3 uniform_wind_velocity(const UniformWindRow& row, const Vec3& p_wind_m, double reference_height_m,
                           double reference_length_m);

}  // namespace fowtsim::wind
