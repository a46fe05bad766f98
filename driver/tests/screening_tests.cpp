// `fowtsim screen` (issue 25, "Beyond the seed"): the frequency-domain screening of a floating
// turbine deck against what the project already matches — the OC3-Hywind free-decay periods of
// OpenFAST, the steady operating points of our own time domain — and against our own time-domain
// run of the same deck in an irregular sea.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <numeric>
#include <sstream>

#include <fmt/format.h>

#include <catch2/catch.hpp>

#include "cli/screen_command.hpp"
#include "fowtsim/post/statistics.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"
#include "scenes/floating_modes.hpp"
#include "scenes/floating_screening.hpp"
#include "scenes/screening_inputs.hpp"
#include "fowtsim/wind/iec_turbulence.hpp"
#include "fowtsim/wind/turbulence_generator.hpp"
#include "sweep/case_expansion.hpp"
#include "sweep/frequency_domain_screening.hpp"
#include "sweep/sweep_spec.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

// The mode nearest `frequency_hz`.
const ScreeningMode& nearest(const ScreeningResult& r, double frequency_hz) {
  REQUIRE(!r.modes.empty());
  return *std::min_element(r.modes.begin(), r.modes.end(), [&](const ScreeningMode& a, const ScreeningMode& b) {
    return std::abs(a.frequency_hz - frequency_hz) < std::abs(b.frequency_hz - frequency_hz);
  });
}

std::size_t channel(const ScreeningResult& r, const std::string& name) {
  const auto it = std::find(r.outputs.begin(), r.outputs.end(), name);
  REQUIRE(it != r.outputs.end());
  return static_cast<std::size_t>(it - r.outputs.begin());
}

// Population standard deviation of a channel over t ≥ from (fowtsim/post's statistics).
double std_after(const io::ChannelTable& t, const std::string& name, double from) {
  const auto c = t.find(name);
  REQUIRE(c);
  const post::RowRange rows = post::rows_in_window(t.time(), post::TimeWindow{from, t.time().back()});
  const std::span<const double> time(t.time().data() + rows.first, rows.size()), x(t.columns[*c].data() + rows.first, rows.size());
  return post::channel_statistics(time, x).std;
}

}  // namespace

TEST_CASE("screening: OC3-Hywind's free-floating frequencies against OpenFAST's free-decay periods", "[verification][screening]") {
  (void)testing::shared_dir_or_skip();  // the WAMIT files live beside the reference data
  // Parked, still water, no aerodynamics: the deck of OpenFAST's free-decay runs
  // (openfast-runs/oc3_free_decay/README.md: surge 125.46 s, heave 30.82 s, pitch 29.49 s, yaw 8.244 s
  // by up-crossings), with WAMIT's A(ω) and B(ω) at each mode's own frequency.
  const ScreeningResult r = screen_floating(testing::source_dir() / "inputs/oc3_hywind/free_decay_pitch_wamit.yaml");
  CHECK(r.operating_point.region == "parked");
  // Measured in frequency: heave −0.13 %, pitch −0.26 %, yaw −0.05 % (the decays' damped periods
  // by up-crossings against the linear model's |λ|): 1 % keeps 4× the largest and tells a wrong
  // mass or added mass apart (either moves a period by 5–30 %). Surge +1.3 %: our quasi-static
  // catenary's stiffness at the static pose against MAP++'s over the decay's 20 m (modes_tests.cpp
  // measures the same +1.0 % at the undisplaced pose); 3 % keeps twice it.
  CHECK(nearest(r, 1.0 / 125.46).frequency_hz == Approx(1.0 / 125.46).epsilon(0.03));
  CHECK(nearest(r, 1.0 / 30.82).frequency_hz == Approx(1.0 / 30.82).epsilon(0.01));
  CHECK(nearest(r, 1.0 / 29.49).frequency_hz == Approx(1.0 / 29.49).epsilon(0.01));
  CHECK(nearest(r, 1.0 / 8.244).frequency_hz == Approx(1.0 / 8.244).epsilon(0.01));
  // At rest with linear and radiation damping every mode decays or is neutral.
  for (const ScreeningMode& m : r.modes) CHECK(m.damping_ratio >= -1e-6);
}

TEST_CASE("screening: the static balance finds the steady operating points of the time domain", "[verification][screening]") {
  const auto deck = testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml";
  // Our time domain in the same steady wind (coupled_turbine_tests.cpp, 250 s, mean of the last
  // 50 s): pitch 10.33° at 15 m/s, 17.29° at 20 m/s, rotor at the PI's reference 12.1 rpm.
  const struct {
    double wind, pitch_deg;
  } points[] = {{15.0, 10.33}, {20.0, 17.29}};
  for (const auto& p : points) {
    const ScreeningResult r = screen_floating(deck, {fmt::format("wind.speed_m_s={}", p.wind)});
    INFO(p.wind << " m/s: pitch " << r.operating_point.pitch_deg << "°");
    CHECK(r.operating_point.region == "region 3");
    // Measured −0.05° and +0.01°: the time domain's mean still carries its slow settling (its rotor
    // 0.6 % above the reference). 0.15° is three times the larger.
    CHECK(std::abs(r.operating_point.pitch_deg - p.pitch_deg) < 0.15);
    // The PI's reference speed PC_RefSpd = 122.9096 rad/s over the gearbox 97, exactly.
    CHECK(r.operating_point.rotor_speed_rpm == Approx(122.9096 / 97.0 * 30.0 / std::numbers::pi).epsilon(1e-9));
  }
  // Below rated: the torque schedule meets the aerodynamic torque at pitch 0. The published
  // steady rotor speeds (PUBLISHED.md, welib NREL5MW_Oper.csv: 7.50, 10.26, 11.87 rpm at 5, 9,
  // 11 m/s; land-based): measured +0.04 %, +0.1 %, 0.0 % on the spar (its 1–5° tilt). 1 % is the
  // spread of the published sources (1–2 %) and 10× the largest.
  const struct {
    double wind, rpm;
  } below[] = {{5.0, 7.50}, {9.0, 10.26}, {11.0, 11.87}};
  for (const auto& p : below) {
    const ScreeningResult r = screen_floating(deck, {fmt::format("wind.speed_m_s={}", p.wind)});
    INFO(p.wind << " m/s: " << r.operating_point.rotor_speed_rpm << " rpm");
    CHECK(r.operating_point.region == "region 2");
    CHECK(r.operating_point.rotor_speed_rpm == Approx(p.rpm).epsilon(0.01));
    CHECK(r.operating_point.pitch_deg == 0.0);
  }
}

namespace {

struct Bound {
  const char* channel;
  double tolerance;  // on |FD/TD − 1|
};

// The deck (with `extra` settings) in steady 18 m/s (region 3) and JONSWAP Hs 4 m, Tp 10 s: the
// waves' part alone, whose time-domain variance over one full period of the periodic record
// (deterministic amplitudes √(2SΔω)) is the spectrum's, so that the comparison carries no sampling
// scatter. The time domain starts at the screening's operating point, runs 300 s of transient and
// one 300-s period of the sea.
void compare_in_waves(const std::filesystem::path& deck, const std::string& scratch, const std::vector<Bound>& bounds) {
  const auto dir = testing::scratch_dir(scratch);
  const std::vector<std::string> sea = {"wind.speed_m_s=18",
                                        "waves={model: jonswap, hs_m: 4.0, tp_s: 10.0, seed: 7, duration_s: 300.0, dt_s: 0.25, depth_m: 320.0}"};
  const ScreeningResult fd = screen_floating(deck, sea);
  REQUIRE(fd.operating_point.region == "region 3");
  RunRequest request = run_request(deck, dir / "td");
  request.deck_settings = sea;
  const ScreeningOperatingPoint& op = fd.operating_point;
  for (const std::string& s : time_domain_settings(op, 600.0)) request.deck_settings.push_back(s);
  run_scene(request, nullptr);
  const io::ChannelTable t = io::read_channels(dir / "td.out");
  for (const Bound& b : bounds) {
    const double td = std_after(t, b.channel, 300.0);
    const double ratio = fd.std_total[channel(fd, b.channel)] / td;
    INFO(deck.filename().string() << " " << b.channel << ": FD " << fd.std_total[channel(fd, b.channel)] << ", TD " << td << ", FD/TD " << ratio);
    CHECK(std::abs(ratio - 1.0) < b.tolerance);
  }
}

}  // namespace

TEST_CASE("screening: standard deviations in an irregular sea against our own time domain, WAMIT", "[verification][screening]") {
  (void)testing::shared_dir_or_skip();  // the WAMIT files live beside the reference data
  // The same deck with OpenFAST's hydrodynamics (hydro_potential_flow.yaml: WAMIT radiation and
  // excitation, linear hydrostatics, drag-only members). Measured FD/TD: PtfmHeave 0.999, PtfmPitch
  // 1.012, TwrBsMyt 1.013 — what the linear model leaves out: the quadratic drag (linearised), the
  // radiation memory's 60-s window, the rotor's periodic loads. 4 % keeps 3× the largest; a lost
  // excitation, radiation or aerodynamic damping term moves them by 10–100 %.
  const auto deck = testing::scratch_dir("screening_wamit_deck") / "wamit.yaml";
  std::ofstream(deck) << "include: [" << (testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml").string() << ", "
                      << (testing::source_dir() / "inputs/oc3_hywind/hydro_potential_flow.yaml").string() << "]\n";
  compare_in_waves(deck, "screening_td_wamit", {{"PtfmHeave", 0.04}, {"PtfmPitch", 0.04}, {"TwrBsMyt", 0.04}});
}

TEST_CASE("screening: standard deviations in an irregular sea against our own time domain, Morison", "[verification][screening]") {
  // The shipped Morison deck (hydro.yaml: Ca 1, exact hydrostatics). Measured FD/TD: PtfmPitch
  // 0.997, TwrBsMyt 1.002 (4 %, as with WAMIT). PtfmHeave 0.919: the time domain's Morison heave is
  // 8 % above the linear one while the linear Morison excitation equals WAMIT's within 0.3 % at
  // Tp (and WAMIT's FD and TD heave agree within 0.1 %): the time domain's loads at the displaced,
  // pitched pose and its exact hydrostatics; 15 % keeps twice that.
  compare_in_waves(testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml", "screening_td_morison",
                   {{"PtfmHeave", 0.15}, {"PtfmPitch", 0.04}, {"TwrBsMyt", 0.04}});
}

TEST_CASE("screening: the OC3 controller detuning gives the platform-pitch mode its damping back", "[verification][screening]") {
  // Jonkman, NREL/TP-500-47266 §7 (and Larsen & Hanson 2007): on OC3-Hywind the land-based pitch
  // gains (PC_KP 0.01882681 s, PC_KI 0.008068634) put the pitch-to-feather loop above the
  // platform-pitch frequency, where its negative thrust slope takes the mode's damping; constant
  // power above rated takes more. The OC3 deck's detuned gains and constant torque restore it.
  const auto deck = testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml";
  auto pitch_mode_damping = [&](std::vector<std::string> settings) {
    settings.insert(settings.begin(), "wind.speed_m_s=18");
    const ScreeningResult r = screen_floating(deck, settings);
    const auto pitch = static_cast<Eigen::Index>(
        std::find(r.coordinates.begin(), r.coordinates.end(), "PtfmPitch") - r.coordinates.begin());
    REQUIRE(pitch < static_cast<Eigen::Index>(r.coordinates.size()));
    // The platform-pitch mode: the mode between 0.025 and 0.04 Hz with the largest pitch entry (the
    // heave and roll modes of the spar lie there too).
    const ScreeningMode* best = nullptr;
    for (const ScreeningMode& m : r.modes)
      if (m.frequency_hz > 0.025 && m.frequency_hz < 0.04 && (!best || std::abs(m.shape[pitch]) > std::abs(best->shape[pitch])))
        best = &m;
    REQUIRE(best);
    return best->damping_ratio;
  };
  const double detuned = pitch_mode_damping({});
  const double land_gains = pitch_mode_damping({"controller.proportional_gain_s=0.01882681", "controller.integral_gain=0.008068634"});
  const double land_power = pitch_mode_damping({"controller.proportional_gain_s=0.01882681", "controller.integral_gain=0.008068634",
                                                "controller.region3_torque=constant_power"});
  INFO("platform-pitch damping: detuned " << detuned << ", land-based gains " << land_gains << ", and constant power " << land_power);
  // Measured: +0.083, +0.005, −0.011 (the ordering and the sign are the published finding; the
  // values are our BEM's and hydrodynamics').
  CHECK(detuned > 0.05);
  CHECK(land_gains < 0.5 * detuned);
  CHECK(land_power < 0.0);
}

TEST_CASE("screening: the flexible tower's modes are those of `fowtsim modes`, damped by the rotor", "[verification][screening]") {
  // The screening linearises the same scene as `fowtsim modes` (FloatingScene::linearised_system),
  // here about the 15-m/s operating point instead of the deck's initial state: the tower's first
  // fore-aft and side-side modes (0.4782 / 0.4865 Hz by `modes`) measured −0.3 % and −0.1 % (the
  // thrust-loaded pose, the closed loop). 1 % keeps 3× the larger. Their damping: the 1 % of the
  // deck's structure (TwrFADmp) plus the rotor's aerodynamic damping fore-aft (measured 4.7 %).
  const auto deck = testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml";
  const std::vector<std::string> flexible = {"structure.tower.flexible=true"};
  const ModesResult modes = floating_modes(deck, flexible);
  const ScreeningResult r = screen_floating(deck, flexible);
  auto first = [](const auto& list, const char* name) {
    const auto it = std::find_if(list.begin(), list.end(), [&](const auto& m) { return m.dominant == name && m.damping_ratio < 0.5; });
    REQUIRE(it != list.end());
    return *it;
  };
  CHECK(first(r.modes, "TwFADOF1").frequency_hz == Approx(first(modes.modes, "TwFADOF1").frequency_hz).epsilon(0.01));
  CHECK(first(r.modes, "TwSSDOF1").frequency_hz == Approx(first(modes.modes, "TwSSDOF1").frequency_hz).epsilon(0.01));
  CHECK(first(r.modes, "TwFADOF1").damping_ratio > 0.02);
}

TEST_CASE("screening: the rotor-effective wind spectrum against the disk average of our turbulence fields", "[verification][screening]") {
  // The FD's rotor-effective spectrum (Kaimal u × the disk-averaged IEC coherence, an equal-area
  // polar grid) against the same average taken over the grid points inside the rotor disk of
  // fields the wind module generates (its own coherent synthesis, IEC 61400-1 Annex B): the ratio
  // of the band power 0.01–0.3 Hz of the disk average to that of a single point.
  wind::WindParams w;
  w.model = wind::WindModel::turbulent;
  w.speed_m_s = 12.0;
  w.reference_height_m = 90.0;
  w.turbulence.ny = w.turbulence.nz = 15;
  w.turbulence.width_m = w.turbulence.height_m = 126.0;  // 9-m spacing over the rotor's diameter
  w.turbulence.dt_s = 0.25;
  w.turbulence.duration_s = 600.0;
  w.turbulence.tower_points = false;
  // The band stops where the coherence length U/(12 f) reaches the grid's 9-m spacing (above, the
  // grid's 150 points average less than the continuous disk).
  const double radius = 63.0, f_low = 0.01, f_high = 0.1;  // [m], [Hz]
  const RotorEffectiveWind rotor(w, 90.0, radius);
  // FD: the mean over the record's frequencies k/600 Hz in the band of S_Ueff/S_u, the disk's
  // coherence factor.
  const wind::KaimalModel kaimal = wind::kaimal_model(w.turbulence, w.speed_m_s, 90.0);
  std::vector<int> band;
  for (int k = 1; k / 600.0 <= f_high; ++k)
    if (k / 600.0 >= f_low) band.push_back(k);
  double fd_ratio = 0.0;
  for (const int k : band) fd_ratio += rotor.spectrum_hz(k / 600.0) / kaimal.spectrum(0, k / 600.0) / static_cast<double>(band.size());
  // The fields: at each of those frequencies the periodogram of the disk average over that of
  // single points (every 7th of the disk's), averaged over the band's 55 frequencies and six seeds.
  double td_ratio = 0.0;
  const std::uint64_t seeds[] = {11u, 12u, 13u, 14u, 15u, 16u};
  for (const std::uint64_t seed : seeds) {
    w.turbulence.seed = seed;
    const wind::GeneratedTurbulence g = wind::generate_turbulence(w);
    const wind::FullField& field = g.field;
    // The disk's points and their u series, means removed.
    std::vector<std::vector<double>> series;
    for (int iz = 0; iz < field.nz; ++iz)
      for (int iy = 0; iy < field.ny; ++iy) {
        const double y = (iy - 0.5 * (field.ny - 1)) * field.dy_m, z = field.z_bottom_m + iz * field.dz_m - 90.0;
        if (y * y + z * z > radius * radius) continue;
        std::vector<double> u(static_cast<std::size_t>(field.nt));
        for (int it = 0; it < field.nt; ++it)
          u[static_cast<std::size_t>(it)] = field.grid[static_cast<std::size_t>(((it * field.nz + iz) * field.ny + iy) * 3)];
        const double mean = std::accumulate(u.begin(), u.end(), 0.0) / static_cast<double>(u.size());
        for (double& x : u) x -= mean;
        series.push_back(std::move(u));
      }
    std::vector<double> average(static_cast<std::size_t>(field.nt), 0.0);
    for (const auto& u : series)
      for (std::size_t i = 0; i < u.size(); ++i) average[i] += u[i] / static_cast<double>(series.size());
    // The periodogram at k/600 Hz by a direct DFT (the field is periodic over its 600 s).
    auto power = [&](const std::vector<double>& x, int k) {
      std::complex<double> sum = 0.0;
      for (std::size_t i = 0; i < x.size(); ++i)
        sum += x[i] * std::polar(1.0, -2.0 * std::numbers::pi * k * static_cast<double>(i) / static_cast<double>(x.size()));
      return std::norm(sum);
    };
    for (const int k : band) {
      double point = 0.0;
      int points = 0;
      for (std::size_t p = 0; p < series.size(); p += 7, ++points) point += power(series[p], k);
      td_ratio += power(average, k) / (point / points) / static_cast<double>(band.size() * std::size(seeds));
    }
  }
  INFO("disk/point spectral ratio over the band: FD " << fd_ratio << ", generated fields " << td_ratio);
  // Measured: FD 0.1464, fields 0.1474 (seeds 11–16) and 0.1621 (seeds 21–26): the sampling
  // scatter of six seeds is ≈ 7 %; 15 % keeps twice it, and no coherence averaging (ratio 1) or a
  // fully coherent disk is far out.
  CHECK(fd_ratio == Approx(td_ratio).epsilon(0.15));
  CHECK(fd_ratio < 0.8);
}

TEST_CASE("screening: decks it cannot linearise are refused with the reason", "[unit][screening]") {
  CHECK_THROWS_AS(screen_floating(testing::source_dir() / "inputs/oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml"), InputError);
  // A regular wave has no spectrum to screen.
  CHECK_THROWS_AS(screen_floating(testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml",
                                  {"waves={model: regular, height_m: 2.0, period_s: 10.0}"}),
                  InputError);
  std::FILE* sink = std::tmpfile();
  CHECK_THROWS_AS(run_screen_command(testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml", {},
                                     std::filesystem::path("screen.csv"), sink),
                  InputError);
  std::fclose(sink);
}

TEST_CASE("sweep --frequency-domain ranks the cases by their screened tower-base moment", "[unit][screening]") {
  const auto dir = testing::scratch_dir("screening_sweep");
  const auto spec_path = dir / "spec.yaml";
  std::ofstream(spec_path) << "sweep:\n  name: fd_rank\n  base_deck: "
                           << (testing::source_dir() / "inputs/oc3_hywind/turbine_ntm_12mps_irregular.yaml").string()
                           << "\n  output_dir: " << (dir / "out").string() << "\n"
                           << "load_cases:\n  - name: dlc12\n    preset: dlc1.2\n    wind_speeds_m_s: [8, 18]\n    seeds: 1\n"
                           << "    sea_state: {hs_m: 2.0, tp_s: 8.0}\n"
                           << "load_table:\n  channels: [TwrBsMyt]\n";
  const sweep::SweepSpec spec = sweep::read_sweep_spec(spec_path);
  const std::vector<sweep::SweepCase> cases = sweep::expand_cases(spec, sweep::read_base_deck_facts(spec.base_deck));
  REQUIRE(cases.size() == 2);
  std::FILE* sink = std::tmpfile();
  CHECK(sweep::screen_sweep(sink, spec, cases) == 0);
  std::fclose(sink);
  // One row per case, ranked: the larger σ(TwrBsMyt) first; each the same as `fowtsim screen` of
  // its own case deck (the base deck with its keys), to the digit the table writes.
  std::ifstream csv(dir / "out/frequency_domain_screening.csv");
  std::string header, first, second;
  std::getline(csv, header);
  std::getline(csv, first);
  std::getline(csv, second);
  CHECK(header.find("std_TwrBsMyt") != std::string::npos);
  auto field = [&](const std::string& line, const std::string& name) {
    std::vector<std::string> names, values;
    std::stringstream h(header), l(line);
    for (std::string x; std::getline(h, x, ',');) names.push_back(x);
    for (std::string x; std::getline(l, x, ',');) values.push_back(x);
    const auto i = static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
    REQUIRE(i < values.size());
    return values[i];
  };
  CHECK(field(first, "rank") == "1");
  CHECK(field(second, "rank") == "2");
  CHECK(std::stod(field(first, "std_TwrBsMyt")) >= std::stod(field(second, "std_TwrBsMyt")));
  for (const std::string& row : {first, second}) {
    const auto it = std::find_if(cases.begin(), cases.end(), [&](const sweep::SweepCase& c) { return c.name == field(row, "case"); });
    REQUIRE(it != cases.end());
    std::vector<std::string> settings;
    for (const sweep::DeckOverride& o : it->overrides) settings.push_back(o.key_path + "=" + o.yaml_value);
    const ScreeningResult alone = screen_floating(spec.base_deck, settings);
    CHECK(std::stod(field(row, "std_TwrBsMyt")) == Approx(alone.std_total[channel(alone, "TwrBsMyt")]).epsilon(1e-5));
  }
}
