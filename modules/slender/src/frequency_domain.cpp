#include "fowtsim/slender/frequency_domain.hpp"

#include "fowtsim/core/error.hpp"
#include "fowtsim/slender/bending_moment.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

namespace fowtsim::slender {
namespace {

using std::numbers::pi;
using namespace std::complex_literals;

// The iterative drag linearisation both solutions share: from the first guess γ, set the drag
// damping c = drag_factor · γ, let `solve` respond to it and return the next γ = G(γ), until γ
// changes by less than the tolerance (relative to its largest value; 0 change when there is no
// drag). The fixed point is found by Anderson mixing of depth one (the secant step on the
// residual f = G(γ) − γ: γ ← G(γ) − θ (G(γ) − G(γ_prev)), θ minimising |f − θ Δf|), which needs
// about half the plain iteration's solves: they converge linearly, by a factor of ≈ 0.14 per
// solve on the riser. The converged γ is the same fixed point to the tolerance.
// Returns the iterations used; NumericalError if it does not converge.
template <class Solve>
int iterate_drag_linearisation(const StripTable& s, VecX gamma, VecX& drag_damping, const FrequencyDomainOptions& options,
                               Solve solve) {
  double change = 1.0;
  int iterations = 0;
  VecX previous_next, previous_residual;
  while (iterations < options.max_iterations && change > options.tolerance) {
    ++iterations;
    drag_damping = s.drag_factor_kg_m2.cwiseProduct(gamma);
    const VecX next = solve();
    const double scale = next.cwiseAbs().maxCoeff();
    const VecX residual = next - gamma;
    change = scale > 0.0 ? residual.cwiseAbs().maxCoeff() / scale : 0.0;
    gamma = next;
    if (iterations > 1) {
      const VecX residual_change = residual - previous_residual;
      const double norm2 = residual_change.squaredNorm();
      if (norm2 > 0.0) gamma = (next - residual_change.dot(residual) / norm2 * (next - previous_next)).cwiseMax(0.0);
    }
    previous_next = next;
    previous_residual = residual;
  }
  if (change > options.tolerance)
    throw NumericalError({"slender.frequency_domain", std::nullopt, "drag linearisation γ",
                          "raise max_iterations or check the drag coefficients"},
                         "γ did not converge in " + std::to_string(options.max_iterations) + " iterations (relative change " +
                             std::to_string(change) + ")");
  return iterations;
}

// Linearised Morison load per length of the flow velocity `flow` (complex amplitude) at ω: the
// inertia term (ρ C_m A) iω u plus the linearised drag c u (the body's own motion enters the
// left-hand side through the drag damping).
VecXc morison_excitation(const StripTable& s, const VecX& drag_damping, double omega, const VecXc& flow) {
  return (1i * omega) * s.inertia_coefficient_kg_m.cast<std::complex<double>>().cwiseProduct(flow) +
         drag_damping.cast<std::complex<double>>().cwiseProduct(flow);
}

// A · B for a real A and a complex B, as two real products (a quarter of a complex product's work).
MatXc real_times(const MatX& a, const MatXc& b) {
  MatXc out(a.rows(), b.cols());
  out.real() = a * b.real();
  out.imag() = a * b.imag();
  return out;
}

// solve_generalised for every frequency of a random sea under one drag damping (the drag
// linearisation's inner loop): what does not change with ω — K⁻¹, the modal damping Ψᵀ C Ψ — is
// formed once per drag damping, and the generalised loads Φᵀ diag(Δx)(iω ρC_mA + c) U of all
// frequencies by two matrix products (the inertia part once per sea), so a frequency costs a
// z × z solve. The same algebra as solve_generalised, reordered.
class RandomSeaSystem {
 public:
  RandomSeaSystem(const Model& model, const Modes& modes, const VecX& omegas, const MatXc& flow, Recovery recovery)
      : model_(model), modes_(modes), omegas_(omegas), flow_(flow),
        weighted_phi_t_(model.phi.transpose() * model.strips.dx_m.asDiagonal()),
        mode_acceleration_(recovery == Recovery::ModeAcceleration && modes.shapes.cols() < model.mass.rows()) {
    const MatX inertia = weighted_phi_t_ * model.strips.inertia_coefficient_kg_m.asDiagonal();
    inertia_load_ = real_times(inertia, flow);
    for (Eigen::Index j = 0; j < omegas.size(); ++j) inertia_load_.col(j) *= 1i * omegas(j);
    if (!mode_acceleration_) return;
    const Eigen::LLT<MatX> stiffness(model.stiffness);
    if (stiffness.info() != Eigen::Success)
      throw InputError({"slender.frequency_domain", std::nullopt, "K", "add end springs or keep every mode"},
                       "mode acceleration needs K positive definite");
    flexibility_ = stiffness.solve(MatX::Identity(model.mass.rows(), model.mass.cols()));
    flexibility_mass_psi_ = flexibility_ * model.mass * modes.shapes;
  }

  // q per unit amplitude at every ω_j (n × Nf) under the drag damping c per strip.
  void solve(const VecX& drag_damping, MatXc& q) {
    const MatX damping = model_.structural_damping + weighted_phi_t_ * drag_damping.asDiagonal() * model_.phi;
    const MatX modal_damping = modes_.shapes.transpose() * damping * modes_.shapes;
    const MatX drag = weighted_phi_t_ * drag_damping.asDiagonal();
    load_ = inertia_load_ + real_times(drag, flow_);
    modal_load_ = real_times(modes_.shapes.transpose(), load_);
    const auto z = modes_.shapes.cols();
    MatXc a(z, omegas_.size());
    MatXc dynamic(z, z);
    Eigen::PartialPivLU<MatXc> lu(z);
    for (Eigen::Index j = 0; j < omegas_.size(); ++j) {
      const double w = omegas_(j);
      dynamic = (1i * w) * modal_damping.cast<std::complex<double>>();
      dynamic.diagonal().array() += (modes_.omega_rad_s.array().square() - w * w).cast<std::complex<double>>();
      lu.compute(dynamic);
      a.col(j) = lu.solve(modal_load_.col(j));
    }
    if (!mode_acceleration_) {
      q = real_times(modes_.shapes, a);
      return;
    }
    // q = K⁻¹[Q + ω² MΨa − iω CΨa].
    const MatX flexibility_damping_psi = flexibility_ * damping * modes_.shapes;
    MatXc inertial = a, viscous = a;
    for (Eigen::Index j = 0; j < omegas_.size(); ++j) {
      inertial.col(j) *= omegas_(j) * omegas_(j);
      viscous.col(j) *= -1i * omegas_(j);
    }
    q = real_times(flexibility_, load_) + real_times(flexibility_mass_psi_, inertial) + real_times(flexibility_damping_psi, viscous);
  }

 private:
  const Model& model_;
  const Modes& modes_;
  const VecX& omegas_;
  const MatXc& flow_;                  // U (N × Nf)
  MatX weighted_phi_t_;                // Φᵀ diag(Δx) (n × N)
  MatXc inertia_load_;                 // Φᵀ diag(Δx ρC_mA) U iω (n × Nf)
  MatXc load_, modal_load_;            // Q (n × Nf), Ψᵀ Q (z × Nf)
  bool mode_acceleration_;
  MatX flexibility_, flexibility_mass_psi_;  // K⁻¹, K⁻¹MΨ
};

}  // namespace

VecXc solve_generalised(const Model& model, const Modes& modes, double omega, const VecXc& force,
                        const VecX& drag_damping, Recovery recovery) {
  const VecX& dx = model.strips.dx_m;
  const MatX damping = model.structural_damping +
                       model.phi.transpose() * drag_damping.cwiseProduct(dx).asDiagonal() * model.phi;
  const VecXc Q = model.phi.transpose() * force.cwiseProduct(dx);
  const MatX& Psi = modes.shapes;
  const auto z = Psi.cols();
  MatXc dynamic = (1i * omega) * (Psi.transpose() * damping * Psi).cast<std::complex<double>>();
  dynamic.diagonal().array() += (modes.omega_rad_s.array().square() - omega * omega).cast<std::complex<double>>();
  const VecXc a = dynamic.partialPivLu().solve(Psi.transpose() * Q);
  if (recovery == Recovery::ModeDisplacement || z == model.mass.rows()) return Psi * a;
  const Eigen::LLT<MatX> stiffness(model.stiffness);
  if (stiffness.info() != Eigen::Success)
    throw InputError({"slender.frequency_domain", std::nullopt, "K", "add end springs or keep every mode"},
                     "mode acceleration needs K positive definite");
  const VecXc Psi_a = Psi * a;
  const VecXc rhs = Q + omega * omega * (model.mass * Psi_a) - 1i * omega * (damping * Psi_a);
  return stiffness.solve(rhs.real()) + 1i * stiffness.solve(rhs.imag());
}

HarmonicResponse solve_harmonic(const Model& model, const Modes& modes, double omega, double amplitude,
                                const VecXc& U, const FrequencyDomainOptions& options) {
  const StripTable& s = model.strips;
  const double harmonic_factor = 8.0 / (3.0 * pi);
  const VecXc flow = amplitude * U;  // u per strip
  HarmonicResponse r{omega, amplitude, {}, {}, {}, {}, 0};
  // First guess: the body at rest.
  r.iterations = iterate_drag_linearisation(s, harmonic_factor * flow.cwiseAbs(), r.drag_damping_N_s_m2, options, [&] {
    // Wave force on strip i: inertia ρCmA u̇ (slide "Wave Force - Morison's Equation") plus the drag
    // on the flow velocity; the −c v̇ part sits in the damping matrix.
    r.excitation_N_m = morison_excitation(s, r.drag_damping_N_s_m2, omega, flow);
    r.q = solve_generalised(model, modes, omega, r.excitation_N_m, r.drag_damping_N_s_m2, options.recovery);
    r.relative_velocity_m_s = flow - (1i * omega) * (model.phi * r.q);
    return VecX(harmonic_factor * r.relative_velocity_m_s.cwiseAbs());
  });
  return r;
}

VecXc harmonic_load_per_length(const Model& model, const HarmonicResponse& r) {
  const StripTable& s = model.strips;
  const double w = r.omega_rad_s;
  const VecXc v = model.phi * r.q;
  const VecXc flow = r.relative_velocity_m_s + (1i * w) * v;  // aU
  const std::complex<double> inertia_factor = w * w - 1i * w * model.body.rayleigh_mass_per_s;
  return (1i * w) * s.inertia_coefficient_kg_m.cast<std::complex<double>>().cwiseProduct(flow) +
         r.drag_damping_N_s_m2.cast<std::complex<double>>().cwiseProduct(r.relative_velocity_m_s) +
         inertia_factor * s.mass_kg_m.cast<std::complex<double>>().cwiseProduct(v);
}

VecXc harmonic_inertial_q(const Model& model, const HarmonicResponse& r) {
  const double w = r.omega_rad_s;
  return (-w * w + 1i * w * model.body.rayleigh_mass_per_s) * r.q;
}

RandomResponse solve_random(const Model& model, const Modes& modes, const VecX& omegas, const VecX& spectrum,
                            double delta_omega, const MatXc& U, const FrequencyDomainOptions& options) {
  const StripTable& s = model.strips;
  const auto N = s.x_m.size(), Nf = omegas.size();
  if (spectrum.size() != Nf || U.cols() != Nf || U.rows() != N)
    throw InputError({"slender.frequency_domain", std::nullopt, "spectrum, velocity table",
                      "give S(ω_j) and U(x_i, ω_j) on the same frequencies"},
                     "sizes differ: " + std::to_string(Nf) + " frequencies, " + std::to_string(spectrum.size()) +
                         " spectral values, table " + std::to_string(U.rows()) + " × " + std::to_string(U.cols()));
  const double random_factor = std::sqrt(8.0 / pi);
  const auto sigma_of = [&](const MatXc& transfer) {  // σ per row of a per-unit-amplitude transfer table
    return VecX((transfer.cwiseAbs2() * (spectrum * delta_omega)).cwiseSqrt());
  };
  RandomResponse r{omegas, delta_omega, spectrum, MatXc(model.mass.rows(), Nf), MatXc(N, Nf), sigma_of(U), {}, 0};
  RandomSeaSystem system(model, modes, omegas, U, options.recovery);
  MatXc velocity(model.mass.rows(), Nf);
  r.iterations = iterate_drag_linearisation(s, random_factor * r.sigma_relative_velocity_m_s, r.drag_damping_N_s_m2, options, [&] {
    system.solve(r.drag_damping_N_s_m2, r.q_transfer);
    for (Eigen::Index j = 0; j < Nf; ++j) velocity.col(j) = (1i * omegas(j)) * r.q_transfer.col(j);
    r.relative_velocity_transfer = U - real_times(model.phi, velocity);
    r.sigma_relative_velocity_m_s = sigma_of(r.relative_velocity_transfer);
    return VecX(random_factor * r.sigma_relative_velocity_m_s);
  });
  return r;
}

MatX displacement_spectrum(const Model& model, const RandomResponse& r) {
  return real_times(model.phi, r.q_transfer).cwiseAbs2() * r.wave_spectrum_m2_s.asDiagonal();
}

// harmonic_load_per_length and inertia_relief_moment at every frequency of the sea; the shape
// products v = Φq and v' = Φ'q of all frequencies as two real matrix products first.
MatX inertia_relief_spectrum(const Model& model, const RandomResponse& r) {
  const StripTable& s = model.strips;
  const MatXc v = real_times(model.phi, r.q_transfer), slope = real_times(model.phi_slope, r.q_transfer);
  MatX spectrum(s.x_m.size(), r.omega_rad_s.size());
  VecXc load(s.x_m.size());
  for (Eigen::Index j = 0; j < r.omega_rad_s.size(); ++j) {
    const double w = r.omega_rad_s(j);
    const std::complex<double> inertia_factor = w * w - 1i * w * model.body.rayleigh_mass_per_s;
    const VecXc q = r.q_transfer.col(j), inertial_q = (-w * w + 1i * w * model.body.rayleigh_mass_per_s) * q;
    for (Eigen::Index i = 0; i < load.size(); ++i) {  // harmonic_load_per_length's terms, strip by strip
      const std::complex<double> relative = r.relative_velocity_transfer(i, j), flow = relative + (1i * w) * v(i, j);
      load(i) = (1i * w) * s.inertia_coefficient_kg_m(i) * flow + r.drag_damping_N_s_m2(i) * relative +
                inertia_factor * s.mass_kg_m(i) * v(i, j);
    }
    spectrum.col(j) = inertia_relief_moment_with_slope<std::complex<double>>(model, load, slope.col(j), q, inertial_q).cwiseAbs2() *
                      r.wave_spectrum_m2_s(j);
  }
  return spectrum;
}

RmsProfiles rms_profiles(const Model& model, const RandomResponse& r) { return rms_profiles(model, r, inertia_relief_spectrum(model, r)); }

RmsProfiles rms_profiles(const Model& model, const RandomResponse& r, const MatX& relief_spectrum) {
  const VecX weight = r.wave_spectrum_m2_s * r.delta_omega_rad_s;
  const MatXc moment = model.strips.bending_stiffness_N_m2.asDiagonal() * real_times(model.phi_curvature, r.q_transfer);
  RmsProfiles p;
  p.displacement_m = (real_times(model.phi, r.q_transfer).cwiseAbs2() * weight).cwiseSqrt();
  p.bending_moment_N_m = (moment.cwiseAbs2() * weight).cwiseSqrt();
  p.stress_Pa = p.bending_moment_N_m.cwiseQuotient(model.strips.section_modulus_m3);
  p.inertia_relief_moment_N_m = ((relief_spectrum * r.delta_omega_rad_s).rowwise().sum()).cwiseSqrt();
  p.inertia_relief_stress_Pa = p.inertia_relief_moment_N_m.cwiseQuotient(model.strips.section_modulus_m3);
  return p;
}

}  // namespace fowtsim::slender
