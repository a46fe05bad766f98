#include <catch2/catch.hpp>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/core/error.hpp"

using namespace fowtsim;

TEST_CASE("channel registry assigns columns in order and finds by name", "[unit][channels]") {
  ChannelRegistry reg;
  CHECK(reg.add({"PtfmSurge", "m", "platform surge", "multibody"}) == 0);
  CHECK(reg.add({"RotSpeed", "rpm", "rotor speed", "multibody"}) == 1);
  REQUIRE(reg.find("RotSpeed"));
  CHECK(*reg.find("RotSpeed") == 1);
  CHECK_FALSE(reg.find("GenPwr"));
  CHECK(reg.at(0).unit == "m");
}

TEST_CASE("channel registry rejects duplicates and bad names, naming both modules", "[unit][channels]") {
  ChannelRegistry reg;
  reg.add({"PtfmSurge", "m", "", "multibody"});
  CHECK_THROWS_WITH(reg.add({"PtfmSurge", "m", "", "hydro"}), Catch::Contains("multibody") && Catch::Contains("PtfmSurge"));
  CHECK_THROWS_AS(reg.add({"Ptfm Surge", "m", "", "hydro"}), InputError);
  CHECK_THROWS_AS(reg.add({"", "m", "", "hydro"}), InputError);
}
