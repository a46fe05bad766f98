// OpenFAST's channel names against ours (run/channel_names.hpp) and the unit check of a compared
// pair (compare/channel_units.hpp).
#include <numbers>

#include <catch2/catch.hpp>

#include "compare/channel_units.hpp"
#include "run/channel_names.hpp"

using namespace fowtsim::driver;

TEST_CASE("MAP++'s tensions are our FAIRTEN/ANCHTEN, asked either way", "[unit][compare]") {
  const auto fair = builtin_alias("T[2]");
  REQUIRE(fair);
  CHECK(fair->ours == "FAIRTEN2");
  CHECK(builtin_alias("fairten12")->openfast == "T[12]");  // names are case-insensitive
  CHECK(builtin_alias("T_a[3]")->ours == "ANCHTEN3");
  CHECK_FALSE(builtin_alias("T[x]"));
  CHECK_FALSE(builtin_alias("T[]"));
  CHECK_FALSE(builtin_alias("RotSpeed"));
}

TEST_CASE("a channel we do not have is explained: alias, not computed, or typo", "[unit][compare]") {
  const std::vector<std::string> ours{"FAIRTEN1", "RotSpeed", "PtfmTAxi", "TwrBsMyt"};
  CHECK_THAT(why_missing("T[1]", ours), Catch::Contains("MAP++") && Catch::Contains("did you mean `FAIRTEN1`?"));
  CHECK_THAT(why_missing("FAIRTEN1", {"T[1]"}), Catch::Contains("did you mean `T[1]`?"));
  CHECK_THAT(why_missing("TTDspFA", ours), Catch::Contains("flexible tower"));
  CHECK_THAT(why_missing("YawBrTDxp", ours), Catch::Contains("flexible tower"));
  CHECK_THAT(why_missing("TwHt1MLxt", ours), Catch::Contains("TwrBs"));
  // One letter from PtfmTAxi, but another frame: the reason, not a did-you-mean.
  CHECK_THAT(why_missing("PtfmTAxt", ours), Catch::Contains("inertial frame") && !Catch::Contains("did you mean"));
  CHECK(why_missing("rotsped", ours) == "did you mean `RotSpeed`?");
  CHECK(why_missing("Zebra", ours).empty());
  // An alias whose counterpart is absent too says nothing of it.
  CHECK(why_missing("T[7]", ours).empty());
}

TEST_CASE("units convert between the spellings of one quantity and refuse the rest", "[unit][compare]") {
  CHECK(normalised_unit("(kN-m)") == "kN-m");
  CHECK(normalised_unit("[N]") == "N");
  CHECK(normalised_unit("kN·m") == "kN-m");
  CHECK(normalised_unit("Nm") == "N-m");
  // test × factor is in the reference's unit
  CHECK(match_units("kN", "N").factor == 1e-3);
  CHECK(match_units("N", "MN").factor == 1e6);
  CHECK(match_units("kN-m", "N·m").factor == 1e-3);
  CHECK(match_units("MN-m", "kN-m").factor == 1e-3);
  CHECK(match_units("deg", "rad").factor == Approx(180.0 / std::numbers::pi).epsilon(1e-15));
  CHECK(match_units("rad/s", "rpm").factor == Approx(std::numbers::pi / 30.0).epsilon(1e-15));
  CHECK(match_units("m", "mm").factor == 1e-3);
  CHECK(match_units("kW", "W").factor == 1e-3);
  CHECK(match_units("m/s^2", "(m/s^2)").comparable());  // unknown to the table, but the same spelling
  CHECK_THAT(match_units("N", "N-m").problem, Catch::Contains("force") && Catch::Contains("moment"));
  CHECK_THAT(match_units("m/s", "knot").problem, Catch::Contains("no known conversion"));
  CHECK_FALSE(match_units("kN", "").comparable());
}
