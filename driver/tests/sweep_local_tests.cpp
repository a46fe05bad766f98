// A local sweep (issue 14): 12 short OC3 cases and one that blows up, in 2 processes. Every good
// case completes and has its row, the failure is reported with its exit code and reason, a rerun
// skips what completed, and a case rerun alone reproduces its output bit for bit.
#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>

#include "fowtsim/io/readers.hpp"
#include "sweep/case_files.hpp"
#include "sweep/case_outcome.hpp"
#include "sweep_test_spec.hpp"

using namespace fowtsim;
using namespace fowtsim::sweep_test;

namespace {

std::vector<std::vector<std::string>> csv_rows(const std::filesystem::path& csv) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read_text(csv));
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (const char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) fields.push_back(std::exchange(field, ""));
      else field += c;
    }
    fields.push_back(field);
    rows.push_back(std::move(fields));
  }
  return rows;
}

}  // namespace

TEST_CASE("local sweep: 12 cases in 2 processes, a failing case reported, resumable, each case reproducible alone",
          "[verification][sweep]") {
  const std::filesystem::path dir = testing::scratch_dir("sweep_local");
  const std::filesystem::path spec = write_small_sweep(dir);
  const std::filesystem::path out = dir / "out";
  const std::string sweep = spec.string() + " --output-dir " + out.string() + " --jobs 2";

  // One case fails: the sweep says so (exit 1) and the others complete.
  REQUIRE(run_fowtsim("sweep " + sweep, dir / "first.log") == 1);
  const std::string first_log = read_text(dir / "first.log");
  INFO(first_log);
  CHECK_THAT(first_log, Catch::Contains("12 completed of 13"));
  CHECK_THAT(first_log, Catch::Contains("failed           blowup (exit 3): numerical failure:"));
  CHECK_THAT(first_log, Catch::Contains("throughput"));
  // The yaw variants of a realisation share its wind seed and its field, generated once; the
  // sweep's folder of fields is gone once they have all run.
  CHECK_THAT(first_log, Catch::Contains("turbulence       6 field(s) shared by 12 case(s), each generated once"));
  CHECK_FALSE(std::filesystem::exists(out / "turbulence"));

  const auto rows = csv_rows(out / "load_table.csv");
  REQUIRE(rows.size() == 1 + kGoodCases + 1);
  const auto& header = rows[0];
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const auto seed_of = [&](const std::string& name) {
    for (const auto& row : rows)
      if (row[column("case")] == name) return row[column("wind_seed")];
    return std::string("not found");
  };
  CHECK(seed_of("dlc12_ws12_yaw0_s1") == seed_of("dlc12_ws12_yaw8_s1"));
  CHECK(seed_of("dlc12_ws12_yaw0_s1") != seed_of("dlc12_ws12_yaw0_s2"));
  CHECK(seed_of("dlc12_ws12_yaw0_s1") != seed_of("dlc12_ws16_yaw0_s1"));
  for (std::size_t r = 1; r <= kGoodCases; ++r) {
    CHECK(rows[r][column("state")] == "completed");
    CHECK_FALSE(rows[r][column("TwrBsMyt_max[kN-m]")].empty());
    CHECK_FALSE(rows[r][column("TwrBsMyt_DEL_m4[kN-m]")].empty());
  }
  const auto& failed = rows.back();
  CHECK(failed[column("case")] == "blowup");
  CHECK(failed[column("state")] == "failed");
  CHECK(failed[column("exit_code")] == "3");
  CHECK_THAT(failed[column("message")], Catch::Contains("numerical failure"));
  CHECK(failed[column("TwrBsMyt_max[kN-m]")].empty());  // listed, with no numbers made up
  CHECK_THAT(read_text(out / "load_table.md"), Catch::Contains("| blowup | failed | 3 |"));
  CHECK(std::filesystem::exists(out / "load_table.h5"));

  // A rerun skips every completed case (their outputs are not touched) and retries the failure.
  const driver::sweep::SweepLayout layout{out};
  const auto written_at = std::filesystem::last_write_time(layout.output("dlc12_ws12_yaw8_s2"));
  const std::string first_table = read_text(out / "load_table.csv");
  REQUIRE(run_fowtsim("sweep " + sweep, dir / "second.log") == 1);
  CHECK_THAT(read_text(dir / "second.log"), Catch::Contains("13 (12 completed earlier and skipped), 1 to run"));
  CHECK(std::filesystem::last_write_time(layout.output("dlc12_ws12_yaw8_s2")) == written_at);
  CHECK(read_text(out / "load_table.csv") == first_table);

  // A case rerun alone from its deck (generating its own field) gives the same numbers, bit for bit,
  // and the same deck hash: the yaw-0 case generated the shared field in the sweep (the yaw-0 cases
  // run first), the yaw-8 case read it.
  for (const std::string name : {"dlc12_ws16_yaw0_s1", "dlc12_ws16_yaw8_s1"}) {
    const std::filesystem::path alone = dir / (name + "_alone.h5");
    REQUIRE(run_fowtsim("run " + layout.deck(name).string() + " -o " + alone.string(), dir / "alone.log") == 0);
    const io::ChannelTable swept = io::read_hdf5_channels(layout.output(name));
    const io::ChannelTable single = io::read_hdf5_channels(alone);
    REQUIRE(swept.names == single.names);
    for (std::size_t c = 0; c < swept.columns.size(); ++c) CHECK(swept.columns[c] == single.columns[c]);
    CHECK(driver::sweep::read_run_attributes(alone).deck_hash == driver::sweep::read_run_attributes(layout.output(name)).deck_hash);
  }
}
