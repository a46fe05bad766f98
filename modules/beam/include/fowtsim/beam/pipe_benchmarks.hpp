#pragma once
// The pipes of seed 000 §3.5 and the classical ones of Païdoussis (Fluid-Structure Interactions
// vol. 1, Ch. 3), in the seed's dimensionless groups (eq. 3.64), with the reference numbers they
// are checked against. Shared by the tests and the README table.
#include <array>
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"
#include "fowtsim/beam/pipe.hpp"

namespace fowtsim::beam::pipe_benchmarks {

// A straight uniform cantilever pipe along z from the origin, length 1 m, E = 1 GPa, ν = 0.3, wall
// density 1000 kg/m³, bore D = 0.8 D_o, inviscid fluid, no damping, with the seed's groups
//   μ_A = A^p L²/I,  μ_m = m^f/(m^f + m^p),  μ_V = V L √(m^f/EI).
// The seed does not give the diameter ratio, ν or densities of Table 3.1: the frequencies depend
// on them only through shear and rotary inertia, O(1/μ_A).
PipeDefinition cantilever(double mu_a, double mu_m, double mu_v);
// The same pipe held at both ends (pinned-pinned or clamped-clamped).
PipeDefinition supported(double mu_a, double mu_m, double mu_v, EndCondition ends);

// ω → μ_ω = ω L² √((m^f + m^p)/EI) and μ_Ω → Ω = μ_Ω / (L² √(m^p/EI)) for that pipe (eq. 3.64).
double dimensionless_frequency(const PipeDefinition& def, double omega_rad_s);
double rotation_speed_rad_s(const PipeDefinition& def, double mu_omega);

// The lowest `count` bending frequencies μ_ω (Im λ of the damped modes, damped_modes) moving along
// f's x (axis 0: in the plane of a rotation about y) or y (axis 1), or in either plane (axis −1,
// a repeated pair counted once: a pipe at rest), about `state` under `input`.
std::vector<double> bending_frequencies(const BeamModel& model, const PipeDefinition& def,
                                        const BeamInput& input, const BeamState& state, int axis, int count);

// The first three bending μ_ω of seed Table 3.1's cantilever with flow (μ_A = 1.8e4, μ_m = 0.5035)
// at μ_V, at rest, with our momentum flux or the seed's.
std::vector<double> table31_flow_frequencies(double mu_v, bool seed_flux, int segments = 40);

// The first `count` bending μ_ω of seed Table 3.1's rotating cantilever (μ_A = 3.9e3, μ_m = 0) at
// μ_Ω about y, out of the plane of rotation (along y) and in it (along x), about the static
// equilibrium under the centrifugal load. At μ_Ω = 0 both are the repeated pair counted once.
struct RotatingFrequencies {
  std::vector<double> flap, lead_lag;
};
RotatingFrequencies table31_rotating_frequencies(double mu_omega, int count, int segments = 40);

// Seed Table 3.1, right half (μ_A = 1.8e4, μ_m = 0.5035, μ_Ω = 0): μ_V and, per row, the seed's
// combined model, Zhai et al. [147] (linear Timoshenko), and the classical Euler–Bernoulli plug-flow
// equation by Chebyshev collocation (scripts/pipe_linear_theory.py: 2√β u and, for the seed's flux,
// half of it), and the same equation for a Timoshenko pipe of cantilever()'s section (the script's
// timoshenko_frequencies), first three Im λ.
struct FlowRow {
  double mu_v;
  std::array<double, 3> seed, zhai, euler_bernoulli, euler_bernoulli_half_coriolis, timoshenko;
};
inline constexpr std::array<FlowRow, 4> kTable31Flow{{
    {0.00, {3.51, 21.98, 61.03}, {3.51, 21.94, 61.28}, {3.5160, 22.0345, 61.6972}, {3.5160, 22.0345, 61.6972},
     {3.5145, 21.9695, 61.2662}},
    {0.27, {3.39, 21.88, 61.03}, {3.46, 21.91, 61.25}, {3.5022, 22.0150, 61.6726}, {3.5192, 22.0131, 61.6707},
     {3.5006, 21.9498, 61.2413}},
    {0.81, {3.39, 21.75, 61.03}, {3.00, 21.61, 60.97}, {3.3893, 21.8585, 61.4758}, {3.5459, 21.8412, 61.4584},
     {3.3876, 21.7928, 61.0424}},
    {1.35, {3.82, 21.00, 60.30}, {1.79, 21.01, 60.42}, {3.1551, 21.5449, 61.0814}, {3.6040, 21.4932, 61.0319},
     {3.1532, 21.4781, 60.6438}},
}};

// Seed Table 3.1, left half (μ_A = 3.9e3, μ_m = 0, μ_V = 0): μ_Ω and the seed's combined model,
// Yoon and Son [94], and the rotating Euler–Bernoulli cantilever (scripts/pipe_linear_theory.py)
// out of the plane of rotation (flap) and in it (lead-lag). 0 = not given.
struct RotationRow {
  double mu_omega;
  std::array<double, 3> seed, yoon_son, flap, lead_lag;
};
inline constexpr std::array<RotationRow, 4> kTable31Rotation{{
    {0.0, {3.49, 21.49, 59.53}, {3.34, 22.02, 0.0}, {3.5161, 22.0345, 61.6972}, {3.5161, 22.0345, 61.6972}},
    {1.0, {3.66, 21.78, 59.76}, {3.37, 22.14, 0.0}, {3.6816, 22.1810, 61.8418}, {3.5432, 22.1585, 61.8337}},
    {2.0, {4.10, 22.15, 60.14}, {3.44, 22.52, 0.0}, {4.1373, 22.6149, 62.2732}, {3.6218, 22.5263, 62.2411}},
    {3.0, {4.69, 22.87, 60.76}, {3.56, 23.12, 0.0}, {4.7973, 23.3203, 62.9850}, {3.7435, 23.1265, 62.9135}},
}};
// The non-rotating row as a Timoshenko beam of cantilever(3.9e3, 0, 0)'s section (the script), and
// ANSYS (20 Timoshenko elements, seed Table 3.1).
inline constexpr std::array<double, 3> kTable31RotationTimoshenko{3.5085, 21.7125, 59.6238};
inline constexpr std::array<double, 3> kTable31RotationAnsys{3.50, 22.49, 58.28};

// Seed §3.5.2: a semi-circular pipe of radius R = 1 m clamped at both ends (centre line from the
// origin along z, bending towards +x: in plane = x–z), the wall and fluid of cantilever(), with
// μ_A = A^p L²/I taken over its length L = πR (the seed does not say which length) and
// μ_V* = V R √(m^f/EI). Pressure zero, inviscid.
PipeDefinition semicircle(double mu_a, double mu_m, double mu_v_star);

// The first `count` in-plane μ_ω* = Im λ R² √(m/EI) of the semicircle about its static equilibrium
// under the flow (the flux turning in the bend pushes it outwards), seed 25 volumes.
std::vector<double> table32_in_plane_frequencies(double mu_a, double mu_m, double mu_v_star, int count, int segments = 25);

// Seed Table 3.2: μ_V* and, per row, the seed's combined model and the reference it was compared
// with: Misra et al. [84] (μ_A = 1e4, μ_m = 0.5, three modes), Jung and Chung [87] (μ_A = 7.36e3,
// μ_m = 0.26, two modes; third entry 0).
struct CurvedRow {
  double mu_v_star;
  std::array<double, 3> seed, reference;
};
inline constexpr std::array<CurvedRow, 5> kTable32Misra{{
    {0.0, {4.79, 9.44, 18.00}, {4.67, 9.84, 18.05}},
    {1.0, {4.70, 9.57, 17.17}, {4.53, 9.88, 17.90}},
    {2.0, {4.45, 9.83, 16.67}, {4.30, 9.92, 17.62}},
    {3.0, {4.08, 10.17, 16.13}, {3.95, 9.77, 17.19}},
    {4.0, {3.68, 10.34, 15.88}, {3.57, 9.65, 17.17}},
}};
inline constexpr std::array<CurvedRow, 5> kTable32JungChung{{
    {0.0, {4.55, 9.00, 0.0}, {4.38, 9.60, 0.0}},
    {1.0, {4.46, 9.04, 0.0}, {4.32, 9.66, 0.0}},
    {2.0, {4.29, 9.17, 0.0}, {4.21, 9.64, 0.0}},
    {3.0, {4.03, 9.30, 0.0}, {4.00, 9.66, 0.0}},
    {4.0, {3.68, 9.34, 0.0}, {3.76, 9.62, 0.0}},
}};

// The seed's time-domain method (§3.5.1): a white-noise lateral force on the tip (along x, normal,
// σ = 1e-3 N, a fixed seed of std::mt19937), `steps` generalized-α steps of dt from rest; returns the
// tip's x displacement after each step [m]. Its power spectrum's peaks are what the seed reports.
std::vector<double> white_noise_tip_response(const PipeDefinition& def, int segments, double dt_s, int steps);

// Cantilever flutter threshold u_cf for β = μ_m = 0.2: Païdoussis vol. 1 §3.5.2 (p. 112, Gregory &
// Païdoussis 1966a, exact analysis) "u_cf ≈ 5.6"; scripts/pipe_linear_theory.py gives 5.5914.
inline constexpr double kFlutterBeta = 0.2;
inline constexpr double kFlutterPublished = 5.6;
inline constexpr double kFlutterEulerBernoulli = 5.5914;

// Divergence of pipes held at both ends (Païdoussis vol. 1 §3.3.6, eqs. 3.90: sin u = 0 pinned,
// clamped likewise): u_cd = π pinned-pinned, 2π clamped-clamped, for any β.

// The largest real part of the eigenvalues of the lowest `modes` bending modes, Re λ · L² √((m^f+m^p)/EI),
// of the straight pipe at rest: > 0 once it flutters or diverges.
double largest_growth_rate(const PipeDefinition& def, int segments, int modes);

// The lowest flow μ_V in [lo, hi] at which supported(μ_A, β, μ_V, ends) (or cantilever() for
// ends = free) loses stability, by bisection to `tolerance`; growth above 1e-3 counts as unstable
// (the eigen-solver's noise on repeated pairs is ~1e-4).
double instability_threshold(double mu_a, double beta, EndCondition ends, int segments, double lo, double hi,
                             double tolerance);

}  // namespace fowtsim::beam::pipe_benchmarks
