// Module-contract conformance: parameters validated with every problem listed, outputs pure,
// advance + outputs = evaluate, state copies reproduce results, channels and values agree,
// profiles start at the anchor and end at the fairlead.
#include <algorithm>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/module.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/mooring/presets.hpp"
#include "fowtsim/mooring/profile.hpp"

using namespace fowtsim;
using namespace fowtsim::mooring;

static_assert(Module<QuasiStaticMooring>);
static_assert(std::is_trivially_copyable_v<QuasiStaticMooring::State>);

namespace {

QuasiStaticMooring::Input displaced() {
  QuasiStaticMooring::Input u;
  u.platform.position_m = Vec3(12.0, 3.0, -0.5);
  u.platform.orientation = euler123_to_matrix(Vec3(0.01, 0.05, 0.03));
  return u;
}

}  // namespace

TEST_CASE("invalid parameters are reported together, naming each key", "[unit][mooring]") {
  MooringParams p = oc3_hywind_mooring();
  p.depth_m = -1.0;
  p.lines[1].ea_N = 0.0;
  p.lines[2].diameter_m = 0.5;  // displaces 201 kg/m > 77.7 kg/m: the line floats
  try {
    validate(p);
    FAIL("expected InputError");
  } catch (const InputError& e) {
    const std::string m = e.message();
    CHECK(m.find("mooring.depth_m") != std::string::npos);
    CHECK(m.find("mooring.lines[1].ea_N") != std::string::npos);
    CHECK(m.find("mooring.lines[2].mass_per_length_kg_m") != std::string::npos);
    CHECK(m.find("floats") != std::string::npos);
  }
  MooringParams none = oc3_hywind_mooring();
  none.lines.clear();
  CHECK_THROWS_AS(QuasiStaticMooring::make_state(none), InputError);
  MooringParams buried = oc3_hywind_mooring();
  buried.lines[0].anchor_m.z() = -330.0;
  CHECK_THROWS_AS(validate(buried), InputError);
  CHECK_THROWS_AS(line_model_from_name("lumped"), InputError);
  CHECK(line_model_from_name("taut") == LineModel::taut);
  // The taut model needs neither mass nor diameter nor depth.
  MooringParams taut = seed_taut_mooring(-93.2, 4.7, 4e5);
  taut.depth_m = 0.0;
  CHECK_NOTHROW(validate(taut));
}

TEST_CASE("outputs is pure, advance then outputs equals evaluate, a copied state reproduces", "[unit][mooring]") {
  const MooringParams p = oc3_hywind_mooring();
  QuasiStaticMooring::State s = QuasiStaticMooring::make_state(p);
  const QuasiStaticMooring::Input u = displaced();
  const QuasiStaticMooring::State before = s;
  const auto y1 = QuasiStaticMooring::outputs(p, u, s);
  CHECK(std::equal(before.lines.begin(), before.lines.end(), s.lines.begin(),
                   [](const auto& a, const auto& b) { return a.valid == b.valid && a.h_N == b.h_N; }));
  QuasiStaticMooring::advance(p, u, 0.0, 0.05, s);
  CHECK(s.lines[0].valid);
  const QuasiStaticMooring::State copy = s;
  const auto y2 = QuasiStaticMooring::outputs(p, u, s);
  const auto y3 = QuasiStaticMooring::outputs(p, u, copy);
  // Cold vs warm start: both converge to the 1e-10 L residual; measured 5.9e-10 relative.
  CHECK((y1.force_N - y2.force_N).norm() <= 1e-8 * y1.force_N.norm());
  CHECK(y2.force_N == y3.force_N);  // bit-identical from identical state
  CHECK(y2.moment_N_m == y3.moment_N_m);
}

TEST_CASE("channels and channel values agree in count, order and units", "[unit][mooring]") {
  const MooringParams p = oc3_hywind_mooring();
  const auto channels = QuasiStaticMooring::channels(p);
  REQUIRE(channels.size() == 6 + 4 * 3);
  CHECK(channels[0].name == "MoorFxi");
  CHECK(channels[6].name == "FAIRTEN1");
  CHECK(channels[7].name == "ANCHTEN1");
  CHECK(channels[10].name == "FAIRTEN2");
  CHECK(channels[17].name == "FAIRV3");
  ChannelRegistry registry;
  for (const auto& c : channels) registry.add(c);  // unique, valid names
  QuasiStaticMooring::State s = QuasiStaticMooring::make_state(p);
  const auto y = QuasiStaticMooring::evaluate(p, displaced(), s);
  std::vector<double> values(channels.size());
  QuasiStaticMooring::channel_values(p, y, values);
  CHECK(values[0] == y.force_N.x());
  CHECK(values[5] == y.moment_N_m.z());
  CHECK(values[6] == y.lines[0].fairlead_tension_N);
  CHECK(values[15] == y.lines[2].anchor_tension_N);
  std::vector<double> wrong(3);
  CHECK_THROWS_AS(QuasiStaticMooring::channel_values(p, y, wrong), InputError);
}

TEST_CASE("line profiles run from the anchor to the fairlead with the solved tensions", "[unit][mooring]") {
  for (const MooringParams& p : {oc3_hywind_mooring(), seed_taut_mooring(-93.2, 4.7, 4e5)}) {
    QuasiStaticMooring::State s = QuasiStaticMooring::make_state(p);
    const auto u = displaced();
    const auto y = QuasiStaticMooring::evaluate(p, u, s);
    for (std::size_t i = 0; i < p.lines.size(); ++i) {
      const auto nodes = line_profile(p, u, s, i, 41);
      REQUIRE(nodes.size() == 41);
      CHECK((nodes.front().position_m - p.lines[i].anchor_m).norm() == 0.0);
      // Closure is the solver's residual: ≤ 1e-10 L = 9e-8 m per span, so ≤ 1.3e-7 m.
      CHECK((nodes.back().position_m - y.lines[i].fairlead_m).norm() <= 1.3e-7);
      CHECK(nodes.back().tension_N == Approx(y.lines[i].fairlead_tension_N).epsilon(1e-12));
      CHECK(nodes.front().tension_N == Approx(y.lines[i].anchor_tension_N).epsilon(1e-12));
      CHECK(nodes.back().arc_length_m == p.lines[i].unstretched_length_m);
      for (const auto& n : nodes) CHECK(n.position_m.z() >= -320.0 - 1e-9);  // never below the seabed
    }
  }
  const MooringParams p = oc3_hywind_mooring();
  CHECK_THROWS_AS(line_profile(p, displaced(), QuasiStaticMooring::make_state(p), 3, 10), InputError);
}

TEST_CASE("the yaw spring of the delta connection resists yaw", "[unit][mooring]") {
  // M_z = −k ψ on top of the lines: the difference with and without the spring is exactly −k ψ.
  MooringParams with = oc3_hywind_mooring(), without = with;
  without.delta_yaw_stiffness_N_m_rad = 0.0;
  QuasiStaticMooring::Input u;
  u.platform.orientation = euler123_to_matrix(Vec3(0.0, 0.0, 0.1));
  QuasiStaticMooring::State s1 = QuasiStaticMooring::make_state(with), s2 = s1;
  const double m_with = QuasiStaticMooring::evaluate(with, u, s1).moment_N_m.z();
  const double m_without = QuasiStaticMooring::evaluate(without, u, s2).moment_N_m.z();
  CHECK(m_with - m_without == Approx(-9.834e7 * 0.1).epsilon(1e-12));
  CHECK(m_without < 0.0);  // the lines alone also restore
}
