// The load basis (issue 27): the shipped OC3 basis expands into the standard's DLC table (case
// counts per DLC from the presets' speeds, factors and realisations), the event presets write
// their wind events and controller events into the case decks, and the load tables apply γ_f,
// find the governing cases with their concurrent values, and weight fatigue by time or by events.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/testing/skip.hpp"
#include "sweep/case_expansion.hpp"
#include "sweep/case_files.hpp"
#include "sweep/iec_presets.hpp"
#include "sweep/load_table.hpp"
#include "sweep/sweep_spec.hpp"
#include "sweep/ultimate_loads.hpp"

using namespace fowtsim;
using namespace fowtsim::driver::sweep;

namespace {

std::string override_of(const SweepCase& c, const std::string& key) {
  std::string value;
  for (const DeckOverride& o : c.overrides)
    if (o.key_path == key) value = o.yaml_value;
  return value;
}

}  // namespace

TEST_CASE("load basis: the shipped OC3 basis lists the floating DLC table, case counts per DLC", "[unit][sweep]") {
  const SweepSpec spec = read_sweep_spec(testing::source_dir() / "inputs/sweeps/oc3_load_basis.yaml");
  const std::vector<SweepCase> cases = expand_cases(spec, read_base_deck_facts(spec.base_deck));
  std::map<std::string, std::size_t> count;
  for (const SweepCase& c : cases) ++count[spec.groups[c.group].name];
  // Expected from the standard's table (IEC 61400-1 ed. 4 Table 2, IEC 61400-3-1 Table 1) for
  // V_in 3, V_r 11.4, V_out 25 m/s: bins of 2 m/s V_in … V_out = 3, 5, …, 25 (12 speeds); six
  // realisations for turbulent cases; ECD ± at V_r − 2, V_r, V_r + 2; EWS vertical/horizontal ±;
  // EOG at V_r ± 2 and V_out with the event at 3 instants of the gust; start-up at V_in, V_r ± 2,
  // V_out; EWM yaw −8/0/+8 (6.1, 7.1), 12 directions (6.2), −20/0/+20 (6.3); 6.4 below 0.7 V_ref.
  const std::size_t bins = 12, seeds = 6;
  const std::map<std::string, std::size_t> expected = {
      {"dlc11", bins * seeds}, {"dlc12", bins * seeds}, {"dlc13", bins * seeds}, {"dlc14", 3 * 2},   {"dlc15", bins * 4},
      {"dlc16", bins * seeds}, {"dlc21", bins * seeds}, {"dlc22", bins * seeds}, {"dlc23", 3 * 3},   {"dlc24", bins * seeds},
      {"dlc31", 3},            {"dlc32", 4 * 3},        {"dlc33", 4 * 2},        {"dlc41", 3},       {"dlc42", 3 * 3},
      {"dlc51", 3 * seeds},    {"dlc61", 3 * seeds},    {"dlc62", 12 * seeds},   {"dlc63", 3 * seeds}, {"dlc64", 16 * seeds},
      {"dlc71", 3 * seeds}};
  CHECK(count == expected);
  CHECK(cases.size() == 842);
  // Every preset of the table is in the basis once.
  std::set<std::string> presets;
  for (const LoadCaseGroup& g : spec.groups) presets.insert(g.preset);
  CHECK(presets.size() == preset_table().size());
}

TEST_CASE("load basis: event presets set the IEC wind event and the controller event at the analysis start", "[unit][sweep]") {
  const SweepSpec spec = read_sweep_spec(testing::source_dir() / "inputs/sweeps/oc3_load_basis.yaml");
  const std::vector<SweepCase> cases = expand_cases(spec, read_base_deck_facts(spec.base_deck));
  auto find = [&](const std::string& name) -> const SweepCase& {
    for (const SweepCase& c : cases)
      if (c.name == name) return c;
    FAIL("no case " << name);
    return cases.front();
  };
  // DLC 2.3: EOG at V_r + 2 = 13.4 m/s from t = 60 s (the transient's end); grid loss at the gust's
  // peak, T/2 = 5.25 s later.
  const SweepCase& eog = find("dlc23_ws13.4_t5.25");
  CHECK(override_of(eog, "wind.model") == "power_law");
  CHECK(override_of(eog, "wind.shear_exponent") == "0.2");
  CHECK(override_of(eog, "wind.event.type") == "EOG");
  CHECK(override_of(eog, "wind.event.start_s") == "60");
  CHECK(override_of(eog, "wind.event.rotor_diameter_m") == "126");
  CHECK(override_of(eog, "controller.events") == "[{type: grid_loss, at_s: 65.25}]");
  CHECK(case_deck_text(spec, eog, "/tmp").find("  events: [{type: grid_loss, at_s: 65.25}]\n") != std::string::npos);
  // DLC 1.5: the four shears at each speed.
  CHECK(override_of(find("dlc15_ws25_ewsh-"), "wind.event.type") == "EWS_horizontal");
  CHECK(override_of(find("dlc15_ws25_ewsh-"), "wind.event.sign") == "-1");
  // DLC 3.2: start-up from idling 10 s before the gust.
  const SweepCase& startup = find("dlc32_ws3_t-10");
  CHECK(override_of(startup, "controller.operating_mode") == "idling");
  CHECK(override_of(startup, "aero.unsteady_airfoil") == "hgm");  // feathered blades in deep stall: dynamic stall on
  CHECK(override_of(startup, "controller.events") == "[{type: startup, at_s: 50}]");
  // DLC 6.3: the turbulent 1-year EWM, V_1 = 0.8 V_ref = 40 m/s, at the extreme yaw error.
  const SweepCase& parked = find("dlc63_yaw20_s1");
  CHECK(parked.wind_speed_m_s.value() == Approx(40.0).epsilon(1e-15));
  CHECK(override_of(parked, "wind.direction_deg") == "20");
  CHECK(override_of(parked, "aero.unsteady_airfoil") == "hgm");
  CHECK(override_of(find("dlc13_ws25_s1"), "aero.unsteady_airfoil").empty());  // operating cases keep the deck's aerodynamics
  // γ_f and analysis types from the table (IEC 61400-1 ed. 4 Table 3).
  const auto group = [&](const std::string& name) -> const LoadCaseGroup& {
    for (const LoadCaseGroup& g : spec.groups)
      if (g.name == name) return g;
    FAIL("no group " << name);
    return spec.groups.front();
  };
  CHECK(group("dlc13").partial_safety_factor == 1.35);
  CHECK(group("dlc23").partial_safety_factor == 1.1);
  CHECK_FALSE(group("dlc12").ultimate);
  CHECK(group("dlc12").fatigue);
  CHECK(group("dlc64").fatigue_time_fraction == 0.05);
}

TEST_CASE("load basis: a preset whose default speeds need the turbine's says which key is missing", "[unit][sweep]") {
  TurbineClass turbine;
  turbine.turbulence_class = "B";
  CHECK_THROWS_WITH(preset_plan("dlc1.3", turbine, {}, 120.0, false), Catch::Contains("needs turbine.cut_"));
  CHECK_NOTHROW(preset_plan("dlc1.3", turbine, {}, 120.0, true));  // the group lists its own speeds
  CHECK_THROWS_WITH(preset_plan("dlc1.4", turbine, {}, 120.0, true), Catch::Contains("turbine.rotor_diameter_m"));
}

namespace {

// A hand-built table: two channels, rows with given extremes (max = value, min = −value/2).
struct HandTable {
  SweepSpec spec;
  std::vector<SweepCase> cases;
  LoadTable table;
};

HandTable hand_table() {
  HandTable h;
  h.spec.groups.resize(3);
  h.spec.groups[0].name = "normal";    // six realisations of one load case, γ_f 1.35
  h.spec.groups[0].partial_safety_factor = 1.35;
  h.spec.groups[1].name = "abnormal";  // one realisation, γ_f 1.1
  h.spec.groups[1].partial_safety_factor = 1.1;
  h.spec.groups[2].name = "fatigue";   // not an ultimate group: never governs
  h.spec.groups[2].ultimate = false;
  const double maxima[] = {10, 12, 14, 16, 18, 20, /*abnormal*/ 27, /*fatigue*/ 1000};
  for (int i = 0; i < 8; ++i) {
    SweepCase c;
    c.group = i < 6 ? 0 : i == 6 ? 1 : 2;
    c.realisation = i < 6 ? i + 1 : 1;
    c.name = fmt::format("{}_s{}", h.spec.groups[c.group].name, c.realisation);
    h.cases.push_back(c);
  }
  h.table.channels = {"TwrBsMyt", "PtfmPitch"};
  h.table.units = {"kN·m", "deg"};
  for (int i = 0; i < 8; ++i) {
    LoadTableRow r;
    r.case_ = &h.cases[i];
    r.outcome.state = CaseState::completed;
    // Channel 0 peaks at t = 100 + i s with PtfmPitch = i then; channel 1 = i/10 everywhere.
    r.maxima = {ChannelExtreme{maxima[i], 100.0 + i, {maxima[i], double(i)}}, ChannelExtreme{i / 10.0, 1.0, {0.0, i / 10.0}}};
    r.minima = {ChannelExtreme{-maxima[i] / 2, 200.0 + i, {-maxima[i] / 2, -double(i)}}, ChannelExtreme{-i / 10.0, 2.0, {0.0, -i / 10.0}}};
    h.table.rows.push_back(r);
  }
  return h;
}

}  // namespace

TEST_CASE("load basis: the ultimate table applies γ_f to the characteristic value and names the governing case", "[unit][sweep]") {
  HandTable h = hand_table();
  const std::vector<UltimateLoad> loads = ultimate_loads(h.table, h.spec);
  REQUIRE(loads.size() == 4);  // two channels × max, min
  // TwrBsMyt max: normal F_k = mean of the six maxima = 15, γ_f F_k = 20.25; abnormal 1.1 × 27 =
  // 29.7 governs (the fatigue group's 1000 is not an ultimate case). Exact: sums of small integers.
  const UltimateLoad& max = loads[0];
  CHECK(max.sense == UltimateLoad::Sense::maximum);
  CHECK(max.design_value == Approx(29.7).epsilon(1e-15));
  CHECK(max.characteristic_value == 27.0);
  CHECK(max.partial_safety_factor == 1.1);
  CHECK_FALSE(max.mean_of_realisations);
  CHECK(max.governing->case_->name == "abnormal_s1");
  CHECK(max.time_s == 106.0);
  CHECK(max.concurrent == std::vector<double>{27.0, 6.0});
  // TwrBsMyt min: normal 1.35 × mean(−5 … −10) = −10.125 against abnormal 1.1 × −13.5 = −14.85.
  CHECK(loads[1].design_value == Approx(-14.85).epsilon(1e-15));
  // PtfmPitch, an angle (deg): no γ_f. Max: abnormal 0.6 governs over normal mean(0 … 0.5) = 0.25.
  CHECK(loads[2].partial_safety_factor == 1.0);
  CHECK(loads[2].design_value == Approx(0.6).epsilon(1e-15));

  SECTION("six realisations: F_k is their mean, the governing realisation holds the largest") {
    h.spec.groups[1].ultimate = false;
    const std::vector<UltimateLoad> normal = ultimate_loads(h.table, h.spec);
    CHECK(normal[0].characteristic_value == Approx(15.0).epsilon(1e-15));
    CHECK(normal[0].design_value == Approx(1.35 * 15.0).epsilon(1e-15));
    CHECK(normal[0].mean_of_realisations);
    CHECK(normal[0].realisations == 6);
    CHECK(normal[0].governing->case_->name == "normal_s6");
    CHECK(normal[0].time_s == 105.0);
    CHECK(normal[0].concurrent == std::vector<double>{20.0, 5.0});
  }
  SECTION("a failed realisation leaves five: F_k is then their largest") {
    h.spec.groups[1].ultimate = false;
    h.table.rows[0].outcome.state = CaseState::failed;
    const std::vector<UltimateLoad> five = ultimate_loads(h.table, h.spec);
    CHECK(five[0].characteristic_value == 20.0);
    CHECK_FALSE(five[0].mean_of_realisations);
  }
}

TEST_CASE("load basis: fatigue of parked time and of events weighted as MLife extrapolates runs", "[unit][sweep]") {
  // Two fatigue groups with one 600-s run each: operating at 10 m/s for 0.9 of the life, and a
  // start-up event at 10 m/s 100 times a year. Damage sums D1 = 5e6, D2 = 2e4 (channel unit^m).
  SweepSpec spec;
  spec.load_table.design_life_years = 20.0;
  spec.groups.resize(2);
  spec.groups[0].name = "operating";
  spec.groups[0].fatigue = true;
  spec.groups[0].fatigue_time_fraction = 0.9;
  spec.groups[1].name = "startup";
  spec.groups[1].fatigue = true;
  spec.groups[1].events_per_year = {100.0};
  std::vector<SweepCase> cases(2);
  LoadTable table;
  table.fatigue = {{"TwrBsMyt", 4.0}};
  table.wind_distribution = post::WindSpeedDistribution::rayleigh(10.0);
  table.bin_width_m_s = 2.0;
  const double damage[] = {5e6, 2e4};
  for (int i = 0; i < 2; ++i) {
    cases[i].group = static_cast<std::size_t>(i);
    cases[i].fatigue = true;
    cases[i].wind_speed_m_s = 10.0;
    LoadTableRow r;
    r.case_ = &cases[i];
    r.outcome.state = CaseState::completed;
    r.window_s = 600.0;
    r.damage_sums = {damage[i]};
    table.rows.push_back(r);
  }
  add_lifetime(table, spec);
  REQUIRE(table.lifetime.at(0).load);
  // D_life = 0.9 P(9 < V ≤ 11) T_life / 600 s · D1 + 100 a⁻¹ · 20 a · D2 (the event's one-value
  // count all at its only speed). Relative 1e-14: a few roundings of the Rayleigh exponentials.
  const double life_s = 20.0 * post::seconds_per_year;
  const double p = table.wind_distribution.cumulative_probability(11.0) - table.wind_distribution.cumulative_probability(9.0);
  const double expected = 0.9 * p * life_s / 600.0 * 5e6 + 100.0 * 20.0 * 2e4;
  CHECK(table.lifetime[0].load->damage_sum == Approx(expected).epsilon(1e-14));
  CHECK(table.lifetime[0].runs == 2);
}
