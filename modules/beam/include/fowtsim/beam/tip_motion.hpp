#pragma once
// A prescribed motion of a held tip (BeamInput::tip_displacement_m): the top of seed 000 §3.5.3's
// riser, moved by its platform as eqs. 3.66–3.67 say —
//   U_axial(t) = stretch · t/T_r for 0 < t < T_r, stretch after           (eq. 3.66, T_r = 1 s)
//   U_sway(t)  = 0 before t_s, A sin(2π (t − t_s)/T) after              (eq. 3.67, A 5 m, T 10 s, t_s 1 s)
// along the given unit directions in f. Velocities jump where the seed's motion has corners (t = 0,
// T_r and t_s), as the seed prescribes.
#include "fowtsim/core/types.hpp"

namespace fowtsim::beam {

struct RampAndSway {
  double stretch_m = 0.0;         // axial displacement after the ramp [m]
  double stretch_time_s = 1.0;    // T_r: duration of the linear ramp [s]
  double sway_amplitude_m = 0.0;  // A [m]
  double sway_period_s = 10.0;    // T [s]
  double sway_start_s = 1.0;      // t_s [s]
  Vec3 axis = Vec3::UnitZ();              // direction of the stretch, in f (unit)
  Vec3 sway_direction = Vec3::UnitY();    // direction of the sway, in f (unit)

  Vec3 displacement(double t_s) const;    // [m]
  Vec3 velocity(double t_s) const;        // [m/s]; at a corner, the value after it
};

}  // namespace fowtsim::beam
