#pragma once
// A piece [a, b] of a station table, re-based so that x = 0 at a: the end values are interpolated
// linearly (as stations.hpp defines the table between stations) and the stations strictly inside
// (a, b) are kept. Used for the FEM elements (exact Gauss integration between kinks of m and EI)
// and for the second body of the mixed FEM–RR model (Sec. 3.4/5.5), whose origin is B.
#include "fowtsim/flexbody/stations.hpp"

namespace fowtsim::flexbody {

// Throws InputError unless 0 <= a < b <= L.
BeamStations segment(const BeamStations& stations, double a, double b);

}  // namespace fowtsim::flexbody
