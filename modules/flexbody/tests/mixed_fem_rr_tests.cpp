// Seed Sec. 5.5, Table 1: the mixed FEM–Rayleigh–Ritz beam (eq. 19) and its Guyan / Craig–Bampton
// reductions, 2nd and 4th frequencies and mode shapes against the clamped-free solution (eq. 32).
#include "fowtsim/flexbody/beam_fem.hpp"
#include "fowtsim/flexbody/mixed_fem_rr.hpp"
#include "fowtsim/flexbody/reduction.hpp"
#include "fowtsim/flexbody/station_segment.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <string>

using namespace fowtsim::flexbody;

namespace {

// Sec. 5.5 uses "the beam of subsection 5.1": uniform, L 100 m, EI 2e12 N m², m 9e3 kg/m. For a
// uniform beam the relative errors below do not depend on these values.
const double L = 100.0, EI = 2e12, m = 9e3;

struct Case {
  std::string name;
  double split;   // x_B / L; 0: no body a, the whole beam is the RR body
  int elements;   // FEM elements of body a
  int cb_modes;   // -1: full FEM; 0: Guyan; k > 0: Craig–Bampton with k fixed-interface modes
  int rr_shapes;  // shapes of body b (eq. 32 modes of b's own length, clamped at B)
};

struct Errors {
  double f[2];  // relative errors of ω_2, ω_4
  double u[2];  // mean relative mode-shape errors of modes 2, 4 over body b
};

double exact_omega(int n) { return std::pow(clamped_free_beta(n) / L, 2) * std::sqrt(EI / m); }

Errors run(const Case& c) {
  const BeamStations beam = uniform_beam(L, m, EI);
  const double xB = c.split * L;
  std::vector<ShapeFunction> shapes;
  for (int j = 1; j <= c.rr_shapes; ++j) shapes.push_back(clamped_free_mode(j, L - xB));
  const SampledBody b = sample(quadrature_points(segment(beam, xB, L)), shapes);

  Eigen::MatrixXd Ma, Ka;
  if (c.split > 0) {
    const BeamFem fem = clamped_beam_fem(segment(beam, 0.0, xB), c.elements);
    Ma = fem.M;
    Ka = fem.K;
  }
  if (c.split > 0 && c.cb_modes >= 0) {
    const ReducedBody r = craig_bampton(Ma, Ka, 2, c.cb_modes);
    Ma = r.M;
    Ka = r.K;
  }
  const MixedModel mix = c.split > 0 ? couple_rr_body(Ma, Ka, b)
                                     : MixedModel{generalized_mass(b), generalized_stiffness(b)};
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(mix.K, mix.M);
  const auto na = static_cast<int>(Ma.rows());

  Errors out{};
  for (int k = 0; k < 2; ++k) {
    const int n = 2 * k + 2;
    out.f[k] = std::sqrt(eig.eigenvalues()(n - 1)) / exact_omega(n) - 1;
    // Mode shape over body b, w = u_z + θ_y x + Σ g_j u_j (mixed_fem_rr.hpp), at 51 equispaced
    // points, scaled to the analytic tip value u(L) = 1 (clamped_free_mode's normalisation);
    // error = mean |w − u| / max|u| (Sec. 5.5: "with respect to the maximum deflection ... only
    // along the second body").
    const Eigen::VectorXd v = eig.eigenvectors().col(n - 1);
    const ShapeFunction exact = clamped_free_mode(n, L);
    const auto w = [&](double x) {
      double s = na > 0 ? v(na - 2) + v(na - 1) * x : 0.0;
      for (int j = 0; j < c.rr_shapes; ++j) s += v(na + j) * shapes[static_cast<std::size_t>(j)](x).u;
      return s;
    };
    const double scale = 1.0 / w(L - xB);
    double sum = 0.0, umax = 0.0;
    for (int i = 0; i <= 50; ++i) {
      const double x = (L - xB) * i / 50.0;
      sum += std::abs(scale * w(x) - exact(xB + x).u);
      umax = std::max(umax, std::abs(exact(xB + x).u));
    }
    out.u[k] = sum / 51.0 / umax;
  }
  return out;
}

}  // namespace

TEST_CASE("Table 1 of Sec. 5.5: mixed FEM-RR, Guyan and Craig-Bampton vs the seed", "[verification]") {
  // seed: δf_2, δf_4, δu_2, δu_4 of Table 1 [%]. "GY2-RR4c" is split "at 0.4% of its length" in the
  // text, but the seed's numbers are those of a split at 0.4 L (40 %): measured 0.14/12.86/0.05/9.54
  // at 0.4 L against 0.00/0.003/0.001/0.27 at 0.004 L (a 0.4 m Guyan stub is exact and b's modes are
  // nearly the full beam's). Both splits are run; the seed's values are compared with 0.4 L.
  struct Row {
    Case c;
    double seed[4];
  };
  const Row rows[] = {
      {{"RR4", 0.0, 0, -1, 4}, {0.00, 0.00, 0.00, 0.00}},
      {{"FEM50-RR2", 0.5, 50, -1, 2}, {0.02, 1.18, 0.18, 4.80}},
      {{"FEM50-RR4", 0.5, 50, -1, 4}, {-0.01, -0.03, 0.01, 0.22}},
      {{"GY2-RR2", 0.5, 50, 0, 2}, {0.71, 50.08, 0.29, 15.89}},
      {{"GY2-RR4", 0.5, 50, 0, 4}, {0.68, 35.28, 0.32, 18.48}},
      {{"GY2-RR4c (0.4 L)", 0.4, 50, 0, 4}, {0.14, 12.06, 0.07, 9.47}},
      {{"CB2+2-RR4", 0.5, 50, 2, 4}, {-0.01, 0.11, 0.01, 0.23}},
  };
  std::printf("Table 1 (Sec. 5.5), errors in %%: ours [seed]\n");
  for (const auto& [c, seed] : rows) {
    const Errors e = run(c);
    const double ours[4] = {100 * e.f[0], 100 * e.f[1], 100 * e.u[0], 100 * e.u[1]};
    std::printf("%-18s df2 %7.3f [%6.2f]  df4 %7.3f [%6.2f]  du2 %6.3f [%5.2f]  du4 %6.3f [%5.2f]\n",
                c.name.c_str(), ours[0], seed[0], ours[1], seed[1], ours[2], seed[2], ours[3], seed[3]);
    INFO(c.name);
    // Every model here is conforming (FEM, Guyan/CB subspaces and b's shapes are all admissible
    // for the clamped-free beam), so Rayleigh–Ritz bounds the frequencies from above; 1e-9 is
    // eigen-solver rounding. The seed's negative −0.01/−0.03 % cannot come from such a model: they
    // are its discretisation/extraction offsets (50 integration sections, time-domain Newmark).
    CHECK(e.f[0] > -1e-9);
    CHECK(e.f[1] > -1e-9);
    // Agreement with the seed within 0.1 percentage point + 8 % of its value: 0.1 covers its
    // 2-decimal rounding and the ±0.05 offsets above (FEM50-RR4, CB: ours +0.001/+0.035,
    // +0.006/+0.18); 8 % covers the largest relative gap measured, 6.7 % on GY2-RR4c δf_4
    // (12.86 vs 12.06) and 2.5 % on GY2-RR2 δf_4 (51.35 vs 50.08) — the seed's frequencies are
    // systematically a little lower, consistent with its coarser spanwise integration; not traced.
    for (int k = 0; k < 4; ++k) CHECK(std::abs(ours[k] - seed[k]) < 0.1 + 0.08 * std::abs(seed[k]));
  }
}

TEST_CASE("GY2-RR4 split at 0.4 % of the length: a Guyan stub is exact", "[verification]") {
  // The text's split. The 0.4 m FEM stub is rigid to within (0.004)^2 of the beam and b's four
  // eq. 32 modes (length 0.996 L) nearly span the full beam's first four: measured δf_2 2.5e-8,
  // δf_4 3.2e-5, δu_4 2.7e-3 (relative) — bounds ~3×.
  const Errors e = run({"GY2-RR4 (0.004 L)", 0.004, 50, 0, 4});
  CHECK(e.f[0] > -1e-9);
  CHECK(e.f[0] < 1e-7);
  CHECK(e.f[1] < 1e-4);
  CHECK(e.u[1] < 1e-2);
}
