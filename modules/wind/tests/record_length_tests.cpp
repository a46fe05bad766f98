// A turbulence box shorter than the run wraps around (periodic) or ends (non-periodic) without a
// word from the wind field: box_length_warning says so, counting the time the box needs to pass
// the rotor (Taylor's shift of the upwind points).
#include <catch2/catch.hpp>

#include <memory>

#include "fowtsim/wind/record_length.hpp"

namespace {

using namespace fowtsim::wind;

// A uniform 10 m/s box of nt samples of 0.5 s on a 40 m × 24 m grid around 92 m.
std::shared_ptr<const FullField> box(int nt, bool periodic) {
  auto f = std::make_shared<FullField>();
  f->ny = 5;
  f->nz = 4;
  f->nt = nt;
  f->dy_m = 10.0;
  f->dz_m = 8.0;
  f->dt_s = 0.5;
  f->z_bottom_m = 80.0;
  f->z_hub_m = 92.0;
  f->u_hub_m_s = 10.0;
  f->periodic = periodic;
  for (int i = 0; i < f->nt * f->nz * f->ny; ++i) f->grid.insert(f->grid.end(), {10.0f, 0.0f, 0.0f});
  return f;
}

WindField field(int nt, bool periodic) {
  WindParams p;
  p.model = WindModel::turbulent;
  p.speed_m_s = 10.0;
  p.reference_height_m = 92.0;
  return WindField(p, box(nt, periodic));
}

}  // namespace

TEST_CASE("a periodic box shorter than the run plus its passage past the rotor is reported as wrapping", "[unit]") {
  const WindField w = field(60, true);  // 30 s
  // 25 s + (0 + 40 m)/(10 m/s) = 29 s: covered.
  CHECK_FALSE(box_length_warning(w, 25.0, 40.0));
  // 30 s + 4 s > 30 s: the upwind points read past the end from t = 26 s on.
  const auto warning = box_length_warning(w, 30.0, 40.0);
  REQUIRE(warning);
  CHECK_THAT(*warning, Catch::Contains("covers 30 s") && Catch::Contains("needs 34 s") && Catch::Contains("wraps around") &&
                           Catch::Contains("after t ≈ 26 s") && Catch::Contains("wind.turbulence.duration_s ≥ 34"));
  CHECK_FALSE(box_length_warning(WindField(WindParams{}), 1e6, 40.0));  // no box, nothing to outlast
}

TEST_CASE("a non-periodic box also counts half its width (InflowWind starts it ahead of the rotor) and says the run stops", "[unit]") {
  const WindField w = field(61, false);  // (61 − 1)·0.5 = 30 s
  // 25 s + (20 m + 40 m)/(10 m/s) = 31 s > 30 s.
  const auto warning = box_length_warning(w, 25.0, 40.0);
  REQUIRE(warning);
  CHECK_THAT(*warning, Catch::Contains("needs 31 s") && Catch::Contains("the run stops where the box ends"));
  CHECK_FALSE(box_length_warning(w, 23.0, 40.0));
}

// Intent: a uniform wind file shorter than the run, and an event starting at or after its end, are
// said in the run summary; a file covering the run and an event inside it are not.
TEST_CASE("uniform files shorter than the run and events after its end are warned of", "[unit][wind]") {
  WindParams p;
  p.model = WindModel::uniform_file;
  p.file = "gust.hh";
  p.reference_length_m = 126.0;
  p.uniform = parse_uniform_wind("0 10 0 0 0 0 0 0\n30 12 0 0 0 0 0 0\n", "gust.hh");
  CHECK_FALSE(box_length_warning(WindField(p), 30.0, 10.0));
  const auto w = box_length_warning(WindField(p), 60.0, 10.0);
  REQUIRE(w);
  CHECK_THAT(*w, Catch::Contains("gust.hh ends at 30 s") && Catch::Contains("last row is held"));
  WindParams e;
  e.model = WindModel::steady;
  e.speed_m_s = 12.0;
  e.event.type = WindEventType::EDC;
  e.event.rotor_diameter_m = 126.0;
  e.event.start_s = 40.0;
  CHECK_FALSE(event_timing_warning(WindField(e), 60.0));
  REQUIRE(event_timing_warning(WindField(e), 40.0));
  CHECK_THAT(*event_timing_warning(WindField(e), 40.0), Catch::Contains("never acts"));
}
