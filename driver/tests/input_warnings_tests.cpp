// Inputs that are legal but almost certainly wrong (issue 23): records shorter than the run, which
// repeat without a word, and unit slips. The run goes ahead; its summary and its HDF5 warnings say so.
#include <catch2/catch.hpp>

#include <algorithm>

#include "fowtsim/testing/skip.hpp"
#include "h5_attributes.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

bool has_warning(const std::vector<std::string>& warnings, const std::string& part) {
  return std::any_of(warnings.begin(), warnings.end(), [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

}  // namespace

TEST_CASE("a sea shorter than the run and unit slips are warned about, in the summary and the HDF5", "[unit][run]") {
  const auto dir = testing::scratch_dir("input_warnings_platform");
  RunRequest r = run_request(testing::source_dir() / "inputs/oc3_hywind/platform_in_waves.yaml", dir / "slips", "h5");
  r.t_max_s = 40.0;
  r.deck_settings = {"waves.duration_s=30", "mooring.water_density_kg_m3=1.025", "waves.depth_m=320000"};
  const RunReport report = run_scene(r, nullptr);
  const std::string stored = string_attribute(dir / "slips.h5", "warnings");
  for (const char* part : {"the waves at t = 35 s are those at t = 5 s", "mooring.water_density_kg_m3 = 1.025, outside 900 … 1100",
                           "waves.depth_m = 320000, outside 0 … 11000"}) {
    INFO(part);
    CHECK(has_warning(report.warnings, part));
    CHECK(stored.find(part) != std::string::npos);
  }

  // The shipped deck over a run shorter than its sea: nothing to say.
  RunRequest plain = run_request(testing::source_dir() / "inputs/oc3_hywind/platform_in_waves.yaml", dir / "plain", "h5");
  plain.t_max_s = 10.0;
  CHECK(run_scene(plain, nullptr).warnings.empty());
}

TEST_CASE("a turbulence box shorter than the run plus its passage past the rotor is warned about", "[unit][run]") {
  const auto dir = testing::scratch_dir("input_warnings_turbine");
  RunRequest r = run_request(testing::source_dir() / "inputs/oc3_hywind/turbine_ntm_12mps_irregular.yaml", dir / "box", "h5");
  r.t_max_s = 2.0;
  r.deck_settings = {"wind.turbulence={ny: 11, nz: 11, dt_s: 0.25, duration_s: 5}", "wind.reference_height_m=90000"};
  const RunReport report = run_scene(r, nullptr);
  // 2 s + (63 m tip radius + 5 m overhang) / 12 m/s > 5 s.
  CHECK(has_warning(report.warnings, "the turbulence box covers 5 s (wind.turbulence.duration_s), the run needs 7.66"));
  CHECK(has_warning(report.warnings, "--set wind.reference_height_m: wind.reference_height_m = 90000, outside 0 … 1000"));
}
