// Tests of the TurbSim full-field .bts reader/writer and the HDF5 copy of a field.
#include <catch2/catch.hpp>

#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/turbsim_bts.hpp"
#include "fowtsim/testing/skip.hpp"

namespace {

using fowtsim::io::TurbSimField;

// A small field with distinct smooth values per component, tower points and a negative w.
TurbSimField synthetic_field() {
  TurbSimField f;
  f.nz = 4;
  f.ny = 5;
  f.n_tower = 2;
  f.nt = 7;
  f.dz_m = 3.5;
  f.dy_m = 4.25;
  f.dt_s = 0.1;
  f.u_hub_m_s = 11.4;
  f.z_hub_m = 90.0;
  f.z_bottom_m = 84.75;
  f.periodic = true;
  f.description = "fowtsim round-trip test field";
  for (int it = 0; it < f.nt; ++it) {
    for (int iz = 0; iz < f.nz; ++iz)
      for (int iy = 0; iy < f.ny; ++iy) {
        const double s = 0.3 * it + 0.7 * iz - 0.4 * iy;
        f.grid.push_back(static_cast<float>(11.4 + 2.0 * std::sin(s)));
        f.grid.push_back(static_cast<float>(0.8 * std::cos(1.3 * s)));
        f.grid.push_back(static_cast<float>(-0.2 + 0.5 * std::sin(2.1 * s)));
      }
    for (int k = 0; k < f.n_tower; ++k) {
      f.tower.push_back(static_cast<float>(9.0 - k + 0.1 * it));
      f.tower.push_back(static_cast<float>(0.05 * k));
      f.tower.push_back(static_cast<float>(-0.01 * it));
    }
  }
  return f;
}

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Largest |a − b| / bound over a component, bound = its half quantisation step.
double worst_quantisation_ratio(const std::vector<float>& a, const std::vector<float>& b, const float lo[3],
                                const float hi[3]) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const int c = static_cast<int>(k % 3);
    const auto s = fowtsim::io::int16_scaling(lo[c], hi[c]);
    // Half a count, plus float32 rounding of the stored value (2⁻²⁴ relative).
    const double bound = 0.5 / s.slope + std::abs(a[k]) * 0x1.0p-24;
    worst = std::max(worst, std::abs(static_cast<double>(a[k]) - b[k]) / bound);
  }
  return worst;
}

void component_range(const TurbSimField& f, float lo[3], float hi[3]) {
  for (int c = 0; c < 3; ++c) lo[c] = INFINITY, hi[c] = -INFINITY;
  for (const auto* values : {&f.grid, &f.tower})
    for (std::size_t k = 0; k < values->size(); ++k) {
      lo[k % 3] = std::min(lo[k % 3], (*values)[k]);
      hi[k % 3] = std::max(hi[k % 3], (*values)[k]);
    }
}

}  // namespace

// Intent: write → read returns the header exactly (as float32) and every sample to within the
// int16 quantisation of the writer, |v − v̂| <= 0.5/slope_c (+ float32 rounding), and a second
// write of what was read is byte-identical (the scaling is reproduced from the dequantised data).
TEST_CASE("a .bts round trip is exact to the int16 quantisation", "[unit][io][turbsim]") {
  const auto dir = fowtsim::testing::scratch_dir("turbsim_round_trip");
  const TurbSimField f = synthetic_field();
  fowtsim::io::write_turbsim_bts(dir / "a.bts", f);
  const TurbSimField g = fowtsim::io::read_turbsim_bts(dir / "a.bts");
  CHECK(g.nz == f.nz);
  CHECK(g.ny == f.ny);
  CHECK(g.n_tower == f.n_tower);
  CHECK(g.nt == f.nt);
  CHECK(g.periodic == f.periodic);
  CHECK(g.description == f.description);
  CHECK(g.dz_m == static_cast<float>(f.dz_m));
  CHECK(g.dy_m == static_cast<float>(f.dy_m));
  CHECK(g.dt_s == static_cast<float>(f.dt_s));
  CHECK(g.u_hub_m_s == static_cast<float>(f.u_hub_m_s));
  CHECK(g.z_hub_m == static_cast<float>(f.z_hub_m));
  CHECK(g.z_bottom_m == static_cast<float>(f.z_bottom_m));
  REQUIRE(g.grid.size() == f.grid.size());
  REQUIRE(g.tower.size() == f.tower.size());
  float lo[3], hi[3];
  component_range(f, lo, hi);
  // Bound: the quantisation of the format itself (ratio <= 1 means within half an int16 count).
  CHECK(worst_quantisation_ratio(f.grid, g.grid, lo, hi) <= 1.0);
  CHECK(worst_quantisation_ratio(f.tower, g.tower, lo, hi) <= 1.0);

  fowtsim::io::write_turbsim_bts(dir / "b.bts", g);
  CHECK(file_bytes(dir / "a.bts") == file_bytes(dir / "b.bts"));
}

// Intent: the writer uses the whole int16 range per component (min -> −32768, max -> 32767), as
// TurbSim does, so the quantisation step is (max − min)/65535.
TEST_CASE("the .bts scaling maps each component's range onto the int16 range", "[unit][io][turbsim]") {
  const auto s = fowtsim::io::int16_scaling(-1.5f, 2.5f);
  CHECK(std::nearbyint(-1.5 * s.slope + s.offset) == -32768.0);
  CHECK(std::nearbyint(2.5 * s.slope + s.offset) == 32767.0);
  const auto constant = fowtsim::io::int16_scaling(3.0f, 3.0f);  // constant component: exact
  CHECK((std::nearbyint(3.0 * constant.slope + constant.offset) - constant.offset) / constant.slope == 3.0);
}

TEST_CASE("malformed .bts files are rejected with the path", "[unit][io][turbsim]") {
  const auto dir = fowtsim::testing::scratch_dir("turbsim_errors");
  fowtsim::io::write_turbsim_bts(dir / "good.bts", synthetic_field());
  const std::string bytes = file_bytes(dir / "good.bts");
  std::ofstream(dir / "short.bts", std::ios::binary) << bytes.substr(0, bytes.size() - 10);
  std::string bad_id = bytes;
  bad_id[0] = 9;
  std::ofstream(dir / "id.bts", std::ios::binary) << bad_id;
  CHECK_THROWS_AS(fowtsim::io::read_turbsim_bts(dir / "short.bts"), fowtsim::InputError);
  CHECK_THROWS_WITH(fowtsim::io::read_turbsim_bts(dir / "id.bts"), Catch::Contains("format id 9"));
  CHECK_THROWS_AS(fowtsim::io::read_turbsim_bts(dir / "missing.bts"), fowtsim::InputError);
  TurbSimField wrong = synthetic_field();
  wrong.grid.pop_back();
  CHECK_THROWS_AS(fowtsim::io::write_turbsim_bts(dir / "wrong.bts", wrong), fowtsim::InputError);
}

// Intent: TurbSim's own file (OC3 run, TurbSim from OpenFAST v5) is read with the header of its
// input/summary files (90m_12mps_twr.inp: 31×31, dt 0.05 s, HubHt 90 m, GridHeight 145 m, URef
// 12 m/s; .sum: 1442 time steps output, 964 points = 961 + tower), and our writer re-encodes it
// to within our quantisation.
TEST_CASE("TurbSim's reference .bts reads with its documented header and re-encodes", "[verification][io][turbsim]") {
  const auto shared = fowtsim::testing::shared_dir_or_skip();
  const auto path = shared / "reference/openfast-runs/oc3_spar_wturb_wavesirr/glue-codes/openfast/5MW_Baseline/Wind/"
                             "90m_12mps_twr.bts";
  const TurbSimField f = fowtsim::io::read_turbsim_bts(path);
  CHECK(f.nz == 31);
  CHECK(f.ny == 31);
  CHECK(f.n_tower == 3 + 1);
  CHECK(f.nt == 1442);
  CHECK_FALSE(f.periodic);  // UsableTime 60 s (not "ALL"): non-periodic, id 7
  CHECK(f.dt_s == Approx(0.05).epsilon(1e-7));       // float32 header
  CHECK(f.dz_m == Approx(145.0 / 30).epsilon(1e-7));
  CHECK(f.dy_m == Approx(145.0 / 30).epsilon(1e-7));
  CHECK(f.u_hub_m_s == 12.0);
  CHECK(f.z_hub_m == 90.0);
  CHECK(f.z_bottom_m == 90.0 - 72.5);
  // The first tower point is the bottom grid row at y = 0 (TurbSim writes it twice).
  for (int it = 0; it < f.nt; it += 100)
    for (int c = 0; c < 3; ++c)
      CHECK(f.tower[static_cast<std::size_t>(it) * f.n_tower * 3 + c] ==
            f.grid[((static_cast<std::size_t>(it) * f.nz + 0) * f.ny + 15) * 3 + c]);

  const auto dir = fowtsim::testing::scratch_dir("turbsim_reencode");
  fowtsim::io::write_turbsim_bts(dir / "again.bts", f);
  const TurbSimField g = fowtsim::io::read_turbsim_bts(dir / "again.bts");
  float lo[3], hi[3];
  component_range(f, lo, hi);
  CHECK(worst_quantisation_ratio(f.grid, g.grid, lo, hi) <= 1.0);  // half an int16 count
  CHECK(worst_quantisation_ratio(f.tower, g.tower, lo, hi) <= 1.0);
}

// Intent: the HDF5 copy holds u, v, w as (nt, nz, ny) float32 arrays equal to the field, the grid
// coordinates and the seed attribute.
TEST_CASE("a field written to HDF5 reads back with h5py's layout", "[unit][io][turbsim]") {
  const auto dir = fowtsim::testing::scratch_dir("turbsim_hdf5");
  const TurbSimField f = synthetic_field();
  fowtsim::io::write_turbsim_hdf5(dir / "field.h5", f, 4242);
  const hid_t file = H5Fopen((dir / "field.h5").string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hid_t w = H5Dopen2(file, "w", H5P_DEFAULT);
  REQUIRE(w >= 0);
  const hid_t space = H5Dget_space(w);
  hsize_t dims[3] = {0, 0, 0};
  CHECK(H5Sget_simple_extent_ndims(space) == 3);
  H5Sget_simple_extent_dims(space, dims, nullptr);
  CHECK(dims[0] == static_cast<hsize_t>(f.nt));
  CHECK(dims[1] == static_cast<hsize_t>(f.nz));
  CHECK(dims[2] == static_cast<hsize_t>(f.ny));
  std::vector<float> values(f.grid.size() / 3);
  H5Dread(w, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  for (std::size_t k = 0; k < values.size(); ++k) CHECK(values[k] == f.grid[3 * k + 2]);
  std::uint64_t seed = 0;
  const hid_t attribute = H5Aopen(file, "seed", H5P_DEFAULT);
  H5Aread(attribute, H5T_NATIVE_UINT64, &seed);
  CHECK(seed == 4242u);
  std::vector<double> z(f.nz);
  const hid_t zset = H5Dopen2(file, "z", H5P_DEFAULT);
  H5Dread(zset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, z.data());
  CHECK(z.back() == Approx(f.z_bottom_m + (f.nz - 1) * f.dz_m));
  H5Dclose(zset);
  H5Aclose(attribute);
  H5Sclose(space);
  H5Dclose(w);
  H5Fclose(file);
}
