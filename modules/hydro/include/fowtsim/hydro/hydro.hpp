#pragma once
// Hydrodynamic and hydrostatic loads on a floating platform made of circular members (seed 000
// §4.2, §4.4.2): Morison strip theory at the instantaneous position and motion of each member,
// nonlinear hydrostatics at the instantaneous position, and the deck's linear extras; optionally
// WAMIT potential flow (potential_flow.hpp: A(∞), the radiation memory, the excitation the driver
// hands in, linear .hst hydrostatics). Without potential flow there is no memory and outputs() is a
// pure function of Params and Input; with it, State is the radiation memory at t_n, advance()
// moves it one platform step, and outputs() at any stage time in [t_n, t_n + ΔT] only reads it.
//
// Coupling with the waves module goes through the driver (modules do not include each other):
//   1. (SurfaceModel::wave_elevation only) waterline_points() → the driver samples the wave
//      elevation there → Input::surface_elevation_m;
//   2. strip_points() → the driver evaluates fluid velocity, acceleration and dynamic pressure at
//      those points → Input::fluid_*;
//   3. (potential flow with excitation) the driver interpolates the precomputed excitation
//      records → Input::wave_excitation;
//   4. outputs() → loads at the reference point and the added-mass matrix; after the platform's
//      step, advance() with the motion at its end.
// The pose handed to outputs() must be the one given to strip_points().
#include <span>
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/core/interface.hpp"
#include "fowtsim/core/types.hpp"
#include "fowtsim/hydro/params.hpp"

namespace fowtsim::hydro {

using Points = Eigen::Matrix<double, 3, Eigen::Dynamic>;  // 3 × n points or vectors, inertial frame g

struct Hydro {
  using Params = hydro::Params;

  // Morison strip theory and hydrostatics carry no memory; potential-flow radiation does.
  struct State {
    RadiationState radiation;  // empty without potential flow
  };

  struct Input {
    // Platform motion: position_m = r_ref (reference point in g), orientation = T_gb,
    // velocity_m_s = ṙ_ref (in g), angular_velocity_rad_s = ω in b (as FrameMotion documents).
    // Accelerations are not read: their loads come back as Output::added_mass.
    FrameMotion platform;
    Points fluid_velocity_m_s;        // (3 × node_count) wave particle velocity at strip_points() [m/s], g
    Points fluid_acceleration_m_s2;   // (3 × node_count) wave particle acceleration [m/s²], g
    VecX dynamic_pressure_Pa;         // (node_count) wave dynamic pressure p − ρ g (−z) [Pa]
    VecX surface_elevation_m;         // (members) wave elevation at waterline_points() [m]; read
                                      // only with SurfaceModel::wave_elevation
    Vec6 wave_excitation = Vec6::Zero();  // first-order potential-flow wave load about r_ref, g [N, N·m];
                                          // read only with potential flow and excitation (the driver
                                          // interpolates it from the sea and the .3 table)
    double time_s = 0.0;              // simulation time [s]: the radiation memory's stage time
  };

  struct Output {
    Vec6 total = Vec6::Zero();        // [F; M] about r_ref, in g [N, N·m]: buoyancy + morison + added_linear
                                      //   + radiation + excitation
    Vec6 buoyancy = Vec6::Zero();     // ρ g V k at the centre of buoyancy [N, N·m]
    Vec6 morison = Vec6::Zero();      // strips + end effects, without the structure-acceleration part [N, N·m]
    Vec6 added_linear = Vec6::Zero(); // F0 − C q − B q̇ − B_quad |q̇| q̇ [N, N·m]
    Vec6 radiation = Vec6::Zero();    // potential flow: −∫ K(τ) q̇(t − τ) dτ [N, N·m] (HydroDyn B1Rdt*)
    Vec6 excitation = Vec6::Zero();   // potential flow: first-order wave excitation [N, N·m] (B1Wvs*)
    // Added mass about r_ref in g: the structure-acceleration part of Morison (and A(∞) of
    // potential flow) is [F; M] = −added_mass · [a_ref; α] (a_ref, α in g). For the solver's mass
    // matrix; not included in any load above.
    Mat6 added_mass = Mat6::Zero();   // [kg, kg·m, kg·m²]
    double submerged_volume_m3 = 0.0;           // V below z = 0 [m³] (linear hydrostatics: V0)
    Vec3 centre_of_buoyancy_m = Vec3::Zero();   // in g [m]; r_ref when V = 0 (linear hydrostatics:
                                                //   r_ref, where ρ g V0 acts)
  };

  // The radiation memory at rest before input.time_s, the platform moving as input.platform then;
  // make_state(params): at rest at t = 0.
  static State make_state(const Params& params, const Input& input);
  static State make_state(const Params& params);
  // Moves the radiation memory from t to t + dt; `input.platform` is the motion at t + dt.
  static void advance(const Params& params, const Input& input, double t, double dt, State& state);
  // Throws NumericalError on a non-finite input or result (never returns NaN).
  static Output outputs(const Params& params, const Input& input, const State& state);
  static std::vector<ChannelInfo> channels(const Params& params);
};

// Field list of the state (core/fields.hpp).
template <class Archive>
void fields(Archive& a, Hydro::State& s) {
  a.io(s.radiation);
}

// An Input sized for params (node_count strip nodes, one elevation per member), at rest.
Hydro::Input make_input(const Params& params);

// Strip-node positions in g for the platform pose (position_m, orientation): member m's strip
// midpoints over the submerged part of its axis, then its end A and end B (node_offset()).
// surface_elevation_m (one per member) is read only with SurfaceModel::wave_elevation.
// out must be 3 × node_count(params). Allocates nothing.
void strip_points(const Params& params, const FrameMotion& platform,
                  const Eigen::Ref<const VecX>& surface_elevation_m, Eigen::Ref<Points> out);

// Where each member's axis meets z = 0 (3 × members): where to sample the wave elevation.
void waterline_points(const Params& params, const FrameMotion& platform, Eigen::Ref<Points> out);

// Current velocity at height z (g) for the current profile [m/s].
Vec3 current_velocity(const CurrentParams& current, double z_m);

// Values of channels(params) in the same order (24, and 12 more with potential flow). As in
// HydroDyn, the total (HydroF·i, HydroM·i) and the radiation load (B1RdtF·i, …) include the
// added-mass reaction −A [a_ref; α] of the platform's acceleration `platform_acceleration`
// ([a_ref; α] in g, as Output::added_mass takes it): all added mass for the total, A(∞) for the
// radiation.
void channel_values(const Params& params, const Hydro::Output& output, const Vec6& platform_acceleration,
                    std::span<double> values);

// q̇ = [ṙ_ref; ω in g] of a platform motion: the velocity the radiation memory takes.
Vec6 generalised_velocity(const FrameMotion& platform);

}  // namespace fowtsim::hydro
