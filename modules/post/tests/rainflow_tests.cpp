// Rainflow counting against ASTM E1049-85 and hand-built series.
#include <algorithm>
#include <map>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/post/rainflow.hpp"

using namespace fowtsim::post;

namespace {

// The example of ASTM E1049-85 §5.4.4 (Fig. 6): loads −2, 1, −3, 5, −1, 3, −4, 4, −2.
const std::vector<double> astm_example{-2, 1, -3, 5, -1, 3, -4, 4, -2};

std::map<double, double> counts_by_range(const std::vector<RainflowCycle>& cycles) {
  std::map<double, double> counts;
  for (const RainflowCycle& c : cycles) counts[c.range] += c.count;
  return counts;
}

}  // namespace

TEST_CASE("rainflow of the ASTM E1049-85 example gives the standard's cycle table", "[verification]") {
  // Source: ASTM E1049-85 (2017) Table 4 / Fig. 6: ranges 3, 4, 6, 8, 9 counted 0.5, 1.5, 0.5, 1.0,
  // 0.5. Exact: ranges are differences of small integers.
  const std::map<double, double> expected{{3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}};
  CHECK(counts_by_range(rainflow_cycles(astm_example)) == expected);
  // The one full cycle is −1 → 3 (mean 1); the rest are residue half cycles.
  const std::vector<RainflowCycle> cycles = rainflow_cycles(astm_example);
  REQUIRE(cycles.size() == 7u);
  CHECK((cycles[0].range == 4 && cycles[0].mean == 1 && cycles[0].count == 1.0));
}

TEST_CASE("residue counted as full cycles doubles only the residue counts", "[unit]") {
  // Residue −2, 1, −3, 5, −4, 4, −2: ranges 3, 4, 8, 9, 8, 6 each 1.0 instead of 0.5.
  const std::map<double, double> expected{{3, 1.0}, {4, 2.0}, {6, 1.0}, {8, 2.0}, {9, 1.0}};
  CHECK(counts_by_range(rainflow_cycles(astm_example, ResidueCounting::full_cycles)) == expected);
}

TEST_CASE("turning points drop monotone runs and plateaus", "[unit]") {
  const std::vector<double> series{0, 1, 2, 2, 3, 1, 1, 0, 4, 4};
  CHECK(turning_points(series) == std::vector<double>{0, 3, 0, 4});
  CHECK(turning_points(std::vector<double>{}).empty());
  CHECK(turning_points(std::vector<double>{5, 5, 5}) == std::vector<double>{5});
  // A densely sampled series counts as its turning points do.
  std::vector<double> dense;
  for (std::size_t i = 0; i + 1 < astm_example.size(); ++i)
    for (int k = 0; k < 10; ++k) dense.push_back(astm_example[i] + (astm_example[i + 1] - astm_example[i]) * k / 10.0);
  dense.push_back(astm_example.back());
  CHECK(counts_by_range(rainflow_cycles(dense)) == counts_by_range(rainflow_cycles(astm_example)));
}

TEST_CASE("a constant or one-sample series has no cycles", "[unit]") {
  CHECK(rainflow_cycles(std::vector<double>{1.0}).empty());
  CHECK(rainflow_cycles(std::vector<double>{2, 2, 2}).empty());
}

TEST_CASE("a small cycle inside a large one closes; the large one stays in the residue", "[unit]") {
  // 0 → 10 → 4 → 6 → −10: the 4–6 excursion is one full cycle of range 2 (mean 5); the rest is
  // residue 0, 10, −10 (half cycles of range 10 and 20).
  const std::vector<RainflowCycle> cycles = rainflow_cycles(std::vector<double>{0, 10, 4, 6, -10});
  REQUIRE(cycles.size() == 3u);
  CHECK((cycles[0].range == 2 && cycles[0].mean == 5 && cycles[0].count == 1.0));
  CHECK((cycles[1].range == 10 && cycles[1].count == 0.5));
  CHECK((cycles[2].range == 20 && cycles[2].mean == 0 && cycles[2].count == 0.5));
}
