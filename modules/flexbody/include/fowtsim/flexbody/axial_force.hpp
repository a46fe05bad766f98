#pragma once
// Axial force distributions T(x) [N] for the geometric stiffness of eq. 26, with the seed's sign
// convention (Sec. 4.2): T > 0 is tension and stiffens (restoring, eq. 23), T < 0 softens.
// Each distribution includes any load applied at the tip (T(L) = T_L, the seed's T_{n_x}).
#include "fowtsim/flexbody/stations.hpp"

#include <functional>

namespace fowtsim::flexbody {

using AxialForce = std::function<double(double x)>;

// Weight of a top mass on a vertical body: T = −M_t g, constant (Sec. 5.1, K_MT).
AxialForce top_mass_axial_force(double top_mass, double gravity);

// Self-weight of a vertical body: T(x) = −g ∫_x^L m dx' (Sec. 5.1, K_SW; p_x = −mg in eq. 21).
AxialForce self_weight_axial_force(const BeamStations& stations, double gravity);

// Centrifugal load on a body spinning at Ω about an axis normal to it through x = −root_radius
// (a blade, Sec. 5.2): T(x) = Ω² ∫_x^L m(s) (root_radius + s) ds.
AxialForce centrifugal_axial_force(const BeamStations& stations, double omega, double root_radius);

}  // namespace fowtsim::flexbody
