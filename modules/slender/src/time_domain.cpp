#include "fowtsim/slender/time_domain.hpp"

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rk4.hpp"
#include "fowtsim/slender/bending_moment.hpp"

#include <Eigen/Cholesky>

#include <cmath>
#include <string>

namespace fowtsim::slender {
namespace {

// Modal matrices and the per-strip force, shared by the derivative and the output recovery.
struct ModalSystem {
  const Model& model;
  const Modes& modes;
  const WaveHistory& waves;
  MatX strip_modes;     // ΦΨ (N × ζ): strip velocity per modal velocity
  MatX modal_damping;   // C_b = Ψᵀ C Ψ (ζ × ζ)
  VecX omega2;          // Ω² (ζ)

  // Morison force per length at wave sample k for strip velocities v̇ (N).
  VecX force_per_length(Eigen::Index k, const VecX& strip_velocity) const {
    const StripTable& s = model.strips;
    const VecX relative = waves.velocity_m_s.col(k) - strip_velocity;
    return s.inertia_coefficient_kg_m.cwiseProduct(waves.acceleration_m_s2.col(k)) +
           s.drag_factor_kg_m2.cwiseProduct(relative.cwiseAbs().cwiseProduct(relative));
  }
  VecX modal_acceleration(const VecX& a, const VecX& a_dot, const VecX& force) const {
    return strip_modes.transpose() * force.cwiseProduct(model.strips.dx_m) - modal_damping * a_dot -
           omega2.cwiseProduct(a);
  }
};

}  // namespace

TimeDomainResult simulate(const Model& model, const Modes& modes, const WaveHistory& waves,
                          const TimeDomainOptions& o) {
  const double dt = o.time_step_s, half = 0.5 * dt;
  const auto z = modes.shapes.cols();
  if (std::abs(waves.sample_interval_s - half) > 1e-12 * half || waves.velocity_m_s.cols() < 2 * o.steps + 1 ||
      waves.velocity_m_s.rows() != model.strips.x_m.size())
    throw InputError({"slender.time_domain", std::nullopt, "wave history", "sample the waves at Δt/2 over the run"},
                     "the wave history does not cover " + std::to_string(o.steps) + " steps of " + std::to_string(dt) +
                         " s at half-step samples on every strip");
  const MatX& Psi = modes.shapes;
  const ModalSystem sys{model, modes, waves, model.phi * Psi, Psi.transpose() * model.structural_damping * Psi,
                        modes.omega_rad_s.cwiseAbs2()};
  const bool mode_acceleration = o.recovery == Recovery::ModeAcceleration && z < model.mass.rows();
  Eigen::LLT<MatX> stiffness;
  if (mode_acceleration) {
    stiffness.compute(model.stiffness);
    if (stiffness.info() != Eigen::Success)
      throw InputError({"slender.time_domain", std::nullopt, "K", "add end springs or keep every mode"},
                       "mode acceleration needs K positive definite");
  }
  const auto derivative = [&](double t, const VecX& y) {
    const Eigen::Index k = std::llround(t / half);
    const VecX a = y.head(z), a_dot = y.tail(z);
    VecX dy(2 * z);
    dy << a_dot, sys.modal_acceleration(a, a_dot, sys.force_per_length(k, sys.strip_modes * a_dot));
    return dy;
  };

  const int outputs = o.steps / o.output_every + 1;
  const auto N = model.strips.x_m.size(), n = model.mass.rows();
  TimeDomainResult r{VecX(outputs), MatX(n, outputs), MatX(N, outputs), MatX(N, outputs), MatX(N, outputs)};
  const auto record = [&](int column, int step, const VecX& y) {
    const Eigen::Index k = 2 * step;
    const VecX a = y.head(z), a_dot = y.tail(z);
    const VecX strip_velocity = sys.strip_modes * a_dot;
    const VecX force = sys.force_per_length(k, strip_velocity);
    const VecX a_ddot = sys.modal_acceleration(a, a_dot, force);
    VecX q = Psi * a;
    if (mode_acceleration)  // slide "Solution in Time Domain": q = K⁻¹[Q − MΨä − CΨȧ]
      q = stiffness.solve(model.phi.transpose() * force.cwiseProduct(model.strips.dx_m) -
                          model.mass * (Psi * a_ddot) - model.structural_damping * (Psi * a_dot));
    const VecX load = force - model.strips.mass_kg_m.cwiseProduct(sys.strip_modes * a_ddot +
                                                                   model.body.rayleigh_mass_per_s * strip_velocity);
    r.time_s(column) = step * dt;
    r.q.col(column) = q;
    r.displacement_m.col(column) = model.phi * q;
    r.moment_elastic_N_m.col(column) = elastic_moment<double>(model, q);
    const VecX inertial = Psi * (a_ddot + model.body.rayleigh_mass_per_s * a_dot);  // q̈ + α q̇ for the point masses
    r.moment_inertia_relief_N_m.col(column) = inertia_relief_moment<double>(model, load, q, inertial);
  };

  VecX y = VecX::Zero(2 * z);
  record(0, 0, y);
  for (int step = 1; step <= o.steps; ++step) {
    y = rk4_step(y, (step - 1) * dt, dt, derivative);
    if (!y.allFinite())
      throw NumericalError({"slender.time_domain", step * dt, "modal state z", "reduce the time step"},
                           "non-finite modal state");
    if (step % o.output_every == 0) record(step / o.output_every, step, y);
  }
  return r;
}

}  // namespace fowtsim::slender
