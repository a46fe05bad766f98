#include "fowtsim/beam/benchmarks.hpp"

#include <cmath>

#include "fowtsim/beam/beam_outputs.hpp"

namespace fowtsim::beam::benchmarks {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Rectangular solid section b (axis 1) × h (axis 2): [κGA, κGA, EA, EI1, EI2, GJ] with shear
// factor 5/6 and Saint-Venant torsion constant of a square, J = 0.1406 b⁴ (b = h).
BeamDefinition rectangular(ReferenceLine line, double b, double h, double e, double g, double rho) {
  const double area = b * h;
  const double i1 = b * h * h * h / 12.0, i2 = h * b * b * b / 12.0;
  const double j = 0.1406 * b * b * b * b;
  const Vec6 k = (Vec6() << 5.0 / 6.0 * g * area, 5.0 / 6.0 * g * area, e * area, e * i1, e * i2, g * j).finished();
  const Vec3 inertia(rho * i1, rho * i2, rho * (i1 + i2));
  BeamDefinition def{std::move(line), {}};
  def.stations = {uniform_station(0.0, k, rho * area, inertia), uniform_station(1.0, k, rho * area, inertia)};
  return def;
}

}  // namespace

Station uniform_station(double eta, const Vec6& stiffness, double mass_per_length, const Vec3& rotary_inertia) {
  Station s;
  s.eta = eta;
  s.stiffness = stiffness.asDiagonal();
  s.mass = Mat6::Zero();
  s.mass.topLeftCorner<3, 3>() = mass_per_length * Mat3::Identity();
  s.mass.bottomRightCorner<3, 3>() = rotary_inertia.asDiagonal();
  return s;
}

BeamDefinition rollup_beam() {
  const Vec6 k = (Vec6() << 1e4, 1e4, 1e4, kRollupBendingStiffness, kRollupBendingStiffness, 2.0).finished();
  BeamDefinition def{ReferenceLine::straight(Vec3::Zero(), Mat3::Identity(), kRollupLength,
                                             [](double) { return 0.0; }),
                     {}};
  def.stations = {uniform_station(0.0, k, 1.0, Vec3(0.1, 0.1, 0.2)), uniform_station(1.0, k, 1.0, Vec3(0.1, 0.1, 0.2))};
  return def;
}

Vec3 rollup_exact_position(double s, double moment_x, double bending_stiffness) {
  const double kappa = moment_x / bending_stiffness;
  if (std::abs(kappa * s) < 1e-12) return Vec3(0.0, 0.0, s);
  return Vec3(0.0, -(1.0 - std::cos(kappa * s)) / kappa, std::sin(kappa * s) / kappa);
}

double rollup_rmse(int segments) {
  const BeamModel model = discretise(rollup_beam(), segments);
  BeamState state = make_state(model);
  BeamInput in;
  const double moment = 2.0 * kPi * kRollupBendingStiffness / kRollupLength;
  in.tip_load[3] = moment;
  StaticOptions opt;
  opt.load_steps = 8;  // a full turn: eighths keep each Newton start near its solution
  solve_static(model, in, state, opt);
  double sum = 0.0;
  for (int n = 0; n < segments; ++n)
    sum += (state.position_m[n] - rollup_exact_position(model.nodes[n].s_m, moment, kRollupBendingStiffness)).squaredNorm();
  return std::sqrt(sum / segments);
}

Vec3 curved_beam_tip_seed_axes(int segments, double force_N) {
  const BeamModel model = discretise(curved_beam(), segments);
  BeamState state = make_state(model);
  BeamInput in;
  in.tip_load[1] = force_N;
  StaticOptions opt;
  opt.load_steps = 4;
  solve_static(model, in, state, opt);
  const Vec3 tip = beam_outputs(model, state).tip_position_m;
  return Vec3(tip.z(), tip.y(), tip.x());
}

BeamDefinition curved_beam() {
  // E·A = 1e7, κGA = 4.16667e6, EI = GJ = 8.33333e5 (the values of the r-test deck).
  BeamDefinition def{ReferenceLine::circular_arc(Vec3::Zero(), Mat3::Identity(), 100.0, kPi / 4.0), {}};
  const Vec6 k = (Vec6() << 4.166667e6, 4.166667e6, 1e7, 8.333333e5, 8.333333e5, 8.333333e5).finished();
  def.stations = {uniform_station(0.0, k, 1.0, Vec3(1.0, 1.0, 2.0) / 12.0), uniform_station(1.0, k, 1.0, Vec3(1.0, 1.0, 2.0) / 12.0)};
  return def;
}

BeamDefinition steel_strip() {
  BeamDefinition def = rectangular(
      ReferenceLine::straight(Vec3::Zero(), Mat3::Identity(), 1.0, [](double) { return 0.0; }),
      0.00331, 0.00331, 200e9, 79.3e9, 7850.0);
  def.stiffness_damping = Vec6::Constant(1e-6);
  return def;
}

double steel_strip_rollup_moment() {
  const double ei = 200e9 * std::pow(0.00331, 4) / 12.0;
  return 2.0 * kPi * ei / 1.0;  // κ = M/EI = 2π/L: one full turn
}

}  // namespace fowtsim::beam::benchmarks
