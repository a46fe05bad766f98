#pragma once
// A pipe conveying fluid (seed 000 Ch. 3): a circular tube of one material with an incompressible
// fluid flowing inside, built as the MBBT beam of the pipe and its contents plus the flow terms of
// internal_flow.hpp. Uniform along its length.
#include "fowtsim/beam/beam_model.hpp"

namespace fowtsim::beam {

struct PipeDefinition {
  ReferenceLine line;                   // centre line, local axis 3 along it
  double outer_diameter_m = 0.0;        // D_o [m]
  double inner_diameter_m = 0.0;        // D: flow passage, 0 for a solid rod [m]
  double youngs_modulus_pa = 0.0;       // E [Pa]
  double poisson_ratio = 0.3;           // ν: G = E / (2 (1 + ν)) [-]
  double shear_coefficient = 1.0;       // k: shear stiffness k G A^p; the seed's K uses G A^p (k = 1) [-]
  double pipe_density_kg_m3 = 0.0;      // ρ^p [kg/m³]
  double fluid_density_kg_m3 = 0.0;     // ρ^f, 0 for an empty pipe [kg/m³]
  double flow_velocity_m_s = 0.0;       // V, + from root to tip [m/s]
  double fluid_viscosity_pa_s = 0.0;    // μ^f, 0 for an inviscid fluid (no friction) [Pa·s]
  double wall_roughness_m = 0.0;        // ε: absolute roughness for the Haaland friction factor [m]
  double stiffness_damping_s = 0.0;     // μ_K: damping D = μ_K K (seed §3.4.3) [s]
  EndCondition root_end = EndCondition::clamped;  // clamped or pinned (the flow enters here when V > 0)
  EndCondition tip_end = EndCondition::free;      // free (the fluid leaves as a jet), clamped or pinned
  double boundary_pressure_pa = 0.0;    // internal gauge pressure at the end named below [Pa]
  bool pressure_at_tip = true;          // true: at the tip (the outlet when V > 0); false: at the root
  bool seed_momentum_flux = false;      // the seed's eq. 3.17 flux (internal_flow.hpp), for comparison
};

// Darcy friction factor: 64/Re when laminar (Re < 2300), else the Haaland equation (seed §3.5,
// ref. [145]): 1/√f = −1.8 log10[(ε/D / 3.7)^1.11 + 6.9/Re]. 0 for Re = 0.
double darcy_friction_factor(double reynolds, double relative_roughness);

// The beam of pipe and contents: stiffness diag(kGA, kGA, EA, EI, EI, 2GI) of the wall (seed §3.5
// in our axis order), mass per length ρ^p A^p + ρ^f A^f, rotary inertia ρ^p I + ρ^f I^f about the
// bending axes and ρ^p 2I about the axis (the fluid does not turn with the pipe, eq. 3.16).
BeamDefinition pipe_beam_definition(const PipeDefinition& def);

// The flow data (BeamModel::flow) of the pipe: m^f, A^f, V, wall friction f_D m^f V|V|/(2D).
InternalFlow pipe_flow(const PipeDefinition& def);

// discretise(pipe_beam_definition(def), segments) with flow = pipe_flow(def). Throws InputError
// on a bad definition (naming the field).
BeamModel discretise_pipe(const PipeDefinition& def, int segments);

}  // namespace fowtsim::beam
