#pragma once
// Fluid flowing inside the beam: the pipe conveying fluid of seed 000 Ch. 3, as data of the
// discretised model (BeamModel::flow). The pipe is the MBBT beam whose control volumes also hold
// the fluid (seed §3.2.6, eq. 3.15): the beam's mass per length is that of pipe and fluid together
// (m^p + m^f, bending inertia of both, torsional inertia of the pipe only, eq. 3.16) and the flow
// adds, per finite volume (src/flow_terms.hpp has the formulas):
//   - the fluid's axial mass does not follow the pipe (eq. 3.11: the flow rate is fixed), mass
//     −m^f t tᵀ (eq. 3.48, term −m^f T (e1 e1ᵀ) ü*);
//   - the rate of the fluid's relative momentum m^f V t (eq. 3.48, −m^f V T ẽ1 θ̇*) and its Coriolis
//     load in a rotating frame 2 m^f Ω × V t;
//   - the momentum flux and pressure at each face, a compressive resultant (p A^f + m^f V²) along
//     the section axis (eqs. 3.21, 3.48), plus the flux of the pipe's own velocity carried by the
//     flow, m^f V (I − 2 t tᵀ) u̇ at the face (see "Departure" below);
//   - at a free end the fluid leaves: the jet reaction −(p A^f + m^f V²) t − m^f V (I − 2 t tᵀ) u̇
//     on the last volume, a follower load;
//   - the pressure along the pipe from the fluid's axial momentum balance (eq. 3.47), solved
//     between steps from the base configuration (weak coupling, seed §3.4.2) with Darcy–Weisbach
//     friction.
//
// Departure from the seed: its momentum flux (eq. 3.17) carries only the fluid's velocity relative
// to the pipe, (V − u̇·e) e; Reynolds' transport theorem carries the fluid's whole velocity (in the
// frame the balance is written in), which adds the pipe's velocity u̇ carried at the flow rate and,
// in a rotating frame, a second Ω × V t. Without them the Coriolis force of the flow is half the
// classical 2 M U ∂²w/∂s∂t (Païdoussis, Fluid-Structure Interactions vol. 1, eq. 3.38) and the
// flow's Coriolis load in a rotating frame is half of 2 m^f Ω × V. `seed_momentum_flux = true`
// keeps the seed's form, to reproduce its Table 3.1 trend (README).
namespace fowtsim::beam {

struct InternalFlow {
  double fluid_mass_per_length_kg_m = 0.0;  // m^f = ρ^f A^f [kg/m]
  double flow_area_m2 = 0.0;                // A^f [m²]
  double velocity_m_s = 0.0;                // V: mean flow speed relative to the pipe, + from root to tip [m/s]
  double friction_per_length_n_m = 0.0;     // Darcy–Weisbach wall shear f_D m^f V|V| / (2 D) [N/m], signed as V
  double boundary_pressure_pa = 0.0;        // internal (gauge) pressure at the end named below [Pa]
  bool pressure_at_tip = true;              // true: the pressure is given at the tip; false: at the root
  bool seed_momentum_flux = false;          // true: the seed's eq. 3.17 flux (relative velocity only)
};

}  // namespace fowtsim::beam
