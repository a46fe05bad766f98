// TurbSim's .bts of the OC3 run, read by fowtsim::io and evaluated by our full field at the
// InflowWind output point, against OpenFAST v5's Wind1VelX/Y/Z.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <memory>

#include "fowtsim/io/readers.hpp"
#include "fowtsim/io/turbsim_bts.hpp"
#include "fowtsim/testing/skip.hpp"
#include "fowtsim/wind/verification.hpp"
#include "fowtsim/wind/wind_field.hpp"

using namespace fowtsim;
using namespace fowtsim::wind;

namespace {

std::shared_ptr<const FullField> to_full_field(io::TurbSimField&& t) {
  auto f = std::make_shared<FullField>();
  static_cast<WindGrid&>(*f) = std::move(t);
  return f;
}

}  // namespace

// Intent: InflowWind's conventions as we implement them (Taylor shift t + (W/2 − x)/U_hub for a
// non-periodic file, linear in time, bilinear in y–z) reproduce OpenFAST's Wind1VelX/Y/Z.
// Run: 5MW_OC3Spar_DLL_WTurb_WavesIrr (.fst: InflowFile ../5MW_Baseline/NRELOffshrBsline5MW_InflowWind_12mps.dat,
// WindType 3, PropagationDir 0, VFlowAng 0, WindVxiList 0, WindVyiList 0, WindVziList 90 m). The
// probe is fixed in the inertial frame (the hub of the run, ElastoDyn: OverHang −5.0191 m, ShftTilt
// −5°, TowerHt 87.6 m + Twr2Shft 1.96256 m, sits at x = −5.00 m, z = 90.00 m and moves with the
// platform; Wind1VelX is not taken there).
// Tolerance per component: half the file's int16 step 0.5/slope_c (7.0e-5 m/s for w, the finest),
// the resolution both codes share; what remains is OpenFAST's float32 arithmetic and the .out's 9
// printed digits (measured 8.4e-7 m/s at most, Wind1VelX).
TEST_CASE("TurbSim's OC3 field at the InflowWind probe matches OpenFAST's Wind1VelX/Y/Z",
          "[verification][wind][bts]") {
  const auto shared = testing::shared_dir_or_skip();
  const auto run = shared / "reference/openfast-runs/oc3_spar_wturb_wavesirr/glue-codes/openfast";
  io::TurbSimField bts = io::read_turbsim_bts(run / "5MW_Baseline/Wind/90m_12mps_twr.bts");
  // Half int16 steps from the file's slopes: 0.5/3552.05, 0.5/4197.02, 0.5/7142.20 m/s.
  const double tolerance[3] = {0.5 / 3552.051513671875, 0.5 / 4197.0185546875, 0.5 / 7142.2021484375};
  WindParams p;
  p.model = WindModel::bts;
  p.file = "90m_12mps_twr.bts";
  p.reference_height_m = 90.0;
  const WindField field(p, to_full_field(std::move(bts)));

  const io::ChannelTable out = io::read_openfast_text(run / "5MW_OC3Spar_DLL_WTurb_WavesIrr/5MW_OC3Spar_DLL_WTurb_WavesIrr.out");
  const char* names[3] = {"Wind1VelX", "Wind1VelY", "Wind1VelZ"};
  std::array<std::vector<double>, 3> recorded;
  for (int c = 0; c < 3; ++c) {
    REQUIRE(out.find(names[c]).has_value());
    recorded[c] = out.columns[*out.find(names[c])];
  }
  REQUIRE(out.rows() == 1201);  // 0–60 s at 0.05 s
  const std::array<double, 3> worst = verification::max_velocity_deviation(field, Vec3(0.0, 0.0, 90.0), out.time(), recorded);
  for (int c = 0; c < 3; ++c) {
    INFO(names[c] << ": max |fowtsim − OpenFAST| = " << worst[c] << " m/s over 1201 samples");
    CHECK(worst[c] < tolerance[c]);
  }
}
