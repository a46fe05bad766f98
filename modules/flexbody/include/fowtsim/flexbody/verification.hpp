#pragma once
// The computations behind the flexbody verification checks (seed paper 002, Sec. 5.1, 5.3, 5.5 and
// welib's uniform beam), shared by the module tests and `fowtsim verify flexbody` so that both run
// the same code. Analytic answers are computed here beside the measured values; the tolerances and
// their reasons stay with the callers. The seed's Table 1 errors are kept here (seed_table1) because
// both callers compare with them.
#include "fowtsim/flexbody/integrals.hpp"
#include "fowtsim/flexbody/torsion.hpp"

#include <Eigen/Dense>
#include <numbers>
#include <string>
#include <vector>

namespace fowtsim::flexbody::verification {

// Sec. 5.1's uniform clamped-free beam (also Sec. 5.5's and Sec. 6's tower): L, EI, m.
inline constexpr double kLength = 100.0, kBendingStiffness = 2e12, kMassPerLength = 9e3;
BeamStations sec51_beam();

// A measured value and the analytic one it is checked against.
struct Checked {
  double value = 0.0, exact = 0.0;
  double relative_error() const { return value / exact - 1.0; }
};

// Sec. 5.1's single shape u_0 = 1 − cos(πx/2L) on sec51_beam(), default Gauss rule, against the
// closed forms: M_q = mL(3π − 8)/(2π), K_q = EIπ⁴/(32L³); top mass M_t: K_MT = −M_t g π²/(8L),
// K_MT/K_q = −M_t g/P_cr; self weight (M = mL): K_SW = Mg(−π²/(8L) + (4 + π²)/(16L)),
// K_SW/K_q = −(Mg/P_cr)(1/2 − 2/π²), P_cr = π²EI/(4L²); centrifugal at Ω, root radius r:
// Ω²m[L(π²/24 − 1/8) + r(π²/16 − 1/4)]; ∫m u_0 = mL(1 − 2/π), ∫m x u_0 = mL²(1/2 − 2/π + 4/π²).
struct CosineBeam {
  Checked Mq, Kq, top_mass, top_mass_ratio, self_weight, self_weight_ratio, centrifugal, first_moment, axial_moment;
};
CosineBeam cosine_beam_closed_forms(double top_mass, double gravity, double omega, double root_radius);

// Generalised symmetric eigenvalues of A v = λ B v (B positive definite), ascending.
Eigen::VectorXd generalized_eigenvalues(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);

// u = x̃^j, j = 2..n+1: complete clamped polynomials (ElastoDyn's space for n = 5).
std::vector<ShapeFunction> monomial_shapes(int n, double length);

// ω_n = (β_n/L)² sqrt(EI/m) of sec51_beam() with top-mass ratio μ (eq. 32), n = 1..modes.
double clamped_free_omega(int n, double top_mass_ratio = 0.0);

// Rayleigh–Ritz frequencies of sec51_beam() with x̃²..x̃^(shapes+1), modes 1..modes, vs ω_n.
std::vector<Checked> monomial_frequencies(int shapes, int modes);

// The first `modes` eq. 32 modes with a top mass M_t = μ mL, the tip mass added to M_q (u_j(L) = 1),
// vs eq. 32's ω_n: exact, as these modes are the eigenfunctions.
std::vector<Checked> top_mass_mode_frequencies(double top_mass_ratio, int modes);

// Buckling of sec51_beam() with x̃²..x̃^(shapes+1): the smallest λ making K_q + λ K^T(unit load)
// singular. euler: tip dead load vs π²EI/(4L²); greenhill: critical self weight as (mgL)_cr L²/EI
// (Greenhill's constant, 7.8373 in Timoshenko & Gere §2.13).
struct Buckling {
  Checked euler;
  double greenhill = 0.0;
};
Buckling column_buckling(int shapes);

// welib yams/tests/test_flexibility.py test_GMGKBeam: uniform beam L 60 m, EI 2e10 N m², m 500 kg/m,
// the first three eq. 32 modes (M_t = 0) on 30 equidistant stations, integrated with `kind`.
struct UniformBeamMatrices {
  Eigen::MatrixXd M, K;
  Eigen::VectorXd first_moment;  // ∫ m u_j
};
inline constexpr double kWelibLength = 60.0, kWelibBendingStiffness = 2e10, kWelibMassPerLength = 500.0;
UniformBeamMatrices welib_uniform_beam(QuadratureRule::Kind kind);

// Sec. 5.5, Table 1: sec51_beam() split at x_B into a FEM body a (possibly Guyan/Craig–Bampton
// reduced) and a Rayleigh–Ritz body b (eq. 32 modes of b's own length, clamped at B), eq. 19.
struct MixedCase {
  std::string name;
  double split = 0.0;  // x_B / L; 0: no body a, the whole beam is the RR body
  int elements = 0;    // FEM elements of body a
  int cb_modes = -1;   // -1: full FEM; 0: Guyan; k > 0: Craig–Bampton with k fixed-interface modes
  int rr_shapes = 0;   // shapes of body b
};
struct MixedErrors {
  double f[2] = {0.0, 0.0};  // relative errors of ω_2, ω_4 vs eq. 32
  double u[2] = {0.0, 0.0};  // mean |w − u| / max|u| of modes 2, 4 over body b, 51 points, tip-normalised
};
MixedErrors mixed_case_errors(const MixedCase& c);

// The seed's Table 1 rows: the case and its printed δf_2, δf_4, δu_2, δu_4 [%]. "GY2-RR4c" is split
// "at 0.4% of its length" in the text; its numbers are those of a split at 0.4 L, the split used here.
struct Table1Row {
  MixedCase c;
  double seed[4];
};
const std::vector<Table1Row>& seed_table1();

// |value − printed| in units of half the last printed digit of `printed` (`digits` significant
// digits): ≤ 1 when the print is `value` rounded.
double printed_digit_error(double value, double printed, int digits);

// Sec. 5.3: hollow steel tube (L 100 m, G 79.3 GPa, ρ 7850 kg/m³, D 8 m, t 45 mm; I_x = π/32 (D⁴ −
// (D − 2t)⁴), K_t = I_x/2, j_G = ρ I_x), shapes ν_x^j = sin(β_j x̃), damping ζ = 1/(10π) per shape,
// tip moment M₀ sin(Ω t), M₀ = 50 GN·m, Ω = 1.0002 ω₁, from rest.
struct TorsionTube {
  double length = 100.0, shear_modulus = 79.3e9, density = 7850.0, diameter = 8.0, wall = 0.045;
  double zeta = 1.0 / (10.0 * std::numbers::pi);
  double moment = 50e9, frequency_ratio = 1.0002;
  double polar_moment() const;  // I_x [m⁴]
  double polar_inertia() const { return density * polar_moment(); }                   // j_G [kg m]
  double torsional_stiffness() const { return shear_modulus * polar_moment() / 2; }  // G K_t [N m²]
  TorsionModel model(int shapes) const;
};

// Tip twist of the tube's RR model from rest by RK4 at `step_s`, sampled every `sample_s` to `end_s`,
// against: one shape vs the one-DOF analytic transient (one_shape_error); four shapes vs the sum of
// the four exact modal transients (modal_error); four shapes vs the seed's one-DOF formula (max and
// RMS difference, and the envelope Σ_{j≥2}(A_j + H₀_j) of the shapes that formula omits). [rad]
struct TorsionTransient {
  double one_shape_error = 0.0, modal_error = 0.0;
  double one_dof_difference = 0.0, one_dof_rms = 0.0, omitted_envelope = 0.0;
  double peak = 0.0;  // max |tip twist| of the four-shape response
};
TorsionTransient torsion_transient(const TorsionTube& tube, double end_s, double sample_s, double step_s);

}  // namespace fowtsim::flexbody::verification
