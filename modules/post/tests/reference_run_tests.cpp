// The OpenFAST OC3-Hywind 600 s run (../shared/reference) post-processed here and, independently,
// by modules/post/tests/reference_numbers.py (numpy; ASTM three-point rainflow and numpy-FFT Welch
// written separately from the C++): both must agree to round-off.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/io/readers.hpp"
#include "fowtsim/post/damage_equivalent_load.hpp"
#include "fowtsim/post/statistics.hpp"
#include "fowtsim/post/welch_psd.hpp"
#include "fowtsim/testing/skip.hpp"

using namespace fowtsim;
using namespace fowtsim::post;

namespace {

const char* const kOc3Run =
    "reference/openfast-runs/oc3_spar_wturb_wavesirr/glue-codes/openfast/5MW_OC3Spar_DLL_WTurb_WavesIrr/"
    "5MW_OC3Spar_DLL_WTurb_WavesIrr_600s.out";

struct WindowedChannel {
  std::vector<double> time_s, values;
};

WindowedChannel channel_over_60_to_600_s(const io::ChannelTable& table, const std::string& name) {
  const RowRange rows = rows_in_window(table.time(), TimeWindow{60.0, 600.0});
  const std::vector<double>& column = table.columns.at(table.find(name).value());
  return {{table.time().begin() + static_cast<std::ptrdiff_t>(rows.first), table.time().begin() + static_cast<std::ptrdiff_t>(rows.last)},
          {column.begin() + static_cast<std::ptrdiff_t>(rows.first), column.begin() + static_cast<std::ptrdiff_t>(rows.last)}};
}

// The numbers printed by reference_numbers.py for one channel over 60–600 s.
struct NumpyReference {
  const char* channel;
  double min, max, mean, std, skewness, kurtosis, time_of_min_s, time_of_max_s;
  double wohler_exponent;           // 0: no DEL
  double del, ultimate_load, goodman_del;  // ultimate_load 0: no Goodman check
  double peak_frequency_hz[3];      // three highest Welch peaks (100 s segments)
  double peak_density[3];
};

// Output of `/usr/bin/python3 modules/post/tests/reference_numbers.py <the run>` (numpy 1.24.2).
const NumpyReference kReferences[] = {
    {"RootMyc1", 3086.84521, 13645.1924, 8455.615714352376, 1743.7264739241343, -0.021056283470106303, 2.713117875543283,
     299.8, 142.75, 10, 5812.710472304881, 1.775e4, 11183.874433586769, {0.02, 0.1, 0.2},
     {30336940.232907444, 20985457.51329486, 16585938.561167393}},
    {"RotTorq", 2439.50098, 4635.29443, 3800.7192464290342, 514.21644306602, -0.7579746275160967, 2.127499513922217, 488.25,
     386.1, 3, 610.2525733381265, 8.909e3, 1034.4282553823323, {0.01, 0.1, 0.16},
     {5545799.965892369, 1748334.5842749486, 260069.2176617436}},
    {"TwrBsMyt", -8522.07617, 142528.453, 74244.73798389627, 25766.71541263441, 0.02049249269216174, 2.6019104065468985,
     299.15, 171.9, 4, 49020.7093594981, 0, 0, {0.1, 0.02, 0.16}, {10505197648.497965, 4600698672.123798, 1759998976.233997}},
    {"PtfmPitch", 1.4771986, 6.09515524, 4.215306672735857, 0.8747261578856388, -0.5532021609489007, 2.847578947190606, 298.5,
     458.5, 0, 0, 0, 0, {0.02, 0.09, 0.25}, {20.84301585570124, 2.85635397317493, 0.0012022133258062606}},
};

}  // namespace

TEST_CASE("statistics, DELs and PSD peaks of the OpenFAST OC3 600 s run agree with numpy", "[verification]") {
  const io::ChannelTable table = io::read_channels(fowtsim::testing::shared_dir_or_skip() / kOc3Run);
  for (const NumpyReference& ref : kReferences) {
    INFO(ref.channel);
    const WindowedChannel ch = channel_over_60_to_600_s(table, ref.channel);
    const ChannelStatistics st = channel_statistics(ch.time_s, ch.values);
    // Extremes and their times are samples: exact. Moments: round-off of 10,801-term sums in another
    // order, 10× the worst measured over the four channels: mean and std 8.2e-15 relative → 1e-13;
    // skewness 6.1e-14 absolute (it is near 0 for two channels) → 1e-12 absolute; kurtosis 3.7e-14 → 5e-13.
    CHECK(st.min == ref.min);
    CHECK(st.max == ref.max);
    CHECK(st.time_of_min_s == ref.time_of_min_s);
    CHECK(st.time_of_max_s == ref.time_of_max_s);
    CHECK(st.samples == 10801u);
    CHECK(st.mean == Approx(ref.mean).epsilon(1e-13));
    CHECK(st.std == Approx(ref.std).epsilon(1e-13));
    CHECK(st.skewness == Approx(ref.skewness).epsilon(0).margin(1e-12));
    CHECK(st.kurtosis == Approx(ref.kurtosis).epsilon(5e-13));

    const double duration_s = ch.time_s.back() - ch.time_s.front();
    if (ref.wohler_exponent > 0) {
      // Same cycles from two algorithms (four-point here, three-point in numpy), summed in another
      // order: measured 0 (bit-identical); 2e-15 for summation order.
      const std::vector<RainflowCycle> cycles = rainflow_cycles(ch.values);
      CHECK(damage_equivalent_load(cycles, duration_s, FatigueParams{ref.wohler_exponent, std::nullopt, 0.0, 1.0}) ==
            Approx(ref.del).epsilon(2e-15));
      if (ref.ultimate_load > 0)
        CHECK(damage_equivalent_load(cycles, duration_s, FatigueParams{ref.wohler_exponent, ref.ultimate_load, 0.0, 1.0}) ==
              Approx(ref.goodman_del).epsilon(2e-15));
    }
    // Welch with 100 s segments: the same peak bins (frequencies to the round-off of k f_s / L),
    // densities to FFT round-off (FFTW against numpy's pocketfft: measured ≤ 5.4e-15) → 1e-13.
    const double fs = uniform_sample_rate_hz(ch.time_s);
    const WelchEstimator welch(segment_samples_for(100.0, fs, ch.values.size()));
    const std::vector<SpectralPeak> peaks = spectral_peaks(welch.estimate(ch.values, fs), 3);
    REQUIRE(peaks.size() == 3u);
    for (int i = 0; i < 3; ++i) {
      CHECK(peaks[i].frequency_hz == Approx(ref.peak_frequency_hz[i]).epsilon(1e-12));
      CHECK(peaks[i].density == Approx(ref.peak_density[i]).epsilon(1e-13));
    }
  }
}
