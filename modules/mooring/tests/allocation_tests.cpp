// The per-step calls (evaluate, advance, outputs, channel_values) must not touch the heap
// (fixed-size State and Output). Global operator new is replaced in this test executable to
// count allocations while a flag is set.
#include <array>
#include <atomic>
#include <cstdlib>
#include <new>

#include <catch2/catch.hpp>

#include "fowtsim/testing/allocation_counter.hpp"

#include "fowtsim/mooring/presets.hpp"
#include "fowtsim/mooring/quasi_static_mooring.hpp"

using fowtsim::testing::allocations;
using fowtsim::testing::counting;

using namespace fowtsim;
using namespace fowtsim::mooring;

TEST_CASE("mooring step calls allocate nothing", "[unit][mooring]") {
  for (const MooringParams& p : {oc3_hywind_mooring(), seed_taut_mooring(-93.2, 4.7, 4e5)}) {
    QuasiStaticMooring::State s = QuasiStaticMooring::make_state(p);
    std::array<double, 6 + 4 * 4> values{};
    const std::size_t n = 6 + 4 * p.lines.size();
    allocations = 0;
    counting = true;
    for (int k = 0; k < 100; ++k) {
      QuasiStaticMooring::Input u;
      u.platform.position_m = Vec3(0.1 * k, 0.0, 0.0);
      u.time_s = 0.05 * k;
      QuasiStaticMooring::advance(p, u, 0.05 * k, 0.05, s);
      const auto y = QuasiStaticMooring::outputs(p, u, s);
      QuasiStaticMooring::channel_values(p, y, std::span<double>(values.data(), n));
    }
    counting = false;
    CHECK(allocations == 0);
  }
}
