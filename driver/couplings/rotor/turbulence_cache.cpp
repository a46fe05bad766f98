#include "rotor/turbulence_cache.hpp"

#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <optional>
#include <system_error>

#include <fmt/format.h>

#include "fowtsim/core/version.hpp"
#include "fowtsim/io/deck.hpp"

namespace fowtsim::driver {
namespace {

constexpr char kMagic[] = "fowtsim turbulence field 1\n";

template <class T>
void put(std::ofstream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}
template <class T>
bool get(std::ifstream& in, T& value) {
  return static_cast<bool>(in.read(reinterpret_cast<char*>(&value), sizeof(T)));
}
void put_floats(std::ofstream& out, const std::vector<float>& v) {
  put(out, static_cast<std::uint64_t>(v.size()));
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(float)));
}
bool get_floats(std::ifstream& in, std::vector<float>& v, std::uint64_t expected) {
  std::uint64_t n = 0;
  if (!get(in, n) || n != expected) return false;
  v.resize(n);
  return static_cast<bool>(in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(float))));
}

// The stored field if `file` holds one of `key`, whole and consistent.
std::optional<wind::FullField> read_field(const std::filesystem::path& file, const std::string& key) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::string magic(sizeof(kMagic) - 1, '\0');
  std::uint64_t key_size = 0;
  if (!in.read(magic.data(), static_cast<std::streamsize>(magic.size())) || magic != kMagic || !get(in, key_size) ||
      key_size != key.size())
    return std::nullopt;
  std::string stored(key_size, '\0');
  if (!in.read(stored.data(), static_cast<std::streamsize>(key_size)) || stored != key) return std::nullopt;
  wind::FullField f;
  std::uint8_t periodic = 0;
  if (!get(in, f.ny) || !get(in, f.nz) || !get(in, f.n_tower) || !get(in, f.nt) || !get(in, f.nt_held) || !get(in, f.nt_tail) ||
      !get(in, f.dy_m) || !get(in, f.dz_m) || !get(in, f.dt_s) || !get(in, f.z_bottom_m) || !get(in, f.z_hub_m) ||
      !get(in, f.u_hub_m_s) || !get(in, periodic))
    return std::nullopt;
  f.periodic = periodic != 0;
  if (f.ny < 2 || f.nz < 2 || f.n_tower < 0 || f.nt < 1 || f.nt_held < 0 || f.nt_tail < 0) return std::nullopt;
  const auto steps = static_cast<std::uint64_t>(f.held_steps());
  if (!get_floats(in, f.grid, steps * static_cast<std::uint64_t>(f.ny) * static_cast<std::uint64_t>(f.nz) * 3) ||
      !get_floats(in, f.tower, steps * static_cast<std::uint64_t>(f.n_tower) * 3))
    return std::nullopt;
  char extra = 0;
  if (in.read(&extra, 1)) return std::nullopt;  // longer than a field: not ours
  return f;
}

// Stores `f` as `file` (temporary name, then rename); false if any write failed (the temporary is gone).
bool write_field(const std::filesystem::path& file, const std::string& key, const wind::FullField& f) {
  const std::filesystem::path part = file.string() + fmt::format(".{}.part", ::getpid());
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out.write(kMagic, sizeof(kMagic) - 1);
    put(out, static_cast<std::uint64_t>(key.size()));
    out.write(key.data(), static_cast<std::streamsize>(key.size()));
    for (const int v : {f.ny, f.nz, f.n_tower, f.nt, f.nt_held, f.nt_tail}) put(out, v);
    for (const double v : {f.dy_m, f.dz_m, f.dt_s, f.z_bottom_m, f.z_hub_m, f.u_hub_m_s}) put(out, v);
    put(out, static_cast<std::uint8_t>(f.periodic ? 1 : 0));
    put_floats(out, f.grid);
    put_floats(out, f.tower);
    out.flush();
    if (out.good()) {
      out.close();
      std::error_code e;
      if (!out.fail()) {
        std::filesystem::rename(part, file, e);
        if (!e) return true;
      }
    }
  }
  std::error_code ignored;
  std::filesystem::remove(part, ignored);
  return false;
}

}  // namespace

std::string turbulence_key(const wind::WindParams& p, const std::optional<wind::HeldTimes>& held) {
  const wind::TurbulenceParams& t = p.turbulence;
  // %a: the doubles exactly. Direction, upflow and events act on the field's use, not on the field.
  return fmt::format(
      "fowtsim {}; speed {:a} m/s at {:a} m, shear {:a}; class {} model {} iec {}; grid {}x{} over {:a} x {:a} m, "
      "dt {:a} s, duration {:a} s, seed {}, tower points {}; held {}",
      kVersion, p.speed_m_s, p.reference_height_m, p.shear_exponent, static_cast<int>(t.category),
      static_cast<int>(t.model), t.iec_wind_class, t.ny, t.nz, t.width_m, t.height_m, t.dt_s, t.duration_s, t.seed,
      t.tower_points ? 1 : 0, held ? fmt::format("until {:a} s, before start {:a} s", held->until_s, held->before_start_s) : "all");
}

std::filesystem::path turbulence_file(const std::filesystem::path& folder, const std::string& key) {
  return folder / fmt::format("turbulence_{:016x}.field", io::fnv1a_64(key));
}

wind::FullField cached_turbulence(const std::filesystem::path& folder, const wind::WindParams& params,
                                  const std::optional<wind::HeldTimes>& held) {
  const std::string key = turbulence_key(params, held);
  const std::filesystem::path file = turbulence_file(folder, key);
  if (std::optional<wind::FullField> stored = read_field(file, key)) return std::move(*stored);
  wind::FullField f = wind::generate_turbulence(params, held).field;
  std::error_code e;
  std::filesystem::create_directories(folder, e);
  if (!e) write_field(file, key, f);
  return f;
}

}  // namespace fowtsim::driver
