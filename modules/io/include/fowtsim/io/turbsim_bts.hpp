#pragma once
// TurbSim full-field binary wind files (.bts), read and written, and an HDF5 copy of a field.
//
// Format (TurbSim User's Guide v2.00, Jonkman 2014/2016, Annex D "binary full-field files";
// little-endian; read the same way by OpenFAST InflowWind, IfW_TurbSim_Init):
//   int16  format id: 7 = non-periodic, 8 = periodic
//   int32  nz, ny, n_tower, nt
//   float32 dz, dy, dt [m, m, s], u_hub [m/s], z_hub [m], z_bottom [m]
//   float32 slope_u, offset_u, slope_v, offset_v, slope_w, offset_w
//   int32  n_char, then n_char bytes of description (ASCII)
//   int16  samples: for each time step, for each z (bottom up), for each y (−W/2 … +W/2), the
//          components u, v, w; then for each tower point (z_bottom − k·dz) u, v, w
//   velocity = (int16 − offset) / slope, per component.
// The writer chooses each component's slope and offset so that its minimum maps to −32768 and its
// maximum to 32767 (the whole int16 range, as TurbSim does): quantisation error
// |v − v̂| <= 0.5 / slope = (max − min) / 131070 per component (plus float32 rounding of the header).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "fowtsim/core/wind_grid.hpp"

namespace fowtsim::io {

// A .bts file's field (core's WindGrid, shared with wind::FullField) and its description line.
struct TurbSimField : WindGrid {
  std::string description;  // free text (<= 200 characters kept by OpenFAST)
};

// Reads a .bts file; throws InputError (module "io.turbsim") naming the file on any inconsistency
// (unknown format id, sizes, truncated file).
TurbSimField read_turbsim_bts(const std::filesystem::path& path);

// Writes a .bts file that TurbSim/OpenFAST read. Throws InputError on inconsistent sizes or
// non-finite data, Error when the file cannot be written.
void write_turbsim_bts(const std::filesystem::path& path, const TurbSimField& field);

// Scaling the writer uses for one component (exposed for the round-trip test).
struct Int16Scaling {
  float slope = 1.0f;   // counts per m/s
  float offset = 0.0f;  // counts
};
Int16Scaling int16_scaling(float minimum, float maximum);

// HDF5 copy of a field for post-processing (h5py: f["u"][it, iz, iy]):
//   /u, /v, /w  float32 (nt, nz, ny) [m/s], attribute unit "m/s"
//   /y, /z      float64 grid coordinates [m] (y from −W/2; z above SWL), /t float64 [s]
//   root attributes: seed (uint64), periodic (int), u_hub_m_s, z_hub_m (float64), description
// Tower points are not written. Throws Error (module "io.hdf5") on HDF5 failures.
void write_turbsim_hdf5(const std::filesystem::path& path, const TurbSimField& field, std::uint64_t seed);

}  // namespace fowtsim::io
