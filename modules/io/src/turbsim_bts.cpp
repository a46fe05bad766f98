#include "fowtsim/io/turbsim_bts.hpp"

#include <hdf5.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "fowtsim/core/error.hpp"
#include "file_bytes.hpp"
#include "hdf5_check.hpp"

namespace fowtsim::io {
namespace {

static_assert(std::endian::native == std::endian::little, ".bts files are little-endian; add byte swapping");

constexpr const char* kModule = "io.turbsim";
constexpr std::size_t kFixedHeaderBytes = 2 + 4 * 4 + 6 * 4 + 6 * 4 + 4;  // up to and with n_char

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& message, const std::string& hint = "") {
  throw InputError(ErrorContext{kModule, std::nullopt, path.string(), hint}, "'" + path.string() + "': " + message);
}

template <class T>
T take(const std::string& bytes, std::size_t& at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof(T));
  at += sizeof(T);
  return value;
}

template <class T>
void put(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

void check_sizes(const TurbSimField& f, const std::filesystem::path& path) {
  if (f.nz < 1 || f.ny < 1 || f.n_tower < 0 || f.nt < 1) fail(path, "grid sizes must be positive");
  if (f.grid.size() != static_cast<std::size_t>(f.nt) * f.nz * f.ny * 3)
    fail(path, "grid holds " + std::to_string(f.grid.size()) + " values, expected nt*nz*ny*3");
  if (f.tower.size() != static_cast<std::size_t>(f.nt) * f.n_tower * 3)
    fail(path, "tower holds " + std::to_string(f.tower.size()) + " values, expected nt*n_tower*3");
}

}  // namespace

Int16Scaling int16_scaling(float minimum, float maximum) {
  // Whole int16 range, as TurbSim: minimum -> −32768, maximum -> 32767.
  constexpr double low = -32768.0, range = 65535.0;
  const double span = static_cast<double>(maximum) - static_cast<double>(minimum);
  Int16Scaling s;
  s.slope = span > 1e-6 ? static_cast<float>(range / span) : 1000.0f;  // constant: any slope fits
  s.offset = static_cast<float>(low - static_cast<double>(s.slope) * minimum);
  if (!(span > 1e-6)) s.offset = static_cast<float>(-static_cast<double>(s.slope) * minimum);
  return s;
}

TurbSimField read_turbsim_bts(const std::filesystem::path& path) {
  const std::string bytes = detail::read_file_bytes(path, kModule);
  if (bytes.size() < kFixedHeaderBytes) fail(path, "shorter than a TurbSim header", "is the file complete?");
  std::size_t at = 0;
  TurbSimField f;
  const auto id = take<std::int16_t>(bytes, at);
  if (id != 7 && id != 8)
    fail(path, "format id " + std::to_string(id) + " is not a TurbSim full-field id (7 or 8)", "is it a .bts file?");
  f.periodic = id == 8;
  f.nz = take<std::int32_t>(bytes, at);
  f.ny = take<std::int32_t>(bytes, at);
  f.n_tower = take<std::int32_t>(bytes, at);
  f.nt = take<std::int32_t>(bytes, at);
  if (f.nz < 1 || f.ny < 1 || f.n_tower < 0 || f.nt < 1 || f.nz > 100000 || f.ny > 100000 || f.n_tower > 100000)
    fail(path, "implausible grid sizes nz " + std::to_string(f.nz) + ", ny " + std::to_string(f.ny) + ", n_tower " +
                   std::to_string(f.n_tower) + ", nt " + std::to_string(f.nt));
  f.dz_m = take<float>(bytes, at);
  f.dy_m = take<float>(bytes, at);
  f.dt_s = take<float>(bytes, at);
  f.u_hub_m_s = take<float>(bytes, at);
  f.z_hub_m = take<float>(bytes, at);
  f.z_bottom_m = take<float>(bytes, at);
  float slope[3], offset[3];
  for (int c = 0; c < 3; ++c) {
    slope[c] = take<float>(bytes, at);
    offset[c] = take<float>(bytes, at);
    if (!(std::isfinite(slope[c]) && slope[c] != 0.0f && std::isfinite(offset[c])))
      fail(path, "invalid scaling of component " + std::to_string(c));
  }
  const auto n_char = take<std::int32_t>(bytes, at);
  if (n_char < 0 || static_cast<std::size_t>(n_char) > bytes.size() - at) fail(path, "bad description length");
  f.description.assign(bytes.data() + at, static_cast<std::size_t>(n_char));
  at += static_cast<std::size_t>(n_char);

  // Compare by division: per_step · nt could overflow size_t for a corrupt header.
  const std::size_t per_step = (static_cast<std::size_t>(f.nz) * f.ny + f.n_tower) * 3;
  if (static_cast<std::size_t>(f.nt) > (bytes.size() - at) / 2 / per_step)
    fail(path, "truncated: " + std::to_string(bytes.size()) + " bytes cannot hold the " + std::to_string(f.nt) + " time steps the header announces",
         "is the file complete?");
  const std::size_t grid_values = static_cast<std::size_t>(f.nz) * f.ny * 3;
  f.grid.resize(grid_values * f.nt);
  f.tower.resize(static_cast<std::size_t>(f.n_tower) * 3 * f.nt);
  for (int it = 0; it < f.nt; ++it) {
    for (std::size_t k = 0; k < per_step; ++k) {
      const auto q = take<std::int16_t>(bytes, at);
      const int c = static_cast<int>(k % 3);
      const float v = static_cast<float>((static_cast<double>(q) - offset[c]) / slope[c]);
      if (k < grid_values) f.grid[it * grid_values + k] = v;
      else f.tower[static_cast<std::size_t>(it) * f.n_tower * 3 + (k - grid_values)] = v;
    }
  }
  return f;
}

void write_turbsim_bts(const std::filesystem::path& path, const TurbSimField& f) {
  check_sizes(f, path);
  float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  auto scan = [&](const std::vector<float>& values) {
    for (std::size_t k = 0; k < values.size(); ++k) {
      const float v = values[k];
      if (!std::isfinite(v)) fail(path, "non-finite velocity at value " + std::to_string(k));
      lo[k % 3] = std::min(lo[k % 3], v);
      hi[k % 3] = std::max(hi[k % 3], v);
    }
  };
  scan(f.grid);
  scan(f.tower);
  Int16Scaling scaling[3];
  for (int c = 0; c < 3; ++c) scaling[c] = int16_scaling(lo[c], hi[c]);

  const std::string description = f.description.substr(0, 200);
  std::string bytes;
  const std::size_t per_step = (static_cast<std::size_t>(f.nz) * f.ny + f.n_tower) * 3;
  bytes.reserve(kFixedHeaderBytes + description.size() + 2 * per_step * f.nt);
  put<std::int16_t>(bytes, f.periodic ? 8 : 7);
  put<std::int32_t>(bytes, f.nz);
  put<std::int32_t>(bytes, f.ny);
  put<std::int32_t>(bytes, f.n_tower);
  put<std::int32_t>(bytes, f.nt);
  for (double v : {f.dz_m, f.dy_m, f.dt_s, f.u_hub_m_s, f.z_hub_m, f.z_bottom_m}) put<float>(bytes, static_cast<float>(v));
  for (int c = 0; c < 3; ++c) {
    put<float>(bytes, scaling[c].slope);
    put<float>(bytes, scaling[c].offset);
  }
  put<std::int32_t>(bytes, static_cast<std::int32_t>(description.size()));
  bytes += description;
  auto quantise = [&](float v, int c) {
    const double q = std::nearbyint(static_cast<double>(v) * scaling[c].slope + scaling[c].offset);
    return static_cast<std::int16_t>(std::clamp(q, -32768.0, 32767.0));
  };
  const std::size_t grid_values = static_cast<std::size_t>(f.nz) * f.ny * 3;
  for (int it = 0; it < f.nt; ++it) {
    for (std::size_t k = 0; k < grid_values; ++k) put(bytes, quantise(f.grid[it * grid_values + k], static_cast<int>(k % 3)));
    for (std::size_t k = 0; k < static_cast<std::size_t>(f.n_tower) * 3; ++k)
      put(bytes, quantise(f.tower[static_cast<std::size_t>(it) * f.n_tower * 3 + k], static_cast<int>(k % 3)));
  }
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.string().c_str(), "wb"), &std::fclose);
  if (!file || std::fwrite(bytes.data(), 1, bytes.size(), file.get()) != bytes.size())
    throw Error(ErrorContext{kModule, std::nullopt, path.string(), "check the directory and disk space"},
                "cannot write '" + path.string() + "'");
}

void write_turbsim_hdf5(const std::filesystem::path& path, const TurbSimField& f, std::uint64_t seed) {
  using hdf5::check;
  using hdf5::checked;
  using hdf5::Handle;
  check_sizes(f, path);
  hdf5::silence_error_printing();
  const std::string name = path.string();
  const Handle file = checked(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, name,
                              "cannot create file");
  auto string_attribute = [&](hid_t object, const char* key, const std::string& value) {
    const Handle type = checked(H5Tcopy(H5T_C_S1), H5Tclose, name, "cannot copy string type", key);
    check(H5Tset_size(type.get(), H5T_VARIABLE), name, "cannot size string type", key);
    check(H5Tset_cset(type.get(), H5T_CSET_UTF8), name, "cannot set UTF-8", key);
    const Handle space = checked(H5Screate(H5S_SCALAR), H5Sclose, name, "cannot create dataspace", key);
    const Handle a = checked(H5Acreate2(object, key, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                             name, "cannot create attribute", key);
    const char* text = value.c_str();
    check(H5Awrite(a.get(), type.get(), &text), name, "cannot write attribute", key);
  };
  auto scalar_attribute = [&](hid_t object, const char* key, hid_t file_type, hid_t memory_type, const void* value) {
    const Handle space = checked(H5Screate(H5S_SCALAR), H5Sclose, name, "cannot create dataspace", key);
    const Handle a = checked(H5Acreate2(object, key, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                             name, "cannot create attribute", key);
    check(H5Awrite(a.get(), memory_type, value), name, "cannot write attribute", key);
  };
  auto dataset = [&](const char* key, int rank, const hsize_t* dims, hid_t file_type, hid_t memory_type,
                     const void* data, const char* unit) {
    const Handle space = checked(H5Screate_simple(rank, dims, nullptr), H5Sclose, name, "cannot create dataspace", key);
    const Handle d = checked(H5Dcreate2(file.get(), key, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                             H5Dclose, name, "cannot create dataset", key);
    check(H5Dwrite(d.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name, "cannot write dataset", key);
    string_attribute(d.get(), "unit", unit);
  };
  const std::size_t plane = static_cast<std::size_t>(f.nz) * f.ny;
  std::vector<float> component(plane * f.nt);
  const hsize_t dims3[3] = {static_cast<hsize_t>(f.nt), static_cast<hsize_t>(f.nz), static_cast<hsize_t>(f.ny)};
  const char* names[3] = {"u", "v", "w"};
  for (int c = 0; c < 3; ++c) {
    for (std::size_t k = 0; k < component.size(); ++k) component[k] = f.grid[k * 3 + c];
    dataset(names[c], 3, dims3, H5T_IEEE_F32LE, H5T_NATIVE_FLOAT, component.data(), "m/s");
  }
  std::vector<double> y(f.ny), z(f.nz), t(f.nt);
  for (int i = 0; i < f.ny; ++i) y[i] = -0.5 * (f.ny - 1) * f.dy_m + i * f.dy_m;
  for (int i = 0; i < f.nz; ++i) z[i] = f.z_bottom_m + i * f.dz_m;
  for (int i = 0; i < f.nt; ++i) t[i] = i * f.dt_s;
  const hsize_t ny = f.ny, nz = f.nz, nt = f.nt;
  dataset("y", 1, &ny, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, y.data(), "m");
  dataset("z", 1, &nz, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, z.data(), "m");
  dataset("t", 1, &nt, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, t.data(), "s");
  const int periodic = f.periodic ? 1 : 0;
  scalar_attribute(file.get(), "seed", H5T_STD_U64LE, H5T_NATIVE_UINT64, &seed);
  scalar_attribute(file.get(), "periodic", H5T_STD_I32LE, H5T_NATIVE_INT, &periodic);
  scalar_attribute(file.get(), "u_hub_m_s", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &f.u_hub_m_s);
  scalar_attribute(file.get(), "z_hub_m", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &f.z_hub_m);
  string_attribute(file.get(), "description", f.description);
}

}  // namespace fowtsim::io
