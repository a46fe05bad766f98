// Potential-flow hydrodynamics (issue 15): OpenFAST's OC3 WAMIT files read by modules/io, their
// radiation memory (convolution and state space) by modules/hydro and the wave excitation by the
// driver, checked against the frequency-domain tables themselves.
#include <cmath>
#include <cstdio>
#include <complex>
#include <fstream>
#include <numbers>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/hydro/potential_flow.hpp"
#include "fowtsim/hydro/radiation_kernel.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/io/wamit_input.hpp"
#include "fowtsim/testing/skip.hpp"
#include "fowtsim/waves/wave_field.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"
#include "scenes/floating_scene.hpp"
#include "scenes/sea_modules.hpp"
#include "sea/wave_excitation.hpp"

using namespace fowtsim;

TEST_CASE("the OC3 spar's WAMIT damping, as a retardation kernel, gives back its added mass (Ogilvie)",
          "[verification][hydro]") {
  // K(t) from B(ω) of Spar.1 (piecewise linear in ω, zero beyond the table), then
  // A(ω) = A(∞) − (1/ω) ∫ K sin(ωt) dt over 0 … 150 s, against the A(ω) WAMIT tabulated itself for
  // surge, heave and pitch. The table's B ends at a finite frequency and WAMIT's own A and B carry
  // its panel error, so the relation holds to a fraction of the frequency-dependent part
  // A(0) − A(∞), not to rounding. Measured over 0.3–1.8 rad/s: surge ≤ 0.13 %, heave ≤ 0.7 %,
  // pitch ≤ 1.1 % of that span (pitch at 0.3 rad/s); bound 5 %.
  const auto dir = testing::shared_dir_or_skip() / "reference/r-test/glue-codes/openfast/5MW_Baseline/HydroData";
  const io::WamitRadiation r = io::read_wamit_radiation(dir / "Spar.1", {1025.0, 9.80665, 1.0});
  std::vector<double> times;
  for (int n = 0; n <= 3000; ++n) times.push_back(0.05 * n);
  const std::vector<Mat6> kernel = hydro::retardation_kernel(r.frequencies_rad_s, r.damping, times);
  // The kernel decays: after 60 s it is below 1 % of its peak in each diagonal entry (measured
  // ≤ 5.4e-4 of it, surge).
  for (int i : {0, 2, 4}) {
    double peak = 0.0;
    for (const Mat6& k : kernel) peak = std::max(peak, std::abs(k(i, i)));
    CHECK(std::abs(kernel[1200](i, i)) < 0.01 * peak);
  }
  // K(0) = (2/π) ∫ B dω: the trapezoidal area of the piecewise-linear B (from B(0) = 0), exactly.
  for (int i : {0, 2, 4}) {
    double area = 0.5 * r.frequencies_rad_s[0] * r.damping[0](i, i);
    for (std::size_t f = 1; f < r.frequencies_rad_s.size(); ++f)
      area += 0.5 * (r.frequencies_rad_s[f] - r.frequencies_rad_s[f - 1]) * (r.damping[f](i, i) + r.damping[f - 1](i, i));
    CHECK(kernel[0](i, i) == Approx(2.0 / std::numbers::pi * area).epsilon(1e-12));  // rounding only
  }
  for (std::size_t f = 0; f < r.frequencies_rad_s.size(); f += 5) {
    const double omega = r.frequencies_rad_s[f];
    if (omega < 0.2 || omega > 2.0) continue;  // the band the spar's motions and waves live in
    const Mat6 a = hydro::added_mass_from_kernel(omega, times, kernel, *r.added_mass_infinite_frequency);
    for (int i : {0, 2, 4}) {
      const double span = std::abs((*r.added_mass_zero_frequency)(i, i) - (*r.added_mass_infinite_frequency)(i, i));
      INFO("ω = " << omega << ", mode " << i + 1 << ": " << a(i, i) << " vs WAMIT " << r.added_mass[f](i, i) << " (span "
                  << span << ")");
      CHECK(std::abs(a(i, i) - r.added_mass[f](i, i)) < 0.05 * span);
    }
  }
}

namespace {

const std::filesystem::path kHydroData = "reference/r-test/glue-codes/openfast/5MW_Baseline/HydroData";

hydro::RadiationModel oc3_radiation(hydro::RadiationMethod method, double step_s) {
  const auto dir = testing::shared_dir_or_skip() / kHydroData;
  const io::WamitRadiation r = io::read_wamit_radiation(dir / "Spar.1", {1025.0, 9.80665, 1.0});
  hydro::RadiationOptions options;
  options.method = method;
  options.step_s = step_s;
  return hydro::make_radiation_model({r.frequencies_rad_s, r.damping, *r.added_mass_infinite_frequency}, options);
}

// Drives DOF j with q̇_j = V sin(ωt) from rest through the memory's RK4-stage evaluations and
// returns the complex amplitude of the radiation load on DOF i over the last 4 periods, after 80 s
// (longer than the 60-s window), from the end-of-step samples.
std::complex<double> harmonic_radiation(const hydro::RadiationModel& model, int i, int j, double omega, double velocity) {
  const double dt = model.step_s;
  hydro::RadiationState s = hydro::make_radiation_state(model, 0.0, Vec6::Zero());
  const double period = 2.0 * std::numbers::pi / omega;
  const long start = std::lround(std::ceil(80.0 / period) * period / dt);
  const long steps = start + std::lround(4.0 * period / dt);
  std::complex<double> sum = 0.0;
  long count = 0;
  for (long n = 0; n < steps; ++n) {
    const double t1 = (n + 1) * dt;
    Vec6 v = Vec6::Zero();
    v[j] = velocity * std::sin(omega * t1);
    (void)hydro::radiation_load(model, s, s.time_s + 0.5 * dt, v);  // a stage: must leave the state alone
    hydro::advance_radiation(model, t1, v, s);
    if (n + 1 > start) {
      sum += hydro::radiation_load(model, s, t1, v)[i] * std::exp(std::complex<double>(0.0, -omega * t1));
      ++count;
    }
  }
  return 2.0 * sum / static_cast<double>(count);
}

}  // namespace

TEST_CASE("the OC3 radiation memory, driven harmonically, gives WAMIT's B(ω) and A(ω) − A(∞) (convolution and state space)",
          "[verification][hydro]") {
  // Cummins' memory integral under q̇_j = V sin ωt settles to F_i = −Re[(B_ij + iω(A_ij(ω) − A_ij(∞))) V̂ e^{iωt}] with
  // V̂ = −iV: the frequency-domain coefficients WAMIT tabulated (Spar.1), reached through the kernel
  // (cosine transform of B), the 60-s window, the trapezoidal rule at ΔT = 0.05 s or the fitted
  // state space (default tolerance 0.2 %). Error relative to |B + iω(A − A∞)| measured at
  // ω = 0.3 … 1.5 rad/s (the spar's response band): convolution ≤ 1.05 %, state space ≤ 1.1 %, both
  // largest at 0.3 rad/s in pitch. The error is systematic, WAMIT's own A and B agreeing to ≈ 1 % of
  // the span (the Ogilvie check above), not noise: bound 3 %. (A 2 % fit tolerance gave 12.5 % in
  // surge at 0.3 rad/s: the low frequencies weigh the kernel's integral, which the RMS fit spreads.)
  const auto dir = testing::shared_dir_or_skip() / kHydroData;
  const io::WamitRadiation table = io::read_wamit_radiation(dir / "Spar.1", {1025.0, 9.80665, 1.0});
  for (const hydro::RadiationMethod method : {hydro::RadiationMethod::convolution, hydro::RadiationMethod::state_space}) {
    const hydro::RadiationModel model = oc3_radiation(method, 0.05);
    for (const auto& [i, j] : {std::pair{0, 0}, std::pair{2, 2}, std::pair{4, 4}, std::pair{0, 4}}) {
      for (double omega : {0.3, 0.6, 1.0, 1.5}) {
        std::size_t f = 0;
        while (table.frequencies_rad_s[f + 1] < omega) ++f;
        const double s = (omega - table.frequencies_rad_s[f]) / (table.frequencies_rad_s[f + 1] - table.frequencies_rad_s[f]);
        const auto lerp6 = [&](const std::vector<Mat6>& m) { return (1.0 - s) * m[f](i, j) + s * m[f + 1](i, j); };
        const std::complex<double> impedance(lerp6(table.damping),
                                             omega * (lerp6(table.added_mass) - (*table.added_mass_infinite_frequency)(i, j)));
        const std::complex<double> expected = -impedance * std::complex<double>(0.0, -1.0);
        const std::complex<double> got = harmonic_radiation(model, i, j, omega, 1.0);
        INFO((method == hydro::RadiationMethod::convolution ? "convolution" : "state space")
             << ", K" << i + 1 << j + 1 << ", ω = " << omega << ": " << got << " vs " << expected);
        CHECK(std::abs(got - expected) < 0.03 * std::abs(impedance));
      }
    }
  }
}

TEST_CASE("the OC3 state-space fit: every kept kernel entry within its tolerance, stable, of modest order",
          "[verification][hydro]") {
  // Deck default tolerance 0.2 % relative RMS over the 60-s window, met with at most the default 20
  // states per entry. Measured: orders 10 (surge, sway), 8 (couplings), 7 (heave), 6 (roll, pitch),
  // errors 0.03–0.15 %; 36 complex states in all (a conjugate pair is one).
  const hydro::RadiationModel model = oc3_radiation(hydro::RadiationMethod::state_space, 0.05);
  CHECK(model.entries.size() >= 9u);  // surge, sway, heave, roll, pitch and the surge–pitch, sway–roll couplings
  std::printf("OC3 state-space radiation: %zu entries, %d complex states\n", model.entries.size(), model.term_count);
  for (const hydro::RadiationEntry& e : model.entries) {
    INFO("K" << e.row + 1 << e.col + 1 << ": order " << e.fit.order << ", error " << e.fit.relative_error);
    CHECK(e.fit.relative_error < 0.002);
    CHECK(e.fit.order <= 20);
    for (const hydro::ExponentialTerm& t : e.fit.terms) CHECK(t.pole.real() < 0.0);
  }
}

TEST_CASE("the OC3 wave excitation of a regular wave is the .3 transfer function times the wave", "[verification][hydro]") {
  // Regular wave H = 4 m, T = 10 s (ω = 0.6283 rad/s, on the WAMIT grid), heading 0 and 20°
  // (between table headings: linear in β). The precomputed records read at any time must give
  // Re[X A e^{iωt}] with A = H/2 (phase 0): interpolation in time at ≥ 8 samples per period is
  // within (9/16)/24 (2π/8)⁴ = 0.9 % of the amplitude at worst; measured 1.4e-5; bound 1 %.
  const auto dir = testing::shared_dir_or_skip() / kHydroData;
  const io::WamitExcitation table = io::read_wamit_excitation(dir / "Spar.3", {1025.0, 9.80665, 1.0});
  for (double heading : {0.0, 20.0}) {
    waves::WaveParams p;
    p.model = waves::WaveModel::regular;
    p.height_m = 4.0;
    p.period_s = 10.0;
    p.dt_s = 0.25;
    p.heading_deg = heading;
    const waves::WaveField field(p);
    const driver::WaveExcitation excitation(field, table);
    const double omega = 2.0 * std::numbers::pi / 10.0;
    for (int dof : {0, 1, 2, 4}) {
      const std::complex<double> x = driver::excitation_transfer(table, dof, omega, heading);
      double worst = 0.0;
      for (double t = 0.0; t < 20.0; t += 0.37)
        worst = std::max(worst, std::abs(excitation.at(t)[dof] - (x * 2.0 * std::exp(std::complex<double>(0.0, omega * t))).real()));
      INFO("heading " << heading << "°, DOF " << dof + 1 << ": |X| = " << std::abs(x) << ", worst error " << worst);
      CHECK(worst <= 0.01 * 2.0 * std::abs(x) + 1e-9);
    }
  }
  // Heading 0: surge leads the elevation by 90° (inertia ∝ fluid acceleration), heave is in phase
  // at long waves (hydrostatic pressure): WAMIT's e^{iωt} convention is the wave field's.
  CHECK(std::arg(driver::excitation_transfer(table, 0, 0.1, 0.0)) == Approx(std::numbers::pi / 2).margin(0.01));
  CHECK(std::abs(std::arg(driver::excitation_transfer(table, 2, 0.1, 0.0))) < 0.01);
}

TEST_CASE("bad potential-flow input stops before anything is written, naming the deck line", "[unit][hydro]") {
  const auto dir = testing::scratch_dir("potential_flow_bad_input");
  const auto deck = testing::source_dir() / "inputs/oc3_hywind/free_decay_pitch.yaml";
  const auto expect_error = [&](const std::string& name, const std::string& overrides, const std::string& needle) {
    std::ofstream(dir / (name + ".yaml")) << "include: [" << deck.string() << "]\n" << overrides;
    const auto base = dir / name;
    try {
      driver::run_scene(driver::run_request(dir / (name + ".yaml"), base), nullptr);
      FAIL("no error for " << name);
    } catch (const InputError& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(needle) != std::string::npos);
      CHECK(std::string(e.what()).find(name + ".yaml:") != std::string::npos);  // file:line of the key
    }
    CHECK_FALSE(std::filesystem::exists(base.string() + ".out"));
  };
  expect_error("missing_wamit", "hydro: {potential_flow: {wamit_root: no/such/Spar}}\n", "Spar.1");
  expect_error("linear_without_wamit", "hydro: {hydrostatics: linear, displaced_volume_m3: 8029.21}\n", "potential_flow");
  expect_error("short_window", "hydro: {potential_flow: {wamit_root: no/such/Spar, radiation_window_s: 0.04}}\n",
               "radiation_window_s");
}

TEST_CASE("OC3 heave in regular waves with WAMIT potential flow follows the frequency-domain RAO", "[verification][hydro]") {
  // The whole time-domain chain — .3 excitation, A(∞) in the mass matrix, the radiation
  // convolution, linear .hst hydrostatics, the multibody and the mooring — against the
  // frequency-domain response of the heave DOF, which symmetry decouples from the others:
  //   ζ₃/a = X₃(ω) / (C33 + K33 − ω²(M + A33(ω)) + iω(B33(ω) + B_add)),
  // M = 8,066,048 kg (platform, tower, nacelle, rotor), C33 from Spar.hst, K33 the catenary's
  // linearised stiffness at rest, B_add = 1.3e5 N·s/m (the deck's AddBLin). Regular waves, 1 m
  // amplitude, 400 s; amplitude and phase by projection on e^{iωt} over the whole wave periods of
  // the last 200 s (the heave transient at 0.204 rad/s, damped by ζ ≈ 0.04, leaks < 1 % into it).
  // Measured |error| / |RAO|: 1.0 % at 0.3 rad/s (closest to the heave resonance: the transient's
  // leakage), 0.14 % at 0.5 and 0.7 rad/s; bound 3 % (the leakage, ≈ 1 %, is systematic, not noise).
  const auto dir = testing::shared_dir_or_skip() / kHydroData;
  const io::WamitRadiation r = io::read_wamit_radiation(dir / "Spar.1", {1025.0, 9.80665, 1.0});
  const io::WamitExcitation x = io::read_wamit_excitation(dir / "Spar.3", {1025.0, 9.80665, 1.0});
  const Mat6 c = io::read_wamit_hydrostatics(dir / "Spar.hst", {1025.0, 9.80665, 1.0});
  const auto scratch = testing::scratch_dir("potential_flow_heave_rao");
  for (double omega : {0.3, 0.5, 0.7}) {
    const double period = 2.0 * std::numbers::pi / omega;
    const auto deck = scratch / fmt::format("rao_{}.yaml", omega);
    std::ofstream(deck) << "include: [" << (testing::source_dir() / "inputs/oc3_hywind/structure.yaml").string() << ", "
                        << (testing::source_dir() / "inputs/oc3_hywind/hydro_potential_flow.yaml").string() << ", "
                        << (testing::source_dir() / "inputs/oc3_hywind/mooring.yaml").string() << "]\n"
                        << "simulation: {t_max_s: 400.0, dt_s: 0.05}\noutput: {format: out, decimation: 2}\n"
                        << fmt::format("waves: {{model: regular, height_m: 2.0, period_s: {:.12g}, depth_m: 320.0}}\n", period);
    const io::ChannelTable out = [&] {
      driver::run_scene(driver::run_request(deck, scratch / fmt::format("rao_{}", omega)), nullptr);
      return io::read_channels(scratch / fmt::format("rao_{}.out", omega));
    }();
    // Mooring heave stiffness at rest, from the same deck.
    const io::ValidatedDeck validated = io::read_deck(driver::floating_scene_schema(), deck);
    const double k33 = driver::SeaModules(validated, FrameMotion{}, 0.05).mooring_stiffness(FrameMotion{})(2, 2);
    std::size_t f = 0;
    while (std::abs(r.frequencies_rad_s[f] - omega) > 1e-4) ++f;  // on the WAMIT grid (to its 6 printed digits)
    const double mass = 8066048.0;
    const std::complex<double> impedance(c(2, 2) + k33 - omega * omega * (mass + r.added_mass[f](2, 2)),
                                         omega * (r.damping[f](2, 2) + 1.3e5));
    const std::complex<double> expected = driver::excitation_transfer(x, 2, omega, 0.0) / impedance;
    const std::vector<double>& t = out.time();
    const auto& heave = out.columns[out.find("PtfmHeave").value()];
    const auto& eta = out.columns[out.find("Wave1Elev").value()];
    const double t0 = 400.0 - std::floor(200.0 / period) * period;
    std::complex<double> z = 0.0, e = 0.0;
    double mean = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i] >= t0) mean += heave[i], ++n;
    mean /= static_cast<double>(n);
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i] >= t0) {
        const std::complex<double> w = std::exp(std::complex<double>(0.0, -omega * t[i]));
        z += (heave[i] - mean) * w;
        e += eta[i] * w;
      }
    const std::complex<double> rao = z / e;  // per unit wave amplitude, phase relative to η at the origin
    INFO("ω = " << omega << " rad/s: RAO " << rao << " vs frequency domain " << expected << ", |error|/|RAO| "
                << std::abs(rao - expected) / std::abs(expected));
    CHECK(std::abs(rao - expected) < 0.03 * std::abs(expected));
  }
}

TEST_CASE("a radiation window that cuts the kernels short, or a state-space fit that misses its tolerance, is warned about",
          "[verification][hydro]") {
  (void)testing::shared_dir_or_skip();
  const auto dir = testing::scratch_dir("potential_flow_warnings");
  const auto deck = testing::source_dir() / "inputs/oc3_hywind/free_decay_pitch_wamit.yaml";
  const auto warnings_of = [&](const std::string& name, const std::string& overrides) {
    std::ofstream(dir / (name + ".yaml")) << "include: [" << deck.string() << "]\nsimulation: {t_max_s: 1.0}\n" << overrides;
    return driver::run_scene(driver::run_request(dir / (name + ".yaml"), dir / name), nullptr).warnings;
  };
  const auto mentions = [](const std::vector<std::string>& list, const std::string& what) {
    for (const std::string& w : list)
      if (w.find(what) != std::string::npos) return true;
    return false;
  };
  // The deck's own 60 s window and 0.2 % fit: no warning (OC3 kernels decay to < 1e-3 of their peak).
  CHECK_FALSE(mentions(warnings_of("as_deck", "hydro: {potential_flow: {radiation: state_space}}\n"), "radiation kernel"));
  // 10 s: the kernels are still 2.7–6.6 % of their peaks there (measured), above the 1 % warning.
  CHECK(mentions(warnings_of("short", "hydro: {potential_flow: {radiation_window_s: 10}}\n"), "radiation_window_s"));
  // Order ≤ 3 cannot reach 1e-6 (measured 3.7–7.7 % at order 3).
  CHECK(mentions(warnings_of("tight", "hydro: {potential_flow: {radiation: state_space, state_space_tolerance: 1e-6, "
                                      "state_space_max_order: 3}}\n"),
                 "state_space_max_order"));
}
