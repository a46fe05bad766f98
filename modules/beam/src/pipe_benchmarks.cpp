#include "fowtsim/beam/pipe_benchmarks.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "fowtsim/beam/modal.hpp"
#include "fowtsim/beam/solvers.hpp"

namespace fowtsim::beam::pipe_benchmarks {
namespace {

constexpr double kLength = 1.0, kModulus = 1e9, kWallDensity = 1000.0, kBoreRatio = 0.8;
// Dimensionless growth rate that counts as unstable: the dense eigen-solver leaves real parts up
// to ~1e-4 on the repeated pairs (two bending planes) of a conservative pipe; a divergence or
// flutter 1e-4 past its threshold grows at ~1e-1.
constexpr double kGrowthNoise = 1e-3;

double bending_stiffness(const PipeDefinition& d) {
  return d.youngs_modulus_pa * M_PI * (std::pow(d.outer_diameter_m, 4) - std::pow(d.inner_diameter_m, 4)) / 64.0;
}
double wall_mass(const PipeDefinition& d) {
  return d.pipe_density_kg_m3 * M_PI * (d.outer_diameter_m * d.outer_diameter_m - d.inner_diameter_m * d.inner_diameter_m) / 4.0;
}
double fluid_mass(const PipeDefinition& d) {
  return d.fluid_density_kg_m3 * M_PI * d.inner_diameter_m * d.inner_diameter_m / 4.0;
}

}  // namespace

PipeDefinition cantilever(double mu_a, double mu_m, double mu_v) {
  PipeDefinition d{ReferenceLine::straight(Vec3::Zero(), Mat3::Identity(), kLength, [](double) { return 0.0; })};
  const double r2 = kBoreRatio * kBoreRatio;
  // μ_A = A L²/I = 16 L² / (D_o² + D²).
  d.outer_diameter_m = std::sqrt(16.0 * kLength * kLength / (mu_a * (1.0 + r2)));
  d.inner_diameter_m = kBoreRatio * d.outer_diameter_m;
  d.youngs_modulus_pa = kModulus;
  d.pipe_density_kg_m3 = kWallDensity;
  // μ_m = ρ^f D² / (ρ^f D² + ρ^p (D_o² − D²)).
  d.fluid_density_kg_m3 = mu_m * (1.0 - r2) * kWallDensity / (r2 * (1.0 - mu_m));
  const double mf = fluid_mass(d);
  d.flow_velocity_m_s = mf > 0.0 ? mu_v / (kLength * std::sqrt(mf / bending_stiffness(d))) : 0.0;
  return d;
}

PipeDefinition supported(double mu_a, double mu_m, double mu_v, EndCondition ends) {
  PipeDefinition d = cantilever(mu_a, mu_m, mu_v);
  d.root_end = ends;
  d.tip_end = ends;
  return d;
}

double dimensionless_frequency(const PipeDefinition& d, double omega) {
  return omega * kLength * kLength * std::sqrt((wall_mass(d) + fluid_mass(d)) / bending_stiffness(d));
}

double rotation_speed_rad_s(const PipeDefinition& d, double mu_omega) {
  return mu_omega / (kLength * kLength * std::sqrt(wall_mass(d) / bending_stiffness(d)));
}

std::vector<double> bending_frequencies(const BeamModel& model, const PipeDefinition& def, const BeamInput& input,
                                        const BeamState& state, int axis, int count) {
  // Bending along x turns the sections about y, and along y about x. A pipe symmetric about its
  // axis bends alike in both planes: the solver returns any two combinations of a repeated pair,
  // so with axis < 0 a lateral mode counts once.
  std::vector<double> out;
  std::complex<double> previous(-1.0, -1.0);
  for (const DampedMode& m : damped_modes(model, input, state)) {
    const bool lateral = axis < 0 ? m.share(0) + m.share(1) > 0.9 && m.share(3) + m.share(4) > 0.9
                                  : m.share(axis) > 0.5 && m.share(axis == 0 ? 4 : 3) > 0.5;
    const bool repeated = std::abs(m.eigenvalue - previous) < 1e-4 * std::abs(m.eigenvalue);
    if (!lateral || m.eigenvalue.imag() <= 0.0) continue;
    previous = m.eigenvalue;
    if (axis < 0 && repeated) continue;
    out.push_back(dimensionless_frequency(def, m.eigenvalue.imag()));
    if (static_cast<int>(out.size()) == count) break;
  }
  return out;
}

std::vector<double> table31_flow_frequencies(double mu_v, bool seed_flux, int segments) {
  PipeDefinition def = cantilever(1.8e4, 0.5035, mu_v);
  def.seed_momentum_flux = seed_flux;
  const BeamModel model = discretise_pipe(def, segments);
  return bending_frequencies(model, def, BeamInput{}, make_state(model), -1, 3);
}

RotatingFrequencies table31_rotating_frequencies(double mu_omega, int count, int segments) {
  const PipeDefinition def = cantilever(3.9e3, 0.0, 0.0);
  const BeamModel model = discretise_pipe(def, segments);
  BeamInput in;
  in.frame.angular_velocity_rad_s = Vec3(0.0, rotation_speed_rad_s(def, mu_omega), 0.0);
  BeamState state = make_state(model);
  if (mu_omega == 0.0) {
    const std::vector<double> f = bending_frequencies(model, def, in, state, -1, count);
    return {f, f};
  }
  solve_static(model, in, state);
  return {bending_frequencies(model, def, in, state, 1, count), bending_frequencies(model, def, in, state, 0, count)};
}

PipeDefinition semicircle(double mu_a, double mu_m, double mu_v_star) {
  // cantilever() sizes the section for μ_A over 1 m; over L = π m the diameters scale by π.
  const PipeDefinition straight = cantilever(mu_a, mu_m, 0.0);
  PipeDefinition d{ReferenceLine::circular_arc(Vec3::Zero(), Mat3::Identity(), 1.0, M_PI)};
  d.outer_diameter_m = M_PI * straight.outer_diameter_m;
  d.inner_diameter_m = M_PI * straight.inner_diameter_m;
  d.youngs_modulus_pa = straight.youngs_modulus_pa;
  d.pipe_density_kg_m3 = straight.pipe_density_kg_m3;
  d.fluid_density_kg_m3 = straight.fluid_density_kg_m3;
  d.root_end = d.tip_end = EndCondition::clamped;
  const double mf = fluid_mass(d);
  d.flow_velocity_m_s = mf > 0.0 ? mu_v_star / std::sqrt(mf / bending_stiffness(d)) : 0.0;  // R = 1
  return d;
}

std::vector<double> table32_in_plane_frequencies(double mu_a, double mu_m, double mu_v_star, int count, int segments) {
  const PipeDefinition def = semicircle(mu_a, mu_m, mu_v_star);
  const BeamModel model = discretise_pipe(def, segments);
  BeamState state = make_state(model);
  solve_static(model, BeamInput{}, state);
  // In plane: the sections turn about y and the centre line stays in the x–z plane.
  std::vector<double> out;
  for (const DampedMode& m : damped_modes(model, BeamInput{}, state)) {
    if (m.share(4) > 0.5 && m.share(1) < 0.5 && m.eigenvalue.imag() > 0.0)
      out.push_back(dimensionless_frequency(def, m.eigenvalue.imag()));  // L = R = 1
    if (static_cast<int>(out.size()) == count) break;
  }
  return out;
}

std::vector<double> white_noise_tip_response(const PipeDefinition& def, int segments, double dt_s, int steps) {
  const BeamModel model = discretise_pipe(def, segments);
  BeamState state = make_state(model);
  DynamicStepper stepper(model, DynamicOptions{});
  std::mt19937 random(7);
  std::normal_distribution<double> force_n(0.0, 1e-3);
  BeamInput in;
  std::vector<double> tip;
  tip.reserve(steps);
  for (int i = 0; i < steps; ++i) {
    in.tip_load(0) = force_n(random);
    stepper.step(in, dt_s, state);
    tip.push_back(state.position_m.back().x() - model.nodes.back().position_m.x());
  }
  return tip;
}

double largest_growth_rate(const PipeDefinition& def, int segments, int modes) {
  const BeamModel model = discretise_pipe(def, segments);
  const BeamState state = make_state(model);
  double largest = -1e300;
  int seen = 0;
  for (const DampedMode& m : damped_modes(model, BeamInput{}, state)) {
    if (m.share(0) + m.share(1) < 0.9 || m.share(3) + m.share(4) < 0.9) continue;  // lateral bending
    largest = std::max(largest, dimensionless_frequency(def, m.eigenvalue.real()));
    if (++seen == modes) break;
  }
  return largest;
}

double instability_threshold(double mu_a, double beta, EndCondition ends, int segments, double lo, double hi,
                             double tolerance) {
  while (hi - lo > tolerance) {
    const double mid = 0.5 * (lo + hi);
    const PipeDefinition def = ends == EndCondition::free ? cantilever(mu_a, beta, mid) : supported(mu_a, beta, mid, ends);
    (largest_growth_rate(def, segments, 4) < kGrowthNoise ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace fowtsim::beam::pipe_benchmarks
