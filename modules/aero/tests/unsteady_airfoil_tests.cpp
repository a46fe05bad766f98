// The HGM unsteady airfoil model (unsteady_airfoil.hpp): attached-flow response against
// Theodorsen's exact C(k), the quasi-steady limit against the static polar, and pitching DU21
// loops (below and through stall) with their physical properties.
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/aero/unsteady_airfoil.hpp"
#include "nrel5mw_deck.hpp"

using namespace fowtsim;
using namespace fowtsim::aero;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;
using Complex = std::complex<double>;

// Theodorsen's function C(k) = H1⁽²⁾(k) / (H1⁽²⁾(k) + i H0⁽²⁾(k)), H_n⁽²⁾ = J_n − i Y_n
// (Theodorsen 1935, NACA Report 496; Bisplinghoff, Ashley & Halfman, Aeroelasticity §5-6).
Complex theodorsen(double k) {
  const Complex h1(std::cyl_bessel_j(1.0, k), -std::cyl_neumann(1.0, k));
  const Complex h0(std::cyl_bessel_j(0.0, k), -std::cyl_neumann(0.0, k));
  return h1 / (h1 + Complex(0.0, 1.0) * h0);
}

// Jones' two-pole approximation the model's shed-wake states implement (HGM eq. 3.9 in the
// frequency domain, reduced time s = t/T_u, iω T_u = ik).
Complex jones(double k) {
  const Complex ik(0.0, k);
  return 1.0 - kJonesA1 * ik / (ik + kJonesB1) - kJonesA2 * ik / (ik + kJonesB2);
}

// A thin-airfoil polar: C_l = 2πα within ±20°, falling linearly to 0 at ±90°, C_d = 0.01, C_m = 0.
Polar thin_airfoil() {
  std::vector<double> alpha, cl, cd, cm;
  for (int d = -180; d <= 180; ++d) {
    const double a = d * kDegree;
    double c = 2.0 * kPi * a;
    if (std::abs(d) > 20) c = std::abs(d) >= 90 ? 0.0 : std::copysign(2.0 * kPi * 20.0 * kDegree * (90.0 - std::abs(d)) / 70.0, a);
    alpha.push_back(d);
    cl.push_back(c);
    cd.push_back(0.01);
    cm.push_back(0.0);
  }
  return Polar("thin", alpha, cl, cd, cm, PolarInterpolation::linear);
}

const Polar& nrel_polar(const std::string& name) {
  static const Params p = aero::testing::load_nrel5mw_deck();
  for (const Polar& polar : p.airfoils)
    if (polar.name() == name) return polar;
  FAIL("no airfoil " << name);
  return p.airfoils.front();
}

// A sinusoidal pitch about the quarter chord, α = mean + amp sin ωt, simulated over `periods`
// with `steps` steps per period; the last period's samples are returned.
struct Sample {
  double alpha, alpha34, cl, cd, cm, pitch_rate;
};
std::vector<Sample> pitch_oscillation(const Polar& polar, const UnsteadyAirfoilConstants& k, double mean, double amp,
                                      double omega, double speed, double chord, int periods, int steps) {
  const double dt = 2.0 * kPi / omega / steps;
  auto motion = [&](double t) {
    return SectionMotion{mean + amp * std::sin(omega * t), speed, amp * omega * std::cos(omega * t), chord};
  };
  UnsteadyAirfoilState st = unsteady_airfoil_steady(polar, polar.separation(), k, motion(0.0));
  std::vector<Sample> last;
  for (int i = 1; i <= periods * steps; ++i) {
    const SectionMotion m = motion(i * dt);
    advance_unsteady_airfoil(polar, polar.separation(), k, m, dt, st);
    if (i > (periods - 1) * steps) {
      const AirfoilCoefficients c = unsteady_coefficients(polar, polar.separation(), k, m, st);
      const double a34 = std::atan2(speed * std::sin(m.alpha_rad) + 0.5 * m.pitch_rate_rad_s * chord,
                                    speed * std::cos(m.alpha_rad));
      last.push_back({m.alpha_rad, a34, c.cl, c.cd, c.cm, m.pitch_rate_rad_s});
    }
  }
  return last;
}

// First Fourier coefficient (complex amplitude of e^{iθ}) of samples over one period.
template <class F>
Complex first_harmonic(const std::vector<Sample>& s, F value) {
  Complex sum = 0.0;
  const double n = static_cast<double>(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double theta = 2.0 * kPi * static_cast<double>(i + 1) / n;
    sum += value(s[i]) * std::exp(Complex(0.0, -theta));
  }
  return 2.0 * sum / n;
}

// ∮ y dα over the samples (closed loop); > 0 clockwise in (α, y).
template <class F>
double loop_integral(const std::vector<Sample>& s, F value) {
  double sum = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Sample& a = s[i];
    const Sample& b = s[(i + 1) % s.size()];
    sum += 0.5 * (value(a) + value(b)) * (b.alpha - a.alpha);
  }
  return sum;
}

}  // namespace

// Intent: the attached-flow part of the model is Theodorsen's theory with Jones' approximation
// of C(k) — the circulatory lift C_l − πT_u α̇ responds to the ¾-chord angle as 2π C(k).
TEST_CASE("HGM attached flow follows Theodorsen's C(k) within Jones' approximation", "[verification][aero]") {
  const Polar polar = thin_airfoil();
  const SeparationData& sep = polar.separation();
  // The derived constants of an exactly linear polar are exact: α0 = 0 (bisection to 1e-12 rad),
  // C_l,α = 2π (least squares on a straight line: round-off, measured 1e-15); 1e-10.
  CHECK(std::abs(sep.alpha0_rad) < 1e-10);
  CHECK(std::abs(sep.lift_slope_per_rad / (2.0 * kPi) - 1.0) < 1e-10);
  const UnsteadyAirfoilConstants k;
  const double speed = 10.0, chord = 1.0, tu = chord / (2.0 * speed);
  double worst_jones_gap = 0.0, worst_model_vs_jones = 0.0;
  for (double kr : {0.05, 0.1, 0.2, 0.5}) {
    const double omega = kr / tu;
    // 10 periods: the slowest shed-wake pole b1/T_u = 0.91/s decays by e^-57 even at k = 0.05.
    const std::vector<Sample> s = pitch_oscillation(polar, k, 0.0, 1.0 * kDegree, omega, speed, chord, 10, 4000);
    const Complex lift = first_harmonic(s, [&](const Sample& x) { return x.cl - kPi * tu * x.pitch_rate; });
    const Complex drive = first_harmonic(s, [](const Sample& x) { return x.alpha34; });
    const Complex model = lift / (2.0 * kPi * drive);
    const Complex exact = theodorsen(kr), approx = jones(kr);
    std::printf("k = %.2f: model |C| %.5f arg %.3f deg; Jones %.5f %.3f; Theodorsen %.5f %.3f\n", kr,
                std::abs(model), std::arg(model) / kDegree, std::abs(approx), std::arg(approx) / kDegree,
                std::abs(exact), std::arg(exact) / kDegree);
    worst_model_vs_jones = std::max(worst_model_vs_jones, std::abs(model - approx));
    worst_jones_gap = std::max(worst_jones_gap, std::abs(approx - exact));
    // The time integration reproduces Jones' transfer function: measured ≤ 7e-5 (at k = 0.5; the
    // first-order hold's O(Δt²) error at 4000 steps a period, T_u frozen per step, and the
    // atan2 nonlinearity of α34 at 1°); 7e-4.
    CHECK(std::abs(model - approx) < 7e-4);
    // Against the exact C(k) the gap is Jones' approximation's own error, which this test measures
    // on the way: |C_Jones − C| ≤ 0.0143 over k = 0.05…0.5 (worst at k = 0.5: |C| 0.6121 vs 0.6166,
    // arg −15.4° vs −14.1°); 0.02 admits it and the model's ≤ 7e-5, nothing more.
    CHECK(std::abs(model - exact) < 0.02);
  }
  std::printf("worst |model - Jones| = %.2e, worst |Jones - Theodorsen| = %.4f\n", worst_model_vs_jones, worst_jones_gap);
}

// Intent: held still, the model returns the static polar exactly (its states sit at their inputs),
// through stall, for every NREL 5MW lifting airfoil.
TEST_CASE("HGM steady state returns the static polar exactly", "[unit][aero]") {
  const UnsteadyAirfoilConstants k;
  for (const char* name : {"DU40_A17", "DU35_A17", "DU30_A17", "DU25_A17", "DU21_A17", "NACA64_A17", "Cylinder1"}) {
    const Polar& polar = nrel_polar(name);
    double worst = 0.0;
    for (double d = -60.0; d <= 60.0; d += 0.25) {
      const SectionMotion m{d * kDegree, 50.0, 0.0, 2.0};
      const UnsteadyAirfoilState st = unsteady_airfoil_steady(polar, polar.separation(), k, m);
      const AirfoilCoefficients u = unsteady_coefficients(polar, polar.separation(), k, m, st);
      const AirfoilCoefficients s = polar.evaluate(m.alpha_rad);
      worst = std::max({worst, std::abs(u.cl - s.cl), std::abs(u.cd - s.cd), std::abs(u.cm - s.cm)});
    }
    // Round-off of α_E = α(1 − A1 − A2) + A1 α + A2 α and of the Kirchhoff identity; measured ≤ 4e-15.
    INFO(name);
    CHECK(worst < 1e-12);
  }
}

// Intent: the separation data the model derives from the NREL 5MW tables agree with the UA
// coefficients OpenFAST's airfoil files list for them (alpha0, C_nalpha: 5MW_Baseline/Airfoils).
TEST_CASE("derived zero-lift angle and lift slope agree with the airfoil files", "[unit][aero]") {
  struct Row {
    const char* name;
    double alpha0_deg, slope;
  };
  // Transcribed from the r-test 5MW_Baseline Airfoils/*.dat headers (alpha0, C_nalpha).
  for (const Row& r : {Row{"DU40_A17", -3.2, 7.4888}, Row{"DU35_A17", -1.2, 7.1838}, Row{"DU30_A17", -2.2, 7.3326},
                       Row{"DU25_A17", -3.2, 6.4462}, Row{"DU21_A17", -4.2, 6.2047}, Row{"NACA64_A17", -4.432, 6.0031}}) {
    const SeparationData& s = nrel_polar(r.name).separation();
    std::printf("%-10s alpha0 %.3f deg (file %.3f)  C_l,alpha %.4f /rad (file C_n,alpha %.4f)  f=0 at %.2f / %.2f deg\n",
                r.name, s.alpha0_rad / kDegree, r.alpha0_deg, s.lift_slope_per_rad, r.slope, s.alpha_low_rad / kDegree,
                s.alpha_high_rad / kDegree);
    INFO(r.name);
    CHECK(s.lifting);
    // The files' alpha0 are hand-entered: within 0.17° of the tables' own zero crossing for the DU
    // sections, 0.58° for NACA64 (file −4.432°, its table crosses zero at −3.85°); 1° bounds both.
    CHECK(std::abs(s.alpha0_rad / kDegree - r.alpha0_deg) < 1.0);
    // C_l,α is the least-squares C_l slope over α0 − 3° … α0 + 5° (this model's choice); the files'
    // C_nα are fits elsewhere on the curve and lower by 5–18 % (measured) for the DU21–DU35 and
    // NACA64 sections: [0.95, 1.3] of the file value. DU40's table has a plateau at α0 (C_l
    // 0.003…0.004 from −3° to −1.5°), so its fitted slope is not comparable: positive only.
    if (std::string(r.name) != "DU40_A17") {
      CHECK(s.lift_slope_per_rad / r.slope > 0.95);
      CHECK(s.lift_slope_per_rad / r.slope < 1.3);
    } else {
      CHECK(s.lift_slope_per_rad > 0.0);
    }
  }
  CHECK_FALSE(nrel_polar("Cylinder1").separation().lifting);  // C_l ≡ 0: no lift slope, static polar
}

// Intent: at a very low reduced frequency the dynamic coefficients follow the static polar
// through stall (the quasi-steady limit).
TEST_CASE("HGM at very low reduced frequency reproduces the static polar through stall", "[verification][aero]") {
  const Polar& polar = nrel_polar("DU25_A17");
  const UnsteadyAirfoilConstants k;
  const double speed = 50.0, chord = 2.0, tu = chord / (2.0 * speed);
  // α = 10° ± 20° (−10° … 30°, through positive stall) at k = 0.001.
  const double omega = 0.001 / tu;
  const std::vector<Sample> s = pitch_oscillation(polar, k, 10.0 * kDegree, 20.0 * kDegree, omega, speed, chord, 2, 20000);
  double dl = 0.0, dd = 0.0, dm = 0.0;
  for (const Sample& x : s) {
    const AirfoilCoefficients st = polar.evaluate(x.alpha);
    dl = std::max(dl, std::abs(x.cl - st.cl));
    dd = std::max(dd, std::abs(x.cd - st.cd));
    dm = std::max(dm, std::abs(x.cm - st.cm));
  }
  std::printf("k = 0.001, DU25 -10..30 deg: max |dCl| %.2e, |dCd| %.2e, |dCm| %.2e\n", dl, dd, dm);
  // The lag scales with k (the slowest state, x1, lags α by ≈ A1 α̇ T_u/b1, and f lags through
  // stall where C_l^st falls steeply): measured |ΔC_l| 0.038 (at stall), |ΔC_d| 1.6e-3, |ΔC_m|
  // 1.2e-3; bounds 0.06, 0.005, 0.005 (≈ 1.5–4×: the lag is linear in k, so a 10× bound would
  // admit k = 0.01 behaviour, which is no longer quasi-steady).
  CHECK(dl < 0.06);
  CHECK(dd < 0.005);
  CHECK(dm < 0.005);
}

// Intent: DU21 pitching at 7.5° ± 2°, 1 Hz, at the NREL 5MW DU21 station's chord and speed
// (k ≈ 0.13): a lift loop that lags α (counter-clockwise, the Theodorsen sense) and positive
// aerodynamic pitch damping; through deep stall (15° ± 10°) a dynamic-stall overshoot of the
// static C_l,max and a loop whose lift on the downstroke stays below the upstroke's.
TEST_CASE("HGM pitching DU21 loops: attached and deep stall", "[verification][aero]") {
  const Polar& polar = nrel_polar("DU21_A17");
  const UnsteadyAirfoilConstants k;
  // NREL 5MW DU21 stations (BlSpn 52.75–56.17 m): chord ≈ 2.9 m, W ≈ Ω r ≈ 1.267 rad/s × 56 m ≈ 70 m/s.
  const double speed = 70.0, chord = 2.9, omega = 2.0 * kPi * 1.0;
  std::printf("DU21 1 Hz: k = %.3f\n", omega * chord / (2.0 * speed));
  {
    const std::vector<Sample> s = pitch_oscillation(polar, k, 7.5 * kDegree, 2.0 * kDegree, omega, speed, chord, 6, 2000);
    const double lift_loop = loop_integral(s, [](const Sample& x) { return x.cl; });
    const double moment_loop = loop_integral(s, [](const Sample& x) { return x.cm; });
    const double drag_loop = loop_integral(s, [](const Sample& x) { return x.cd; });
    double cl_min = 1e9, cl_max = -1e9;
    for (const Sample& x : s) cl_min = std::min(cl_min, x.cl), cl_max = std::max(cl_max, x.cl);
    std::printf("7.5 +- 2 deg: loop integrals Cl %.5f, Cm %.5f, Cd %.5f (rad); Cl %.4f..%.4f (static %.4f..%.4f)\n",
                lift_loop, moment_loop, drag_loop, cl_min, cl_max, polar.evaluate(5.5 * kDegree).cl,
                polar.evaluate(9.5 * kDegree).cl);
    // Theodorsen for pitch about the ¼ chord at k = 0.13: C_L/(2πα̂) = C(k)(1 + ik) + ik/2 ≈
    // 0.84 + 0.04i — the total lift *leads* α (the ¾-chord angle and the added mass outweigh the
    // wake lag), a clockwise loop, ∮ C_l dα > 0 (measured 0.0041; the ±0.0002 of resolution
    // changes between step sizes 1000 and 2000 per period). ∮ C_m dα < 0: the pitching moment
    // does negative work on the airfoil per cycle — positive pitch damping (measured −0.00087).
    CHECK(lift_loop > 0.0);
    CHECK(moment_loop < 0.0);
  }
  {
    const std::vector<Sample> s = pitch_oscillation(polar, k, 15.0 * kDegree, 10.0 * kDegree, omega, speed, chord, 6, 2000);
    double cl_max = -1e9, static_max = -1e9;
    for (const Sample& x : s) cl_max = std::max(cl_max, x.cl);
    for (double d = 5.0; d <= 25.0; d += 0.05) static_max = std::max(static_max, polar.evaluate(d * kDegree).cl);
    // Lift at 15° on the up- and downstroke (samples where α crosses 15°).
    double up = 0.0, down = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Sample& next = s[(i + 1) % s.size()];
      if (s[i].alpha < 15.0 * kDegree && next.alpha >= 15.0 * kDegree) up = s[i].cl;
      if (s[i].alpha > 15.0 * kDegree && next.alpha <= 15.0 * kDegree) down = s[i].cl;
    }
    const double lift_loop = loop_integral(s, [](const Sample& x) { return x.cl; });
    std::printf("15 +- 10 deg: Cl max %.4f (static max %.4f), Cl(15 deg) up %.4f down %.4f (static %.4f), loop %.4f\n",
                cl_max, static_max, up, down, polar.evaluate(15.0 * kDegree).cl, lift_loop);
    // Dynamic stall: the separation lags, so the upstroke carries more lift than the static
    // maximum (measured +0.3 above 1.39) — 0.05 is well above the step's resolution — and the
    // downstroke, still separated, less lift than the upstroke at the same α.
    CHECK(cl_max > static_max + 0.05);
    CHECK(up > down + 0.05);
  }
}
