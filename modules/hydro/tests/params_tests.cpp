// Parameter validation and the node layout shared with the driver.
#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/module.hpp"
#include "fowtsim/hydro/hydro.hpp"
#include "fowtsim/hydro/oc3.hpp"

using namespace fowtsim;
using namespace fowtsim::hydro;

static_assert(Module<Hydro>);

TEST_CASE("validate lists every bad field with its key", "[unit][hydro]") {
  Params p = oc3_hywind_params();
  p.water_density_kg_m3 = -1.0;
  p.members[1].diameter_b_m = 0.0;
  p.members[2].strips = 0;
  p.members[0].cd = -0.1;
  p.current.profile = CurrentParams::Profile::power_law;
  try {
    validate(p);
    FAIL("validate accepted bad parameters");
  } catch (const InputError& e) {
    const std::string what = e.what();
    CHECK_THAT(what, Catch::Contains("5 invalid"));
    CHECK_THAT(what, Catch::Contains("hydro.water_density_kg_m3"));
    CHECK_THAT(what, Catch::Contains("hydro.members[1].diameter_b_m"));
    CHECK_THAT(what, Catch::Contains("hydro.members[2].strips"));
    CHECK_THAT(what, Catch::Contains("hydro.members[0].cd"));
    CHECK_THAT(what, Catch::Contains("hydro.current.reference_depth_m"));
  }
  CHECK_NOTHROW(validate(oc3_hywind_params()));
  Params empty;
  CHECK_THROWS_WITH(validate(empty), Catch::Contains("at least one member"));
}

TEST_CASE("node layout: strips then ends, per member", "[unit][hydro]") {
  const Params p = oc3_hywind_params(24, 4, 4);
  CHECK(node_count(p) == 24 + 4 + 4 + 6);
  CHECK(node_offset(p, 2) == 26 + 6);
  Points points(3, node_count(p));
  FrameMotion pose;
  strip_points(p, pose, VecX::Zero(3), points);
  CHECK(points(2, 0) == Approx(-120.0 + 108.0 / 48.0));        // first strip midpoint
  CHECK(points(2, 24) == -120.0);                              // member 0 end A
  CHECK(points(2, 25) == -12.0);                               // member 0 end B
  CHECK(points(2, node_offset(p, 2) + 3) == Approx(-0.5));     // top member: strips over the 4 wet m
  CHECK(points(2, node_count(p) - 1) == 10.0);                 // top member end B (dry)
  CHECK(Hydro::channels(p).size() == 24u);  // four parts × six components without potential flow
  CHECK(Hydro::channels(p)[0].name == "HydroFxi");
  CHECK(Hydro::channels(p)[5].name == "HydroMzi");
}
