#pragma once
// Benchmark beams in a rotating floating frame (issue 3): the rotating straight beam of seed 000
// §2.5.3 and Kane's spin-up beam of seed 002 §5.2, with the loads and frame kinematics that drive
// them and, for Kane's beam, the seed-002 Rayleigh–Ritz reference response.
//
// Axis mapping. Both seeds lay the beam along x; our local axis 3 is the beam axis (BeamDyn's
// convention, reference_line.hpp). Both beams are therefore built with the reference line along
// the floating frame's x axis, local axes (1, 2, 3) = f's (y, z, x): frame0 = [e_y e_z e_x], a
// proper rotation (cyclic permutation). All results in f are then directly in the seeds' (x, y, z).
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"

namespace fowtsim::beam::benchmarks {

// ---- Seed 000 §2.5.3: rotating straight beam -------------------------------------------------
// Steel cantilever 10 m long, 0.5 m high (along y, the load direction) × 0.25 m wide (along z),
// E = 200 GPa, G = 79.3 GPa, ρ = 7850 kg/m³ ("same material properties as in Section 2.5.1",
// including that section's stiffness damping 1e-6 s). The root is clamped at the origin of f,
// which spins about its y axis at Ω_y = 10 rad/s. Loads: static tip force 5000 kN in −y plus the
// distributed w_y(t) = W sin(ωt), W = −48.13 kN/m (five times the beam's weight per length),
// ω = 25.6 rad/s (the first flapwise natural frequency of the non-rotating beam).
// Section (local 1 = y, local 2 = z): A = 0.125 m², EI1 = E·0.5·0.25³/12 (bending about y, i.e.
// deflection along z, the soft direction), EI2 = E·0.25·0.5³/12 (deflection along y), shear
// factor 5/6, Saint-Venant torsion J = 0.229·0.5·0.25³ (aspect ratio 2), rotary inertia ρI.
BeamDefinition rotating_steel_beam();
inline constexpr double kRotatingBeamLength = 10.0;              // [m]
inline constexpr double kRotatingBeamSpin = 10.0;                // Ω_y [rad/s]
inline constexpr double kRotatingBeamTipForce = -5.0e6;          // F_y at the tip [N]
inline constexpr double kRotatingBeamLoadAmplitude = -48.13e3;   // W [N/m]
inline constexpr double kRotatingBeamLoadFrequency = 25.6;       // ω [rad/s]

// The §2.5.3 input at time t (sample it at DynamicStepper::input_time_fraction() of the step): frame spinning at
// spin_rad_s about f's y (origin on the axis, no gravity), tip force kRotatingBeamTipForce along
// y, and W sin(ωt)·Δs_n along y on every segment n. spin_rad_s = 0 gives the non-rotating case.
BeamInput rotating_beam_input(const BeamModel& model, double time_s,
                              double spin_rad_s = kRotatingBeamSpin);

// ---- Seed 002 §5.2: Kane's spin-up beam ------------------------------------------------------
// L = 10 m, EI = 14 kN·m², m = 1.2 kg/m (seed 002), clamped at the hub axis (the seed gives no
// hub radius) and spun up about f's z axis, so the in-plane (edgewise) deflection is along f's y.
// The seed models the beam as inextensible Euler–Bernoulli and gives no other property; we use
// the section these numbers come from in Kane, Ryan & Banerjee (1987, seed 002 ref. [17]):
// E = 70 GPa, A = 4e-4 m², I = 2e-7 m⁴, ρ = 3000 kg/m³, i.e. EA = 2.8e7 N and rotary inertia
// ρI = 6e-4 kg·m per bending axis (1.2e-3 polar); shear GA = 1e7 N and torsion GJ = 14 kN·m² are
// not given and are chosen stiff / irrelevant (the planar response neither shears nor twists
// measurably: EI/(GA L²) = 1.4e-5). Both bending stiffnesses are EI. No damping.
BeamDefinition kane_beam();
inline constexpr double kKaneLength = 10.0;             // [m]
inline constexpr double kKaneBendingStiffness = 14.0e3;  // EI [N·m²]
inline constexpr double kKaneMassPerLength = 1.2;        // m [kg/m]
inline constexpr double kKaneSpinUpTime = 15.0;          // end of the spin-up [s]

// Prescribed hub motion (seed 002 §5.2): θ̈ = 0.4 (1 − cos(π t/7.5)) rad/s² for 0 ≤ t < 15 s,
// 0 afterwards, starting from rest; θ̇ reaches 6 rad/s at 15 s.
double kane_hub_acceleration(double time_s);  // θ̈ [rad/s²]
double kane_hub_rate(double time_s);          // θ̇ [rad/s]

// Frame kinematics of the root frame at time t: Ω = θ̇ e_z, Ω̇ = θ̈ e_z, origin on the axis.
FrameKinematics kane_frame(double time_s);

// Reference: seed 002's Rayleigh–Ritz model of the same beam (§4.2, §5.2), small deflection v(x, t)
// along y in the rotating frame, v = Σ q_j φ_j(x) with the clamped-free modes of eq. 32
// (M_t = 0) as shape functions:
//   M q̈ + [K + θ̇² (K_T − M)] q = −θ̈ f,    M_ij = ∫ m φ_i φ_j,  K_ij = ∫ EI φ_i'' φ_j'',
//   K_T,ij = ∫ T̂ φ_i' φ_j' with the centrifugal tension per θ̇², T̂(x) = m (L² − x²)/2 (eq. 26),
//   f_i = ∫ m x φ_i;
// the −θ̇² M term is the in-plane centrifugal softening, −θ̈ f the Euler (tangential inertia) load.
// With geometric_stiffening = false K_T is omitted — the uncorrected linear model that the seed
// reports as diverging. Integrated from rest by classical RK4 with steps ≤ 1 ms; returns the tip
// deflection v(L) [m] at t = k·sample_s, k = 0 … round(end_s/sample_s).
std::vector<double> kane_rayleigh_ritz_tip(double end_s, double sample_s, int modes,
                                           bool geometric_stiffening = true);

}  // namespace fowtsim::beam::benchmarks
