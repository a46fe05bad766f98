// The folder of generated turbulence fields runs share (rotor/turbulence_cache.hpp, issue 28): a field
// read back is the generated one float for float, each field has its own key, and a damaged file is
// generated anew rather than read.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "fowtsim/testing/skip.hpp"
#include "fowtsim/wind/verification.hpp"
#include "rotor/turbulence_cache.hpp"

namespace fowtsim::driver {
namespace {

void check_same(const wind::FullField& a, const wind::FullField& b) {
  CHECK(a.ny == b.ny);
  CHECK(a.nz == b.nz);
  CHECK(a.n_tower == b.n_tower);
  CHECK(a.nt == b.nt);
  CHECK(a.nt_held == b.nt_held);
  CHECK(a.nt_tail == b.nt_tail);
  CHECK(a.dy_m == b.dy_m);
  CHECK(a.dz_m == b.dz_m);
  CHECK(a.dt_s == b.dt_s);
  CHECK(a.z_bottom_m == b.z_bottom_m);
  CHECK(a.z_hub_m == b.z_hub_m);
  CHECK(a.u_hub_m_s == b.u_hub_m_s);
  CHECK(a.periodic == b.periodic);
  CHECK(a.grid == b.grid);  // exact: a run on the stored field writes what a run that generated it writes
  CHECK(a.tower == b.tower);
}

}  // namespace

TEST_CASE("a cached turbulence field is the generated one, bit for bit, under its own key", "[unit][wind][sweep]") {
  const std::filesystem::path folder = testing::scratch_dir("turbulence_cache") / "fields";
  std::filesystem::remove_all(folder);
  const wind::WindParams p = wind::verification::small_turbulent_field(7);
  const std::optional<wind::HeldTimes> held = wind::HeldTimes{20.0, 2.0};
  const wind::FullField generated = wind::generate_turbulence(p, held).field;
  REQUIRE(generated.nt_held > 0);  // the held part only, as a run stores it

  const std::filesystem::path file = turbulence_file(folder, turbulence_key(p, held));
  const wind::FullField first = cached_turbulence(folder, p, held);  // generated and stored
  REQUIRE(std::filesystem::exists(file));
  check_same(first, generated);
  const auto stored_at = std::filesystem::last_write_time(file);
  check_same(cached_turbulence(folder, p, held), generated);  // read back
  CHECK(std::filesystem::last_write_time(file) == stored_at);

  // What shapes the field is in the key; how it is used (direction, events) is not.
  wind::WindParams other_seed = p, turned = p;
  other_seed.turbulence.seed = 8;
  turned.direction_deg = 8.0;
  turned.event.type = wind::WindEventType::EOG;
  CHECK(turbulence_key(other_seed, held) != turbulence_key(p, held));
  CHECK(turbulence_key(p, std::nullopt) != turbulence_key(p, held));
  CHECK(turbulence_key(p, wind::HeldTimes{21.0, 2.0}) != turbulence_key(p, held));
  CHECK(turbulence_key(turned, held) == turbulence_key(p, held));
  check_same(cached_turbulence(folder, other_seed, held), wind::generate_turbulence(other_seed, held).field);

  // A truncated file (a disk that filled while another writer had renamed it) is generated anew.
  std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
  check_same(cached_turbulence(folder, p, held), generated);
  CHECK(std::filesystem::file_size(file) > 0);
  check_same(cached_turbulence(folder, p, held), generated);
  // No temporaries are left behind.
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    CHECK(entry.path().extension() == ".field");
    ++files;
  }
  CHECK(files == 2);
}

}  // namespace fowtsim::driver
