#include "fowtsim/beam/rotating_benchmarks.hpp"

#include "fowtsim/beam/benchmarks.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "fowtsim/core/error.hpp"

namespace fowtsim::beam::benchmarks {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Local axes (1, 2, 3) = f's (y, z, x): the beam runs along f's x (see the header).
Mat3 beam_along_x() {
  Mat3 frame;
  frame.col(0) = Vec3::UnitY();
  frame.col(1) = Vec3::UnitZ();
  frame.col(2) = Vec3::UnitX();
  return frame;
}

BeamDefinition uniform_beam_along_x(double length_m, const Vec6& stiffness, double mass_per_length,
                                    const Vec3& rotary_inertia) {
  BeamDefinition def{ReferenceLine::straight(Vec3::Zero(), beam_along_x(), length_m,
                                             [](double) { return 0.0; }),
                     {}};
  def.stations = {uniform_station(0.0, stiffness, mass_per_length, rotary_inertia),
                  uniform_station(1.0, stiffness, mass_per_length, rotary_inertia)};
  return def;
}

// Clamped-free bending mode j (0-based) of seed 002 eq. 32 with M_t = 0, at x̃ = x/L: value and
// first and second derivatives with respect to x. β_j solves 1 + cosh β cos β = 0.
struct ModeValue {
  double phi, dphi, ddphi;
};

double clamped_free_root(int j) {
  // Newton on g(β) = 1 + cosh β cos β from the asymptote (2j + 1)π/2 (0-based j).
  double beta = (2.0 * j + 1.0) * kPi / 2.0;
  if (j == 0) beta = 1.875;
  for (int it = 0; it < 50; ++it) {
    const double g = 1.0 + std::cosh(beta) * std::cos(beta);
    const double dg = std::sinh(beta) * std::cos(beta) - std::cosh(beta) * std::sin(beta);
    const double step = g / dg;
    beta -= step;
    if (std::abs(step) < 1e-14 * beta) break;
  }
  return beta;
}

ModeValue clamped_free_mode(double beta, double length_m, double x_m) {
  const double s = std::sinh(beta) + std::sin(beta);
  const double c = std::cosh(beta) + std::cos(beta);
  const double b = beta * x_m / length_m, k = beta / length_m;
  return {s * (std::cosh(b) - std::cos(b)) - c * (std::sinh(b) - std::sin(b)),
          k * (s * (std::sinh(b) + std::sin(b)) - c * (std::cosh(b) - std::cos(b))),
          k * k * (s * (std::cosh(b) + std::cos(b)) - c * (std::sinh(b) + std::sin(b)))};
}

}  // namespace

BeamDefinition rotating_steel_beam() {
  constexpr double e = 200e9, g = 79.3e9, rho = 7850.0;
  constexpr double h = 0.5, b = 0.25;  // extent along local 1 (= f y) and local 2 (= f z) [m]
  const double area = h * b;
  const double i1 = h * b * b * b / 12.0;  // ∫ x2² dA: bending about local 1, deflection along z
  const double i2 = b * h * h * h / 12.0;  // ∫ x1² dA: bending about local 2, deflection along y
  const double j = 0.229 * h * b * b * b;  // Saint-Venant, h/b = 2 (Timoshenko's β = 0.229)
  const double shear = 5.0 / 6.0 * g * area;
  const Vec6 k = (Vec6() << shear, shear, e * area, e * i1, e * i2, g * j).finished();
  BeamDefinition def = uniform_beam_along_x(kRotatingBeamLength, k, rho * area,
                                            Vec3(rho * i1, rho * i2, rho * (i1 + i2)));
  def.stiffness_damping = Vec6::Constant(1e-6);  // seed 000 §2.5.1 solver setting [s]
  return def;
}

BeamInput rotating_beam_input(const BeamModel& model, double time_s, double spin_rad_s) {
  BeamInput in;
  in.frame.angular_velocity_rad_s = Vec3(0.0, spin_rad_s, 0.0);
  in.tip_load[1] = kRotatingBeamTipForce;
  const double w = kRotatingBeamLoadAmplitude * std::sin(kRotatingBeamLoadFrequency * time_s);
  in.node_loads.assign(model.node_count(), Vec6::Zero());
  for (int n = 0; n < model.node_count(); ++n) in.node_loads[n][1] = w * model.nodes[n].segment_length_m;
  return in;
}

BeamDefinition kane_beam() {
  const double ei = kKaneBendingStiffness;
  const Vec6 k = (Vec6() << 1e7, 1e7, 2.8e7, ei, ei, 14.0e3).finished();
  return uniform_beam_along_x(kKaneLength, k, kKaneMassPerLength, Vec3(6e-4, 6e-4, 1.2e-3));
}

double kane_hub_acceleration(double time_s) {
  if (time_s < 0.0 || time_s >= kKaneSpinUpTime) return 0.0;
  return 0.4 * (1.0 - std::cos(kPi * time_s / 7.5));
}

double kane_hub_rate(double time_s) {
  if (time_s <= 0.0) return 0.0;
  const double t = std::min(time_s, kKaneSpinUpTime);
  return 0.4 * t - 0.4 * 7.5 / kPi * std::sin(kPi * t / 7.5);
}

FrameKinematics kane_frame(double time_s) {
  FrameKinematics f;
  f.angular_velocity_rad_s = Vec3(0.0, 0.0, kane_hub_rate(time_s));
  f.angular_acceleration_rad_s2 = Vec3(0.0, 0.0, kane_hub_acceleration(time_s));
  return f;
}

std::vector<double> kane_rayleigh_ritz_tip(double end_s, double sample_s, int modes,
                                           bool geometric_stiffening) {
  if (modes < 1 || !(sample_s > 0.0) || !(end_s >= 0.0))
    throw InputError({"beam.benchmarks", std::nullopt, "kane_rayleigh_ritz_tip",
                      "modes ≥ 1, sample_s > 0, end_s ≥ 0"},
                     "bad Rayleigh–Ritz reference arguments");
  const double length = kKaneLength, m = kKaneMassPerLength, ei = kKaneBendingStiffness;
  std::vector<double> beta(modes);
  for (int j = 0; j < modes; ++j) beta[j] = clamped_free_root(j);

  // Composite Simpson over the span; the integrands are smooth, 4000 intervals make the
  // quadrature error negligible (< 1e-12 relative).
  const int intervals = 4000;
  const double h = length / intervals;
  MatX mass = MatX::Zero(modes, modes), stiff = MatX::Zero(modes, modes), geo = MatX::Zero(modes, modes);
  VecX load = VecX::Zero(modes), tip(modes);
  std::vector<ModeValue> v(modes);
  for (int i = 0; i <= intervals; ++i) {
    const double x = i * h;
    const double w = (i == 0 || i == intervals) ? h / 3.0 : (i % 2 ? 4.0 * h / 3.0 : 2.0 * h / 3.0);
    for (int j = 0; j < modes; ++j) v[j] = clamped_free_mode(beta[j], length, x);
    const double tension = m * (length * length - x * x) / 2.0;  // per θ̇² [N·s²]
    for (int a = 0; a < modes; ++a) {
      load[a] += w * m * x * v[a].phi;
      for (int b = 0; b < modes; ++b) {
        mass(a, b) += w * m * v[a].phi * v[b].phi;
        stiff(a, b) += w * ei * v[a].ddphi * v[b].ddphi;
        geo(a, b) += w * tension * v[a].dphi * v[b].dphi;
      }
    }
  }
  for (int j = 0; j < modes; ++j) tip[j] = clamped_free_mode(beta[j], length, length).phi;
  if (!geometric_stiffening) geo.setZero();
  const Eigen::LLT<MatX> mass_llt(mass);

  // y = [q; q̇]; ẏ = [q̇; M⁻¹(−θ̈ f − (K + θ̇² (K_T − M)) q)].
  auto rate = [&](double t, const VecX& y) {
    const int n = modes;
    const double w = kane_hub_rate(t);
    VecX out(2 * n);
    out.head(n) = y.tail(n);
    out.tail(n) = mass_llt.solve(-kane_hub_acceleration(t) * load -
                                 (stiff + w * w * (geo - mass)) * y.head(n));
    return out;
  };
  const long samples = std::lround(end_s / sample_s);
  const int substeps = std::max(1, static_cast<int>(std::ceil(sample_s / 1e-3 - 1e-9)));
  const double dt = sample_s / substeps;
  VecX y = VecX::Zero(2 * modes);
  std::vector<double> out;
  out.reserve(samples + 1);
  out.push_back(0.0);
  double t = 0.0;
  for (long k = 1; k <= samples; ++k) {
    for (int s = 0; s < substeps; ++s) {
      const VecX k1 = rate(t, y);
      const VecX k2 = rate(t + dt / 2, y + dt / 2 * k1);
      const VecX k3 = rate(t + dt / 2, y + dt / 2 * k2);
      const VecX k4 = rate(t + dt, y + dt * k3);
      y += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      t = (k - 1) * sample_s + (s + 1) * dt;
    }
    out.push_back(tip.dot(y.head(modes)));
  }
  return out;
}

}  // namespace fowtsim::beam::benchmarks
