#pragma once
// A slender offshore structure as strips (seed 004, slide "Development Strategy": "structure
// modelled as strips to allow non-uniform structure design") with shape functions, assembled into
// M q̈ + C q̇ + K q = Q (slide "Equation of Motion for Linear Vibration"). x runs along the body
// from its bottom end (x = 0) to its top (x = L); v(x, t) is the transverse deflection in the wave
// direction. The Model is immutable after make_model: strip data, sampled shapes, matrices.
#include "fowtsim/core/types.hpp"
#include "fowtsim/slender/shape_functions.hpp"

#include <vector>

namespace fowtsim::slender {

struct Strip {
  double length_m;                     // Δx, strip length along the body [m]
  double outer_diameter_m;             // D, hydrodynamic and bending diameter [m]
  double inner_diameter_m;             // bore [m], 0 for a solid section
  double density_kg_m3;                // wall material density [kg/m³]
  double youngs_modulus_Pa;            // E [Pa]; EI = E π(D⁴ − Dᵢ⁴)/64
  double drag_coefficient;             // Cd [-] on D
  double added_mass_coefficient;       // Ca [-]; Cm = 1 + Ca for the wave inertia force
  double contents_density_kg_m3 = 0.0; // fluid in the bore [kg/m³] (adds mass and weight)
};

enum class Support { Free, Pinned, Clamped };  // essential conditions the shapes must satisfy

struct EndSprings {
  double translational_N_m = 0.0;      // k on v at the end (mooring, tensioner stroke) [N/m]
  double rotational_N_m_rad = 0.0;     // k on v' at the end [N·m/rad]
};

// A spring attached at one point along the body (a fairlead's mooring stiffness, a guide).
struct PointSpring {
  double x_m = 0.0;                    // where, from the bottom end [m], 0 <= x <= L
  double translational_N_m = 0.0;      // k on v(x) [N/m]
  double rotational_N_m_rad = 0.0;     // k_θ on v'(x) [N·m/rad]
};

// A lumped mass at one point (the RNA on a tower, a buoy, a joint): translation and rotary inertia.
struct PointMass {
  double x_m = 0.0;                    // where, from the bottom end [m], 0 <= x <= L
  double mass_kg = 0.0;                // on v̈(x) [kg]
  double rotary_inertia_kg_m2 = 0.0;   // on v̈'(x), about the axis normal to the bending plane [kg·m²]
};

struct Environment {
  double water_density_kg_m3 = 1025.0;
  double gravity_m_s2 = 9.81;
  double still_water_level_m = 0.0;    // x of the still water surface [m]; strips above are dry
  double water_depth_m = 0.0;          // surface to seabed [m]; <= 0 means deep water
};

struct BodyDescription {
  std::vector<Strip> strips;           // bottom to top; their lengths add up to L
  Support bottom_support = Support::Free;
  Support top_support = Support::Free;
  EndSprings bottom_springs;
  EndSprings top_springs;
  std::vector<PointSpring> point_springs;  // along the body (springs at the ends may also be given here)
  std::vector<PointMass> point_masses;
  double top_tension_N = 0.0;          // effective tension at x = L [N] (tensioner; 0 for a free top)
  double rayleigh_mass_per_s = 0.0;    // α of C = αM + βK [1/s]
  double rayleigh_stiffness_s = 0.0;   // β of C = αM + βK [s]
  std::vector<ShapeFunction> shapes;   // φ_1 … φ_n
};

// Per-strip data, all vectors of size N (strips), evaluated at strip midpoints.
struct StripTable {
  VecX x_m;                    // midpoint [m]
  VecX dx_m;                   // Δx [m]
  VecX diameter_m;             // D [m]
  VecX section_modulus_m3;     // Z = I/(D/2) [m³]: stress = M/Z
  VecX bending_stiffness_N_m2; // EI [N·m²]
  VecX structural_mass_kg_m;   // wall + contents [kg/m]
  VecX mass_kg_m;              // structural + added ρ Ca A f [kg/m]: the mass of M
  VecX submerged_fraction;     // f ∈ [0, 1], wet share of the strip [-]
  VecX x_kinematics_m;         // where wave kinematics are taken: centre of the wet part [m]
  VecX inertia_coefficient_kg_m; // ρ Cm A f: wave inertia force per length = this × u̇ [kg/m]
  VecX drag_factor_kg_m2;      // ½ ρ Cd D f: drag per length = this × |u_r| u_r [kg/m²]
  VecX effective_tension_N;    // T_eff at the midpoint [N] (tension > 0)
};

struct Model {
  BodyDescription body;        // as given
  Environment environment;     // as given
  double length_m;             // L [m]
  StripTable strips;
  MatX phi;                    // Φ (N × n): φ_m at strip midpoints
  MatX phi_slope;              // Φ' (N × n) [1/m]
  MatX phi_curvature;          // Φ'' (N × n) [1/m²]
  VecX phi_top, phi_top_slope; // φ_m(L), φ_m'(L) (n): end springs, inertia relief
  VecX phi_bottom, phi_bottom_slope; // φ_m(0), φ_m'(0) (n)
  MatX phi_springs, phi_springs_slope; // φ_m, φ_m' at the point springs (springs × n)
  MatX phi_masses, phi_masses_slope;   // φ_m, φ_m' at the point masses (masses × n)
  MatX mass;                   // M = Φᵀ diag(m Δx) Φ + point masses (n × n) [kg]
  MatX stiffness;              // K = Φ''ᵀ diag(EI Δx) Φ'' + Φ'ᵀ diag(T_eff Δx) Φ' + end and point springs [N/m]
  MatX structural_damping;     // C = αM + βK (n × n) [N·s/m]
};

// Builds the model; throws InputError on bad strips, on shapes that break an essential condition,
// on points off the body, and on a clamped top above a supported bottom (the inertia-relief
// moment then sums from the free bottom end; with supports at both ends and a clamped one it
// would need a reaction that statics does not give).
Model make_model(const BodyDescription& body, const Environment& environment);

// T_eff(x) at the strip midpoints: T_top + ∫_x^L (buoyancy − weight) per length (equilibrium of
// the part above x; a point mass's weight on the sections below it). A clamped top (a hanging
// body, free bottom): ∫_0^x (weight − buoyancy), the part below x, point masses below included. The seed's slide "Development Strategy" writes T_eff = (ρ_f − ρ_s) g A x for a
// uniform body with a free bottom; this is the same balance for any strips and a top tension.
VecX effective_tension(const BodyDescription& body, const Environment& environment,
                       const VecX& structural_mass_kg_m, const VecX& submerged_fraction);

}  // namespace fowtsim::slender
