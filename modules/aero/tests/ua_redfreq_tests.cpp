// The HGM model against a published reference loop: OpenFAST's UnsteadyAero driver on its r-test
// case modules/unsteadyaero/ua_redfreq/UA3 (OpenFAST/r-test, UA3.dvr and UA3.out of 14-Feb-2023):
// DU21_A17, chord 3.5 m, 40 m/s, α = 7.5° ± 2° at 1 Hz (k = ωc/2U = 0.275), 60 steps, one cycle
// from the steady start, UA_Mod 3 (Beddoes–Leishman as Minnema/Pierce: the model OpenFAST's OC3 deck
// runs). The driver pitches about the half chord: its "Alpha" at the ¼ chord is the pitch angle less
// ω c/(4U), and "Vrel" carries the ¼-chord point's motion; both are read as the inputs here, with ω
// = 2π · 2° · cos 2πt. Columns transcribed (numbers only): time, Alpha, Vrel, Cl, Cm.
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/aero/unsteady_airfoil.hpp"
#include "nrel5mw_deck.hpp"

using namespace fowtsim;
using namespace fowtsim::aero;

namespace {

struct Row {
  double t, alpha_deg, vrel, cl, cm;
};

// UA3.out, every row from t = 1/60 s (the t = 0 row is the driver's start-up value, not a step).
constexpr Row kUa3[] = {
    {0.016667, 7.43797, 40.0260, 1.25584, -0.131642}, {0.033333, 7.64933, 40.0263, 1.25769, -0.132705},
    {0.050000, 7.85905, 40.0262, 1.26216, -0.133815}, {0.066667, 8.06483, 40.0257, 1.26897, -0.134915},
    {0.083333, 8.26441, 40.0249, 1.27774, -0.135934}, {0.100000, 8.45560, 40.0237, 1.28811, -0.136817},
    {0.116667, 8.63629, 40.0222, 1.29973, -0.137524}, {0.133333, 8.80452, 40.0203, 1.31230, -0.138029},
    {0.150000, 8.95843, 40.0180, 1.32550, -0.138319}, {0.166667, 9.09633, 40.0155, 1.33907, -0.138343},
    {0.183333, 9.21673, 40.0127, 1.35275, -0.137928}, {0.200000, 9.31829, 40.0097, 1.36629, -0.137275},
    {0.216667, 9.39991, 40.0066, 1.37947, -0.136400}, {0.233333, 9.46070, 40.0033, 1.39208, -0.135322},
    {0.250000, 9.50000, 40.0000, 1.40391, -0.134063}, {0.266667, 9.51738, 39.9967, 1.41480, -0.132757},
    {0.283333, 9.51266, 39.9935, 1.42449, -0.131335}, {0.300000, 9.48590, 39.9904, 1.43247, -0.129664},
    {0.316667, 9.43739, 39.9874, 1.43850, -0.128018}, {0.333333, 9.36766, 39.9847, 1.44250, -0.126347},
    {0.350000, 9.27750, 39.9823, 1.44443, -0.124655}, {0.366667, 9.16788, 39.9801, 1.44434, -0.122961},
    {0.383333, 9.04001, 39.9783, 1.44234, -0.121285}, {0.400000, 8.89529, 39.9769, 1.43852, -0.119653},
    {0.416667, 8.73530, 39.9758, 1.44689, -0.118014}, {0.433333, 8.56180, 39.9750, 1.44149, -0.116622},
    {0.450000, 8.37668, 39.9746, 1.43299, -0.115399}, {0.466667, 8.18197, 39.9746, 1.42277, -0.114357},
    {0.483333, 7.97979, 39.9748, 1.41103, -0.113478}, {0.500000, 7.77237, 39.9754, 1.39798, -0.112746},
    {0.516667, 7.56195, 39.9762, 1.38385, -0.112135}, {0.533333, 7.35085, 39.9773, 1.36886, -0.111615},
    {0.550000, 7.14137, 39.9785, 1.35397, -0.110958}, {0.566667, 6.93581, 39.9800, 1.33828, -0.110490},
    {0.583333, 6.73642, 39.9815, 1.32197, -0.110193}, {0.600000, 6.54537, 39.9832, 1.27602, -0.110057},
    {0.616667, 6.36476, 39.9849, 1.26008, -0.110074}, {0.633333, 6.19657, 39.9868, 1.24407, -0.110255},
    {0.650000, 6.04264, 39.9886, 1.22813, -0.110607}, {0.666667, 5.90466, 39.9905, 1.21241, -0.111129},
    {0.683333, 5.78415, 39.9924, 1.19708, -0.111819}, {0.700000, 5.68242, 39.9943, 1.18229, -0.112721},
    {0.716667, 5.60058, 39.9962, 1.16920, -0.114162}, {0.733333, 5.53956, 39.9981, 1.15689, -0.115763},
    {0.750000, 5.50000, 40.0000, 1.14549, -0.117506}, {0.766667, 5.48235, 40.0019, 1.13516, -0.119204},
    {0.783333, 5.48681, 40.0039, 1.12601, -0.120765}, {0.800000, 5.51333, 40.0058, 1.11816, -0.122414},
    {0.816667, 5.56163, 40.0078, 1.11171, -0.124134}, {0.833333, 5.63117, 40.0098, 1.10674, -0.125863},
    {0.850000, 5.72119, 40.0117, 1.10332, -0.127559}, {0.866667, 5.83072, 40.0137, 1.10150, -0.129275},
    {0.883333, 5.95856, 40.0156, 1.10130, -0.130994}, {0.900000, 6.10330, 40.0174, 1.10361, -0.132958},
    {0.916667, 6.26336, 40.0192, 1.10748, -0.134614}, {0.933333, 6.43699, 40.0208, 1.11290, -0.136166},
    {0.950000, 6.62227, 40.0223, 1.12052, -0.137670}, {0.966667, 6.81719, 40.0236, 1.12950, -0.139037},
    {0.983333, 7.01961, 40.0247, 1.13979, -0.140291}};

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kChord = 3.5;

SectionMotion motion(double t, double alpha_deg, double vrel) {
  const double omega = 2.0 * std::numbers::pi * 2.0 * kDegree * std::cos(2.0 * std::numbers::pi * t);
  return {alpha_deg * kDegree, vrel, omega, kChord};
}

}  // namespace

TEST_CASE("HGM on OpenFAST's ua_redfreq case: the lift loop of UA_Mod 3 (DU21, 7.5 ± 2 deg, k = 0.275)",
          "[verification][aero]") {
  const Params deck = aero::testing::load_nrel5mw_deck();
  const Polar* du21 = nullptr;
  for (const Polar& p : deck.airfoils)
    if (p.name() == "DU21_A17") du21 = &p;
  REQUIRE(du21 != nullptr);
  const UnsteadyAirfoilConstants k;  // HGM's τ_p = 1.5, τ_f = 6
  // Steady start at the driver's t = 0 inputs (7.22729°, 40.0255 m/s), as UnsteadyAero starts.
  UnsteadyAirfoilState state = unsteady_airfoil_steady(*du21, du21->separation(), k, motion(0.0, 7.22729, 40.0255));
  double previous = 0.0, sum2 = 0.0, worst = 0.0, worst_cm = 0.0, loop_ours = 0.0, loop_ref = 0.0;
  double cl_min = 1e9, cl_max = -1e9, mean_ours = 0.0, mean_ref = 0.0;
  std::complex<double> h_ours = 0.0, h_ref = 0.0;
  double last_alpha = 7.22729, last_cl = 0.0, last_ref = 1.30164;
  for (const Row& r : kUa3) {
    const SectionMotion m = motion(r.t, r.alpha_deg, r.vrel);
    advance_unsteady_airfoil(*du21, du21->separation(), k, m, r.t - previous, state);
    previous = r.t;
    const AirfoilCoefficients c = unsteady_coefficients(*du21, du21->separation(), k, m, state);
    sum2 += (c.cl - r.cl) * (c.cl - r.cl);
    worst = std::max(worst, std::abs(c.cl - r.cl));
    worst_cm = std::max(worst_cm, std::abs(c.cm - r.cm));
    const std::complex<double> w = std::exp(std::complex<double>(0.0, -2.0 * std::numbers::pi * r.t));
    h_ours += c.cl * w;
    h_ref += r.cl * w;
    mean_ours += c.cl;
    mean_ref += r.cl;
    cl_min = std::min(cl_min, r.cl);
    cl_max = std::max(cl_max, r.cl);
    if (last_cl != 0.0) {
      loop_ours += 0.5 * (c.cl + last_cl) * (r.alpha_deg - last_alpha) * kDegree;
      loop_ref += 0.5 * (r.cl + last_ref) * (r.alpha_deg - last_alpha) * kDegree;
    }
    last_alpha = r.alpha_deg;
    last_cl = c.cl;
    last_ref = r.cl;
  }
  const double rms = std::sqrt(sum2 / std::size(kUa3));
  const double n = static_cast<double>(std::size(kUa3));
  std::printf("ua_redfreq: mean Cl %.4f vs UA3 %.4f; first harmonic %.4f at %.1f deg vs %.4f at %.1f deg\n", mean_ours / n,
              mean_ref / n, 2.0 * std::abs(h_ours) / n, std::arg(h_ours) / kDegree, 2.0 * std::abs(h_ref) / n,
              std::arg(h_ref) / kDegree);
  std::printf("ua_redfreq: Cl RMS difference %.4f, largest %.4f (UA3 loop %.3f..%.3f); Cm largest %.4f; "
              "loop integrals ours %.5f, UA3 %.5f\n",
              rms, worst, cl_min, cl_max, worst_cm, loop_ours, loop_ref);
  // What agrees: the mean lift over the cycle, 1.309 against 1.283 (+2.0 %), both from the same
  // DU21 polar; bound 5 %. What does not, and is reported rather than bounded: UA3's loop lags α by
  // 47° with a first harmonic of 0.201 (the static slope gives 0.128), ours by 3° with 0.150 (Theodorsen
  // for this pitch axis and k: a 5° lead of the attached lift). UA3 flags trailing-edge separation
  // (f' < 1) and leading-edge vortex shedding from t = 0.28 s at 9.5° with the file's UA
  // coefficients, while HGM with the Kirchhoff f derived from the polar keeps DU21 attached to 9.5°;
  // and UA3's single cycle from its start is not yet periodic. Cl RMS difference 0.104, largest
  // 0.193; Cm largest 0.018.
  CHECK(std::abs(mean_ours / mean_ref - 1.0) < 0.05);
}
