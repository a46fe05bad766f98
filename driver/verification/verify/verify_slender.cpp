// `fowtsim verify slender`: the slender-body module (modules/slender, seed 004) on the shipped decks
// of inputs/slender/ through the scene's own analysis (scenes/slender_analysis.hpp): the riser's
// modes against the tensioned-string-beam closed form, the drag linearisation against the nonlinear
// time domain in a regular wave (FD vs TD steady state, both applications) and a JONSWAP sea, and
// EI v'' against inertia relief. The same bounds and sources as driver/tests/slender_scene_tests.cpp
// and the module's tests; about a second.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "fowtsim/slender/modes.hpp"
#include "fowtsim/slender/shape_functions.hpp"
#include "scenes/slender_analysis.hpp"
#include "scenes/slender_scene.hpp"
#include "verify/verify_modules.hpp"

namespace fowtsim::driver {

std::filesystem::path source_input(const std::string& relative);  // verify_cases.cpp

namespace {

VerificationRow below(const std::string& metric, double value, double limit, const std::string& source) {
  return {"slender", metric, value, fmt::format("< {:.3g}", limit), source, value < limit};
}

SlenderCase shipped(const std::string& name, const std::vector<std::string>& settings = {}) {
  return read_slender_case(std::filesystem::absolute(source_input("slender/" + name)), settings);
}

// The riser without gravity: T_eff is the top tension along the whole length, so its pinned–pinned
// modes are the closed form ω_n = (nπ/L)²√(EI/m)√(1 + TL²/(EI n²π²)) (m with contents and added mass).
double riser_mode_error(std::FILE* out) {
  SlenderCase c = shipped("riser_harmonic.yaml");
  c.deck.environment.gravity_m_s2 = 0.0;
  const slender::Model model = slender::make_model(c.deck.body, c.deck.environment);
  const slender::Modes modes = slender::compute_modes(model, 5);
  const double L = model.length_m, EI = model.strips.bending_stiffness_N_m2(0), m = model.strips.mass_kg_m(0);
  const double T = c.deck.body.top_tension_N;
  double worst = 0.0;
  fmt::print(out, "riser, no gravity (T_eff = {:.4g} N uniform), ω_n [rad/s] model [closed form]:", T);
  for (int n = 1; n <= 5; ++n) {
    const double k = n * std::numbers::pi / L;
    const double exact = k * k * std::sqrt(EI / m) * std::sqrt(1.0 + T / (EI * k * k));
    fmt::print(out, " {:.9f} [{:.9f}]", modes.omega_rad_s(n - 1), exact);
    worst = std::max(worst, std::abs(modes.omega_rad_s(n - 1) / exact - 1.0));
  }
  fmt::print(out, "\n");
  return worst;
}

}  // namespace

std::vector<VerificationRow> verify_slender(std::FILE* out) {
  std::vector<VerificationRow> rows;
  // Midpoint-sampled sines are discretely orthogonal: exact to rounding (module test: < 1e-14).
  rows.push_back(below("riser modes 1–5 vs tensioned pinned–pinned closed form: worst |rel. diff|", riser_mode_error(out), 1e-12,
                       "Blevins, string-beam; modules/slender README"));

  for (const char* deck : {"oc3_tower_harmonic.yaml", "riser_harmonic.yaml"}) {
    const SlenderCase c = shipped(deck);
    const SlenderResults r = solve_slender(c.deck, c.dt_s, c.t_max_s);
    const double d = profile_difference(r.frequency_domain->displacement_m, r.time_domain->displacement_m);
    const double s = profile_difference(r.frequency_domain->stress_inertia_relief_Pa, r.time_domain->stress_inertia_relief_Pa);
    fmt::print(out, "{}: peak amplitude FD {:.6g} m, TD {:.6g} m; stress (IR) FD {:.6g} MPa, TD {:.6g} MPa\n", deck,
               r.frequency_domain->displacement_m.maxCoeff(), r.time_domain->displacement_m.maxCoeff(),
               r.frequency_domain->stress_inertia_relief_Pa.maxCoeff() / 1e6, r.time_domain->stress_inertia_relief_Pa.maxCoeff() / 1e6);
    // The drag linearisation 8/3π|u_r| against the nonlinear drag: measured 8e-6 (spar, inertia
    // dominated), 6.1e-3 / 8.2e-3 (riser); the 1 %.
    const std::string source = "issue 25: FD vs TD steady state ≤ 1 % (8/3π linearisation)";
    rows.push_back(below(fmt::format("{} FD vs TD amplitude, displacement profile", deck), d, 1e-2, source));
    rows.push_back(below(fmt::format("{} FD vs TD amplitude, stress profile (IR)", deck), s, 1e-2, source));
  }

  const SlenderCase sea = shipped("riser_jonswap.yaml");
  const SlenderResults random = solve_slender(sea.deck, sea.dt_s, sea.t_max_s);
  const double rms = std::abs(random.time_domain->displacement_m.maxCoeff() / random.frequency_domain->displacement_m.maxCoeff() - 1.0);
  // Seed 1 of the 4 in the driver test (mean 3.4e-2, σ 2.1e-2 over seeds; measured here 1.3e-2):
  // √(8/π)σ linearisation's bias plus the seed scatter, 1e-1.
  rows.push_back(below("riser_jonswap.yaml FD vs TD peak RMS displacement, seed 1", rms, 1e-1,
                       "statistical linearisation bias + seed scatter (driver/tests/slender_scene_tests.cpp)"));

  // EI v'' against inertia relief on the riser refined 8× (800 strips, 128 sines): measured 3.3e-2,
  // falling at second order from 0.83 at the deck's 100 strips and 16 sines.
  SlenderCase fine = shipped("riser_harmonic.yaml", {"analysis.domain=frequency"});
  std::vector<slender::Strip> strips;
  for (slender::Strip s : fine.deck.body.strips) {
    s.length_m /= 8.0;
    strips.insert(strips.end(), 8, s);
  }
  fine.deck.body.strips = strips;
  fine.deck.body.shapes = slender::pinned_pinned_shapes(128, fine.deck.body.shapes.front().length_m);
  const SlenderResults refined = solve_slender(fine.deck, fine.dt_s, fine.t_max_s);
  rows.push_back(below("riser EI v'' vs inertia-relief moment, 800 strips, 128 sines: max diff / max M_IR",
                       profile_difference(refined.frequency_domain->moment_inertia_relief_N_m, refined.frequency_domain->moment_elastic_N_m),
                       1e-1, "seed 004 'both EI and IR can be used'; convergence in driver/tests/slender_scene_tests.cpp"));
  return rows;
}

}  // namespace fowtsim::driver
