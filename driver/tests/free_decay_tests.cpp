// OC3-Hywind free decay with the rigid multibody, Morison hydro, nonlinear hydrostatics and the
// catenary mooring (issue 6, verification 4): natural periods within 5 % of the published OC3
// values, and against the OpenFAST v5 free-decay runs of the same deck.
#include <cmath>
#include <numeric>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

// Mean period between up-crossings of the signal about its mean over the second half (the level
// it decays to), as the OpenFAST runs' README measures it.
double mean_period(const std::vector<double>& t, const std::vector<double>& x) {
  const std::size_t half = x.size() / 2;
  const double level = std::accumulate(x.begin() + static_cast<long>(half), x.end(), 0.0) / static_cast<double>(x.size() - half);
  std::vector<double> up;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (x[i - 1] - level < 0.0 && x[i] - level >= 0.0)
      up.push_back(t[i - 1] + (t[i] - t[i - 1]) * (level - x[i - 1]) / (x[i] - x[i - 1]));
  REQUIRE(up.size() >= 2);
  return (up.back() - up.front()) / static_cast<double>(up.size() - 1);
}

struct DecayCase {
  const char* name;
  const char* channel;
  double published_hz;  // PUBLISHED.md, OC3-Hywind platform natural frequencies (TP-47266)
};

}  // namespace

TEST_CASE("OC3-Hywind free-decay periods", "[verification][floating_scene]") {
  const auto dir = testing::scratch_dir("free_decay");
  const DecayCase cases[] = {{"surge", "PtfmSurge", 0.0080}, {"heave", "PtfmHeave", 0.0324},
                             {"pitch", "PtfmPitch", 0.0343}, {"yaw", "PtfmYaw", 0.1210}};
  for (const DecayCase& c : cases) {
    run_scene(run_request(testing::source_dir() / "inputs/oc3_hywind" / (std::string("free_decay_") + c.name + ".yaml"),
                          dir / c.name),
              nullptr);
    const io::ChannelTable ours = io::read_channels(dir / (std::string(c.name) + ".out"));
    const double period = mean_period(ours.time(), ours.columns[*ours.find(c.channel)]);
    INFO(c.name << ": period " << period << " s, published " << 1.0 / c.published_hz << " s");
    // Issue 6: within 5 % of the published natural frequency. Measured: surge +1.1 %, heave
    // −1.8 %, pitch +2.9 %, yaw −0.3 % (the published values are rounded to 2–3 digits).
    CHECK(std::abs(period * c.published_hz - 1.0) < 0.05);
  }
}

TEST_CASE("OC3-Hywind free decay against the OpenFAST runs", "[verification][floating_scene]") {
  const auto ref_dir = testing::shared_dir_or_skip() / "reference/openfast-runs/oc3_free_decay";
  const auto dir = testing::scratch_dir("free_decay_vs_openfast");
  const DecayCase cases[] = {{"surge", "PtfmSurge", 0}, {"heave", "PtfmHeave", 0}, {"pitch", "PtfmPitch", 0}, {"yaw", "PtfmYaw", 0}};
  for (const DecayCase& c : cases) {
    run_scene(run_request(testing::source_dir() / "inputs/oc3_hywind" / (std::string("free_decay_") + c.name + ".yaml"),
                          dir / c.name),
              nullptr);
    const io::ChannelTable ours = io::read_channels(dir / (std::string(c.name) + ".out"));
    const io::ChannelTable theirs = io::read_channels(ref_dir / c.name / (std::string("oc3_decay_") + c.name + ".out"));
    const double p_ours = mean_period(ours.time(), ours.columns[*ours.find(c.channel)]);
    const double p_theirs = mean_period(theirs.time(), theirs.columns[*theirs.find(c.channel)]);
    // The OpenFAST runs take added mass and radiation damping from WAMIT potential flow, we from
    // Morison strips with Ca = 1 (the runs' README: "compare periods to a few percent"): 3 %.
    // Measured: surge +0.7 %, heave −1.7 %, pitch +1.8 %, yaw −0.03 %.
    INFO(c.name << ": ours " << p_ours << " s, OpenFAST " << p_theirs << " s");
    CHECK(std::abs(p_ours / p_theirs - 1.0) < 0.03);
    // A free decay: nothing grows beyond the initial displacement (5 % for the offset of the
    // static equilibrium, e.g. the heave sink under the turbine weight).
    const auto& x = ours.columns[*ours.find(c.channel)];
    double largest = 0.0;
    for (double v : x) largest = std::max(largest, std::abs(v));
    CHECK(largest <= std::abs(x.front()) * 1.05);
  }
}
