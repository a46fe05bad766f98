#pragma once
// Kane's spin-up of the pre-bent beam (seed 002 Sec. 5.4) across two modules: the coupled edge–
// flap–torsion Rayleigh–Ritz body of modules/flexbody (prebent_spinning_beam.hpp) against the MBBT
// beam of modules/beam on the curved reference line, both spun up by the same prescribed hub
// motion. Shared by driver/tests/prebent_spin_up_tests.cpp and `fowtsim verify flexbody`.
#include "fowtsim/flexbody/prebent_spinning_beam.hpp"

namespace fowtsim::driver {

// Tip histories every 20 ms over 0–30 s (15 s spin-up, 15 s at Ω_s = 6 rad/s): edge u_y(L) [m],
// flap z(L) [m] (−0.5 at rest), torsion φ(L) [rad] about the tip's undeformed tangent (positive
// root → tip). MBBT: 30 segments, Δt = 5 ms (Kane's straight-beam setting, kane_spin_up.hpp),
// EA 2e7 N, GJ 200 N·m², EI 14 kN·m² both ways, shear GA 1e7 N (stiff: the seed gives none),
// mass 1.2 kg/m on the line, section inertia j_G = 2 kg·m about the tangent and 0 about the
// bending axes (the RR body is Euler–Bernoulli; the segments keep their rod inertia m Δs²/12).
// RR: 3 edge, 3 flap, 3 torsion shapes, RK4 at 1 ms.
struct PrebentSpinUp {
  flexbody::PrebentTipHistory mbbt, rr;
};
PrebentSpinUp prebent_spin_up_histories();

// The figures the test and the verify rows check (RMS over the grid, 0–30 s).
struct PrebentComparison {
  double edge_rms_over_max;          // RMS(RR − MBBT) / max |MBBT| of the edge tip
  double flap_final_mbbt, flap_final_rr;  // z(L) at 30 s [m]
  double flap_max_difference;        // max |RR − MBBT| of z(L) [m]
  double torsion_min_mbbt, torsion_min_rr, torsion_max_mbbt, torsion_max_rr;  // extremes of φ(L) [rad]
  double torsion_rms_over_max;       // RMS(RR − MBBT) / max |MBBT| of φ(L)
};
PrebentComparison compare(const PrebentSpinUp& h);

}  // namespace fowtsim::driver
