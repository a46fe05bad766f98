// The parameter decks hold the published constants: each key of inputs/nrel5mw/controller_land.yaml
// and inputs/oc3_hywind/controller.yaml equals the corresponding member of the C++ preset
// (transcribed from PUBLISHED.md), and the decks validate.
#include <map>
#include <string>

#include <catch2/catch.hpp>
#include <yaml-cpp/yaml.h>

#include "fowtsim/control/presets.hpp"
#include "fowtsim/testing/skip.hpp"

using namespace fowtsim::control;

namespace {

// Reads the deck's controller section into BaselineParams, key by key (the driver's deck reader
// will do the same with full validation); fails the test on an unknown or missing key.
BaselineParams read_deck(const std::string& path) {
  const YAML::Node c = YAML::LoadFile(path)["controller"];
  REQUIRE(c);
  CHECK(c["type"].as<std::string>() == "baseline");
  BaselineParams p;
  const std::map<std::string, double*> numbers = {
      {"sample_time_s", &p.sample_time_s},
      {"filter_corner_rad_s", &p.filter_corner_rad_s},
      {"cut_in_speed_rad_s", &p.cut_in_speed_rad_s},
      {"region2_start_speed_rad_s", &p.region2_start_speed_rad_s},
      {"region2_gain_N_m_s2", &p.region2_gain_N_m_s2},
      {"rated_generator_speed_rad_s", &p.rated_generator_speed_rad_s},
      {"rated_power_W", &p.rated_power_W},
      {"slip_percent", &p.slip_percent},
      {"max_torque_N_m", &p.max_torque_N_m},
      {"max_torque_rate_N_m_s", &p.max_torque_rate_N_m_s},
      {"region3_min_pitch_rad", &p.region3_min_pitch_rad},
      {"reference_speed_rad_s", &p.reference_speed_rad_s},
      {"proportional_gain_s", &p.proportional_gain_s},
      {"integral_gain", &p.integral_gain},
      {"gain_schedule_pitch_rad", &p.gain_schedule_pitch_rad},
      {"min_pitch_rad", &p.min_pitch_rad},
      {"max_pitch_rad", &p.max_pitch_rad},
      {"max_pitch_rate_rad_s", &p.max_pitch_rate_rad_s},
      {"generator_efficiency", &p.generator_efficiency}};
  std::size_t seen = 0;
  for (const auto& entry : c) {
    const std::string key = entry.first.as<std::string>();
    INFO(path << ": key " << key);
    if (key == "type") { ++seen; continue; }
    if (key == "region3_torque") {
      p.region3_torque = region3_torque_from_name(entry.second.as<std::string>());
      ++seen;
      continue;
    }
    const auto it = numbers.find(key);
    REQUIRE(it != numbers.end());
    *it->second = entry.second.as<double>();
    ++seen;
  }
  CHECK(seen == numbers.size() + 2);  // every key present once
  return p;
}

void check_equal(const BaselineParams& a, const BaselineParams& b) {
  CHECK(a.sample_time_s == b.sample_time_s);
  CHECK(a.filter_corner_rad_s == b.filter_corner_rad_s);
  CHECK(a.cut_in_speed_rad_s == b.cut_in_speed_rad_s);
  CHECK(a.region2_start_speed_rad_s == b.region2_start_speed_rad_s);
  CHECK(a.region2_gain_N_m_s2 == b.region2_gain_N_m_s2);
  CHECK(a.rated_generator_speed_rad_s == b.rated_generator_speed_rad_s);
  CHECK(a.rated_power_W == b.rated_power_W);
  CHECK(a.slip_percent == b.slip_percent);
  CHECK(a.max_torque_N_m == b.max_torque_N_m);
  CHECK(a.max_torque_rate_N_m_s == b.max_torque_rate_N_m_s);
  CHECK(a.region3_min_pitch_rad == b.region3_min_pitch_rad);
  CHECK(a.region3_torque == b.region3_torque);
  CHECK(a.reference_speed_rad_s == b.reference_speed_rad_s);
  CHECK(a.proportional_gain_s == b.proportional_gain_s);
  CHECK(a.integral_gain == b.integral_gain);
  CHECK(a.gain_schedule_pitch_rad == b.gain_schedule_pitch_rad);
  CHECK(a.min_pitch_rad == b.min_pitch_rad);
  CHECK(a.max_pitch_rad == b.max_pitch_rad);
  CHECK(a.max_pitch_rate_rad_s == b.max_pitch_rate_rad_s);
  CHECK(a.generator_efficiency == b.generator_efficiency);
}

}  // namespace

TEST_CASE("controller decks equal the published presets", "[unit][control]") {
  const auto root = fowtsim::testing::source_dir() / "inputs";
  const BaselineParams land = read_deck((root / "nrel5mw" / "controller_land.yaml").string());
  const BaselineParams oc3 = read_deck((root / "oc3_hywind" / "controller.yaml").string());
  check_equal(land, nrel5mw_land_baseline());
  check_equal(oc3, oc3_hywind_baseline());
  CHECK_NOTHROW(validate(land));
  CHECK_NOTHROW(validate(oc3));
}
