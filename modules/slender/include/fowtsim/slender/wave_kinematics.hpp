#pragma once
// Linear (Airy) wave kinematics at the strips: the slender body's own wave input. A physics
// module may not include another (DESIGN.md §1), so the waves module's dispersion relation is not
// reachable from here; the few lines below are the seed's own "constructWave" step (slide
// "Solution in Time Domain": u = ω a e^{−k z}, k = ω²/g in deep water), extended to finite depth.
// Every solver takes the transfer table as data, so a caller (the engine) may hand in kinematics
// from the waves module, or any other, instead.
#include "fowtsim/core/types.hpp"
#include "fowtsim/slender/model.hpp"

#include <complex>

namespace fowtsim::slender {

using VecXc = Eigen::VectorXcd;  // complex amplitudes, sized at initialisation
using MatXc = Eigen::MatrixXcd;

// k of ω² = g k tanh(k h) [rad/m]; depth_m <= 0 means deep water (k = ω²/g). Newton's method from
// the deep-water value (the residual is convex in k, so the iterates decrease monotonically).
double wave_number(double omega_rad_s, double gravity_m_s2, double depth_m);

// Horizontal particle velocity per unit wave amplitude at each strip's kinematics point (N):
// for a surface elevation η(t) = Re(a e^{iωt}) at the body, u(x, t) = Re(a U(x) e^{iωt}) with
// U = ω cosh(k(h + z))/sinh(k h) (deep water: ω e^{kz}), z = x − x_swl <= 0 the depth below still
// water; zero on dry strips. U is real (u in phase with η; the seed's iω a e^{−kx} takes the
// phase of the horizontal particle displacement instead). The acceleration transfer is iωU.
VecXc velocity_transfer(const Model& model, double omega_rad_s);

// The same for several frequencies: column j for omegas(j) (N × Nf).
MatXc velocity_transfer_table(const Model& model, const VecX& omegas_rad_s);

}  // namespace fowtsim::slender
