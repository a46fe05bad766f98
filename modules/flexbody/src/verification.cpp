#include "fowtsim/flexbody/verification.hpp"

#include "fowtsim/flexbody/axial_force.hpp"
#include "fowtsim/flexbody/beam_fem.hpp"
#include "fowtsim/flexbody/harmonic_response.hpp"
#include "fowtsim/flexbody/mixed_fem_rr.hpp"
#include "fowtsim/flexbody/reduction.hpp"
#include "fowtsim/flexbody/station_segment.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace fowtsim::flexbody::verification {

using std::numbers::pi;

BeamStations sec51_beam() { return uniform_beam(kLength, kMassPerLength, kBendingStiffness); }

CosineBeam cosine_beam_closed_forms(double Mt, double g, double Omega, double r) {
  const double L = kLength, EI = kBendingStiffness, m = kMassPerLength, M = m * L;
  const BeamStations stations = sec51_beam();
  const SampledBody body = sample(quadrature_points(stations), {cosine_shape(L)});
  const double Pcr = pi * pi * EI / (4 * L * L);  // massless-beam buckling load (Sec. 5.1)
  CosineBeam c;
  c.Mq = {generalized_mass(body)(0, 0), m * L * (3 * pi - 8) / (2 * pi)};
  c.Kq = {generalized_stiffness(body)(0, 0), EI * pi * pi * pi * pi / (32 * L * L * L)};
  c.top_mass = {geometric_stiffness(body, top_mass_axial_force(Mt, g))(0, 0), -Mt * g * pi * pi / (8 * L)};
  c.top_mass_ratio = {c.top_mass.value / c.Kq.value, -Mt * g / Pcr};
  c.self_weight = {geometric_stiffness(body, self_weight_axial_force(stations, g))(0, 0),
                   M * g * (-pi * pi / (8 * L) + (4 + pi * pi) / (16 * L))};
  c.self_weight_ratio = {c.self_weight.value / c.Kq.value, -(M * g / Pcr) * (0.5 - 2 / (pi * pi))};
  // T = Ω² m [(L² − x²)/2 + r (L − x)]; ∫_0^1 (1 − t²) sin²(πt/2) dt = 1/3 − 1/π².
  c.centrifugal = {geometric_stiffness(body, centrifugal_axial_force(stations, Omega, r))(0, 0),
                   Omega * Omega * m * (L * (pi * pi / 24 - 0.125) + r * (pi * pi / 16 - 0.25))};
  // ∫ m x u_0 = mL² ∫_0^1 t(1 − cos(πt/2)) dt = mL²(1/2 − 2/π + 4/π²), by parts.
  c.first_moment = {mass_first_moment(body)(0), m * L * (1 - 2 / pi)};
  c.axial_moment = {mass_axial_moment(body)(0), m * L * L * (0.5 - 2 / pi + 4 / (pi * pi))};
  return c;
}

Eigen::VectorXd generalized_eigenvalues(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  return Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(A, B, Eigen::EigenvaluesOnly).eigenvalues();
}

std::vector<ShapeFunction> monomial_shapes(int n, double length) {
  std::vector<ShapeFunction> out;
  for (int j = 2; j <= n + 1; ++j) {
    std::array<double, 5> c{};
    c[static_cast<std::size_t>(j - 2)] = 1.0;
    out.push_back(polynomial_shape(c, length));
  }
  return out;
}

double clamped_free_omega(int n, double top_mass_ratio) {
  return std::pow(clamped_free_beta(n, top_mass_ratio) / kLength, 2) * std::sqrt(kBendingStiffness / kMassPerLength);
}

std::vector<Checked> monomial_frequencies(int shapes, int modes) {
  const SampledBody body = sample(quadrature_points(sec51_beam()), monomial_shapes(shapes, kLength));
  const Eigen::VectorXd w2 = generalized_eigenvalues(generalized_stiffness(body), generalized_mass(body));
  std::vector<Checked> out;
  for (int n = 1; n <= modes; ++n) out.push_back({std::sqrt(w2(n - 1)), clamped_free_omega(n)});
  return out;
}

std::vector<Checked> top_mass_mode_frequencies(double mu, int modes) {
  std::vector<ShapeFunction> shapes;
  for (int j = 1; j <= modes; ++j) shapes.push_back(clamped_free_mode(j, kLength, mu));
  const SampledBody body = sample(quadrature_points(sec51_beam()), shapes);
  const Eigen::MatrixXd M = generalized_mass(body) + mu * kMassPerLength * kLength * Eigen::MatrixXd::Ones(modes, modes);
  const Eigen::VectorXd w2 = generalized_eigenvalues(generalized_stiffness(body), M);
  std::vector<Checked> out;
  for (int n = 1; n <= modes; ++n) out.push_back({std::sqrt(w2(n - 1)), clamped_free_omega(n, mu)});
  return out;
}

Buckling column_buckling(int shapes) {
  const double L = kLength, EI = kBendingStiffness;
  const BeamStations stations = sec51_beam();
  const SampledBody body = sample(quadrature_points(stations), monomial_shapes(shapes, L));
  const Eigen::MatrixXd K = generalized_stiffness(body);
  Buckling b;
  b.euler = {generalized_eigenvalues(K, -geometric_stiffness(body, top_mass_axial_force(1.0, 1.0)))(0),
             pi * pi * EI / (4 * L * L)};
  // Unit g: the smallest λ is the critical g.
  const double g_cr = generalized_eigenvalues(K, -geometric_stiffness(body, self_weight_axial_force(stations, 1.0)))(0);
  b.greenhill = g_cr * kMassPerLength * L / (EI / (L * L));
  return b;
}

UniformBeamMatrices welib_uniform_beam(QuadratureRule::Kind kind) {
  const double L = kWelibLength;
  BeamStations s;
  for (int i = 0; i < 30; ++i) {
    s.x.push_back(L * i / 29.0);
    s.m.push_back(kWelibMassPerLength);
    s.EI.push_back(kWelibBendingStiffness);
  }
  const SampledBody body = sample(quadrature_points(s, {kind}),
                                  {clamped_free_mode(1, L), clamped_free_mode(2, L), clamped_free_mode(3, L)});
  return {generalized_mass(body), generalized_stiffness(body), mass_first_moment(body)};
}

MixedErrors mixed_case_errors(const MixedCase& c) {
  const double L = kLength;
  const BeamStations beam = sec51_beam();
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
  const MixedModel mix = c.split > 0 ? couple_rr_body(Ma, Ka, b) : MixedModel{generalized_mass(b), generalized_stiffness(b)};
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(mix.K, mix.M);
  const auto na = static_cast<int>(Ma.rows());

  MixedErrors out;
  for (int k = 0; k < 2; ++k) {
    const int n = 2 * k + 2;
    out.f[k] = std::sqrt(eig.eigenvalues()(n - 1)) / clamped_free_omega(n) - 1;
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

const std::vector<Table1Row>& seed_table1() {
  static const std::vector<Table1Row> rows = {
      {{"RR4", 0.0, 0, -1, 4}, {0.00, 0.00, 0.00, 0.00}},
      {{"FEM50-RR2", 0.5, 50, -1, 2}, {0.02, 1.18, 0.18, 4.80}},
      {{"FEM50-RR4", 0.5, 50, -1, 4}, {-0.01, -0.03, 0.01, 0.22}},
      {{"GY2-RR2", 0.5, 50, 0, 2}, {0.71, 50.08, 0.29, 15.89}},
      {{"GY2-RR4", 0.5, 50, 0, 4}, {0.68, 35.28, 0.32, 18.48}},
      {{"GY2-RR4c (0.4 L)", 0.4, 50, 0, 4}, {0.14, 12.06, 0.07, 9.47}},
      {{"CB2+2-RR4", 0.5, 50, 2, 4}, {-0.01, 0.11, 0.01, 0.23}},
  };
  return rows;
}

double printed_digit_error(double value, double printed, int digits) {
  const double unit = std::pow(10.0, std::floor(std::log10(std::abs(printed))) - (digits - 1));
  return std::abs(value - printed) / (0.5 * unit);
}

double TorsionTube::polar_moment() const {
  return pi / 32 * (std::pow(diameter, 4) - std::pow(diameter - 2 * wall, 4));
}

TorsionModel TorsionTube::model(int shapes) const {
  std::vector<ShapeFunction> s;
  for (int j = 1; j <= shapes; ++j) s.push_back(torsion_sine_shape(j, length));
  return torsion_model(uniform_beam(length, polar_inertia(), torsional_stiffness()), s);
}

namespace {

double omega(const TorsionModel& m, int j) { return std::sqrt(m.K(j, j) / m.M(j, j)); }

std::vector<double> tip_twist(const TorsionTube& tube, const TorsionModel& m, double end_s, double sample_s, double step_s) {
  return harmonic_response(m.M, modal_stiffness_damping(m.M, m.K, tube.zeta), m.K, tube.moment * m.tip,
                           tube.frequency_ratio * omega(m, 0), m.tip, end_s, sample_s, step_s);
}

}  // namespace

TorsionTransient torsion_transient(const TorsionTube& tube, double end_s, double sample_s, double step_s) {
  TorsionTransient out;
  // One shape: the model is the one-DOF system itself.
  {
    const TorsionModel m = tube.model(1);
    const double w1 = omega(m, 0);
    const std::vector<double> y = tip_twist(tube, m, end_s, sample_s, step_s);
    const SingleDofTransient exact(w1, tube.zeta, tube.frequency_ratio * w1, tube.moment / m.K(0, 0));
    for (std::size_t k = 0; k < y.size(); ++k)
      out.one_shape_error = std::max(out.one_shape_error, std::abs(y[k] - exact(static_cast<double>(k) * sample_s)));
  }
  // Four shapes: each shape is a damped mode (M, K, D diagonal), so the exact tip twist is the sum
  // of four one-DOF transients; the seed's one-DOF formula is its first term.
  const TorsionModel m = tube.model(4);
  const double Om = tube.frequency_ratio * omega(m, 0);
  const std::vector<double> y = tip_twist(tube, m, end_s, sample_s, step_s);
  std::vector<SingleDofTransient> modes;
  for (int j = 0; j < 4; ++j) {
    modes.emplace_back(omega(m, j), tube.zeta, Om, tube.moment * m.tip(j) / m.K(j, j));
    if (j > 0) out.omitted_envelope += std::abs(modes.back().A) + std::abs(modes.back().H0);
  }
  double sq = 0.0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    const double t = static_cast<double>(k) * sample_s;
    double sum = 0.0;
    for (int j = 0; j < 4; ++j) sum += m.tip(j) * modes[static_cast<std::size_t>(j)](t);
    out.modal_error = std::max(out.modal_error, std::abs(y[k] - sum));
    out.one_dof_difference = std::max(out.one_dof_difference, std::abs(y[k] - modes[0](t)));
    sq += std::pow(y[k] - modes[0](t), 2);
    out.peak = std::max(out.peak, std::abs(y[k]));
  }
  out.one_dof_rms = std::sqrt(sq / static_cast<double>(y.size()));
  return out;
}

}  // namespace fowtsim::flexbody::verification
