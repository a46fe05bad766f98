#pragma once
// The data of a full-field wind: velocities on a y–z grid at equally spaced times, plus optional
// tower points below it — what a TurbSim .bts file holds (fowtsim::io reads and writes it) and
// what the wind module interpolates (wind::FullField adds the lookup). One type in core, so a
// field passes between the two modules by assignment instead of a field-by-field copy.
#include <vector>

namespace fowtsim {

struct WindGrid {
  int ny = 0;                // grid points across [-]
  int nz = 0;                // grid points vertically [-]
  int n_tower = 0;           // tower points below the grid [-] (0: none)
  int nt = 0;                // time samples of the record [-]
  int nt_held = 0;           // of those, the first held in grid and tower [-]; 0: all nt. A run's own
                             // generated field holds only the samples the run reaches (the record and
                             // its period are still nt's: the held samples are the same values) ...
  int nt_tail = 0;           // ... and the record's last nt_tail, held after them (points downwind of the
                             // hub read the periodic record's end at the run's start) [-]
  double dy_m = 0.0;         // lateral spacing [m]
  double dz_m = 0.0;         // vertical spacing [m]
  double dt_s = 0.0;         // time step [s]
  double z_bottom_m = 0.0;   // height of the lowest grid row above SWL [m]
  double z_hub_m = 0.0;      // hub (reference) height [m]
  double u_hub_m_s = 0.0;    // mean hub speed = advection speed of Taylor's hypothesis [m/s]
  bool periodic = false;     // true: record wraps (TurbSim format id 8); false: id 7
  std::vector<float> grid;   // (held, nz, ny, 3) u, v, w in the wind frame [m/s]; index ((it·nz+iz)·ny+iy)·3+c
  std::vector<float> tower;  // (held, n_tower, 3) [m/s]; index (it·n_tower+k)·3+c

  int held_steps() const { return nt_held > 0 ? nt_held + nt_tail : nt; }
};

}  // namespace fowtsim
