// `fowtsim verify screening`: the frequency-domain screening of the floating turbine (issue 25,
// "Beyond the seed"; scenes/floating_screening.hpp) against what the project already matches —
// OpenFAST's OC3-Hywind free-decay periods, the steady operating points of our time domain and the
// published rotor speeds, and our own time domain of the same deck in an irregular sea over one
// period of its periodic record. The bounds and their reasons are those of
// driver/tests/screening_tests.cpp; a few seconds. It prints the time of one screening case.
#include <limits>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "fowtsim/post/statistics.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "run/run_scene.hpp"
#include "scenes/floating_screening.hpp"
#include "verify/verify_cases.hpp"

namespace fowtsim::driver {

std::filesystem::path source_input(const std::string& relative);  // verify_cases.cpp

namespace {

std::filesystem::path input(const std::string& relative) { return std::filesystem::absolute(source_input(relative)); }

VerificationRow within(const std::string& metric, double value, double limit, const std::string& source) {
  return {"screening", metric, value, fmt::format("< {:.3g}", limit), source, std::abs(value) < limit};
}

double nearest_frequency(const ScreeningResult& r, double frequency_hz) {
  double best = NAN;
  for (const ScreeningMode& m : r.modes)
    if (std::isnan(best) || std::abs(m.frequency_hz - frequency_hz) < std::abs(best - frequency_hz)) best = m.frequency_hz;
  return best;
}

std::size_t channel(const ScreeningResult& r, const std::string& name) {
  return static_cast<std::size_t>(std::find(r.outputs.begin(), r.outputs.end(), name) - r.outputs.begin());
}

// Population standard deviation of a channel over t ≥ from (fowtsim/post's statistics).
double std_after(const io::ChannelTable& t, const std::string& name, double from) {
  const auto c = t.find(name);
  if (!c) return std::numeric_limits<double>::quiet_NaN();
  const post::RowRange rows = post::rows_in_window(t.time(), post::TimeWindow{from, t.time().back()});
  const std::span<const double> time(t.time().data() + rows.first, rows.size()), x(t.columns[*c].data() + rows.first, rows.size());
  return post::channel_statistics(time, x).std;
}

// Parked, still water, WAMIT: the deck of OpenFAST's free-decay runs (openfast-runs/oc3_free_decay:
// surge 125.46 s, heave 30.82 s, pitch 29.49 s, yaw 8.244 s by up-crossings). The WAMIT files live
// beside the reference data: without them the rows are left out and the output says so.
void free_floating(std::FILE* out, std::vector<VerificationRow>& rows) {
  ScreeningResult r;
  try {
    r = screen_floating(input("oc3_hywind/free_decay_pitch_wamit.yaml"));
  } catch (const InputError& e) {
    fmt::print(out, "free-floating frequencies: left out, the WAMIT files are not readable ({})\n", e.what());
    return;
  }
  const struct {
    const char* name;
    double period_s, limit;
    const char* why;
  } decays[] = {
      {"surge", 125.46, 0.03, "our quasi-static catenary vs MAP++ (+1.0 % in `modes`); 3 % keeps twice the measured +1.3 %"},
      {"heave", 30.82, 0.01, "measured −0.13 %; a wrong mass or added mass moves it 5–30 %"},
      {"pitch", 29.49, 0.01, "measured −0.26 %; a wrong mass or added mass moves it 5–30 %"},
      {"yaw", 8.244, 0.01, "measured −0.05 %; a wrong inertia moves it 5–30 %"}};
  for (const auto& d : decays) {
    const double f = nearest_frequency(r, 1.0 / d.period_s);
    fmt::print(out, "free-floating {}: screened {:.5g} s, OpenFAST free decay {:.5g} s\n", d.name, 1.0 / f, d.period_s);
    rows.push_back(within(fmt::format("OC3 free-floating {} frequency vs OpenFAST free decay: rel. diff", d.name),
                          f * d.period_s - 1.0, d.limit, std::string("openfast-runs/oc3_free_decay; ") + d.why));
  }
}

// The static balance against our steady time domain above rated (coupled_turbine_tests.cpp, mean
// of 200–250 s) and the published steady rotor speeds below rated (PUBLISHED.md, welib NREL5MW_Oper).
void operating_points(std::FILE* out, std::vector<VerificationRow>& rows) {
  const auto deck = input("oc3_hywind/turbine_steady_15mps.yaml");
  for (const auto& [wind, pitch] : {std::pair{15.0, 10.33}, std::pair{20.0, 17.29}}) {
    const ScreeningResult r = screen_floating(deck, {fmt::format("wind.speed_m_s={}", wind)});
    fmt::print(out, "{:g} m/s: {} pitch {:.4f}° (time domain {:.2f}°)\n", wind, r.operating_point.region, r.operating_point.pitch_deg, pitch);
    rows.push_back(within(fmt::format("operating point at {:g} m/s: pitch − our steady time domain [deg]", wind),
                          r.operating_point.region == "region 3" ? r.operating_point.pitch_deg - pitch : NAN, 0.15,
                          "coupled_turbine_tests.cpp steady means; 3× the measured 0.05° (the TD's slow settling)"));
  }
  for (const auto& [wind, rpm] : {std::pair{5.0, 7.50}, std::pair{9.0, 10.26}, std::pair{11.0, 11.87}}) {
    const ScreeningResult r = screen_floating(deck, {fmt::format("wind.speed_m_s={}", wind)});
    fmt::print(out, "{:g} m/s: {} rotor {:.4f} rpm (published {:.2f})\n", wind, r.operating_point.region, r.operating_point.rotor_speed_rpm, rpm);
    rows.push_back(within(fmt::format("operating point at {:g} m/s: rotor speed vs published: rel. diff", wind),
                          r.operating_point.region == "region 2" ? r.operating_point.rotor_speed_rpm / rpm - 1.0 : NAN, 0.01,
                          "PUBLISHED.md / welib NREL5MW_Oper.csv; the sources' 1–2 % spread, 10× the measured 0.1 %"));
  }
}

// Steady 18 m/s and JONSWAP Hs 4 m Tp 10 s, the Morison deck: the time domain from the screening's
// operating point, 300 s of transient and one 300-s period of the periodic sea, whose variance is
// then the spectrum's (no sampling scatter).
void fd_against_td(std::FILE* out, std::vector<VerificationRow>& rows) {
  const auto deck = input("oc3_hywind/turbine_steady_15mps.yaml");
  const std::vector<std::string> sea = {"wind.speed_m_s=18",
                                        "waves={model: jonswap, hs_m: 4.0, tp_s: 10.0, seed: 7, duration_s: 300.0, dt_s: 0.25, depth_m: 320.0}"};
  const ScreeningResult fd = screen_floating(deck, sea);
  const ScreeningOperatingPoint& op = fd.operating_point;
  const auto dir = std::filesystem::temp_directory_path() / "fowtsim-verify" / "screening";
  std::filesystem::create_directories(dir);
  RunRequest request;
  request.deck_path = deck;
  request.output_base = dir / "td";
  request.output_format = "out";
  request.deck_settings = sea;
  for (const std::string& s : time_domain_settings(op, 600.0)) request.deck_settings.push_back(s);
  run_scene(request, nullptr);
  const io::ChannelTable t = io::read_channels(dir / "td.out");
  const struct {
    const char* channel;
    double limit;
    const char* why;
  } bounds[] = {{"PtfmHeave", 0.15, "measured 0.919: the TD's Morison loads at the displaced pose and exact hydrostatics (WAMIT deck: 0.999)"},
                {"PtfmPitch", 0.04, "measured 0.997; 4 % is the linearisation's drag and second-order residue"},
                {"TwrBsMyt", 0.04, "measured 1.002; 4 % is the linearisation's drag and second-order residue"}};
  for (const auto& b : bounds) {
    const double td = std_after(t, b.channel, 300.0), ratio = fd.std_total[channel(fd, b.channel)] / td;
    fmt::print(out, "18 m/s, Hs 4 m, Tp 10 s, Morison: {} std FD {:.5g}, TD {:.5g}, FD/TD {:.4f}\n", b.channel,
               fd.std_total[channel(fd, b.channel)], td, ratio);
    rows.push_back(within(fmt::format("FD/TD std of {} in a periodic JONSWAP sea (Morison deck): |ratio − 1|", b.channel), ratio - 1.0,
                          b.limit, std::string("screening_tests.cpp; ") + b.why));
  }
}

// The target: one screening case of the OC3 turbine under 100 ms (printed: wall time on a
// shared machine is no pass/fail criterion). The best of three, as a benchmark takes it.
void timing(std::FILE* out) {
  for (const char* deck : {"oc3_hywind/turbine_ntm_12mps_irregular.yaml", "oc3_hywind/turbine_steady_15mps.yaml"}) {
    double best = INFINITY;
    ScreeningResult r;
    for (int k = 0; k < 3; ++k) {
      r = screen_floating(input(deck));
      best = std::min(best, r.seconds_total());
    }
    fmt::print(out, "time per screening case, {}: {:.1f} ms (best of 3; issue 25's target 100 ms)\n", deck, 1e3 * best);
  }
}

}  // namespace

std::vector<VerificationRow> verify_screening(std::FILE* out) {
  std::vector<VerificationRow> rows;
  free_floating(out, rows);
  operating_points(out, rows);
  fd_against_td(out, rows);
  timing(out);
  return rows;
}

}  // namespace fowtsim::driver
