// Seed 000 §3.5.3's riser and what it needs: a held tip moved by a prescribed motion, still water
// (buoyancy, added mass, drag on the relative velocity) and the four cases (a)–(d).
#include <cmath>
#include <cstdio>

#include <catch2/catch.hpp>

#include "fowtsim/beam/riser.hpp"

using namespace fowtsim;
using namespace fowtsim::beam;

TEST_CASE("explore riser", "[.explore]") {
  for (char c : {'a', 'b', 'c', 'd'}) {
    const riser::RiserRun r = riser::simulate(riser::seed_case(c), 100, 1e-3, 11.0, {1.0, 3.5, 6.0, 8.5, 11.0});
    std::printf("case %c: max M %.4g N·m (bottom %.4g, top %.4g), max defl %.4g m, mid sway %.4g\n", c,
                r.max_bending_moment_n_m_overall, r.max_bending_moment_n_m.front(), r.max_bending_moment_n_m.back(),
                r.max_deflection_m, r.final_mid_sway_m);
  }
}

#include <chrono>
TEST_CASE("explore speed", "[.explore]") {
  for (double dt : {1e-3, 2e-3, 4e-3}) {
    for (int every : {10, 1000000}) {
      const auto t0 = std::chrono::steady_clock::now();
      const riser::RiserRun r = riser::simulate(riser::seed_case('b'), 100, dt, 11.0, {}, every);
      const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("dt %g every %d: %.3f s wall, %.1fx, maxM %.5g mid %.5g\n", dt, every, sec, 11.0 / sec, r.max_bending_moment_n_m_overall, r.final_mid_sway_m);
    }
  }
}
