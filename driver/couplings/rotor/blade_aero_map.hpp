#pragma once
// Between the aerodynamic nodes of a blade table and the finite volumes of an MBBT blade, which
// need not coincide (issue 12 item 3):
//  * place: each aero node at the deflected position and orientation of the blade (twist
//    deflection included) with its structural velocity, from the beam state interpolated at the
//    node's span;
//  * distribute: the aero loads per unit span (piecewise linear between aero nodes, as the aero
//    module integrates its rotor resultant) onto the beam's segments, conserving force and moment
//    exactly: each segment gets the integral of the force over its span and the integral of
//    (x(s) − x_n) × f(s) + m(s) about its node, by 2-point Gauss on every piece between
//    breakpoints (exact: the integrands are at most quadratic in s).
// Geometry in the pitched root frame f of the blade (flexible_rotor.hpp). The aero node's
// offsets from the pitch axis (BlCrvAC, BlSwpAC) are taken fixed in f, i.e. they pitch with the
// blade (the rigid-rotor placement keeps them in the unpitched frame; the two differ by a
// rotation of ≤ 0.6 m offsets by the pitch angle). Spans are measured along the beam's arclength.
#include <vector>

#include <Eigen/Geometry>

#include "fowtsim/aero/aero.hpp"
#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"

namespace fowtsim::driver {

struct BladeFrame;

class BladeAeroMap {
 public:
  // precone_rad in the aero convention (+ upwind), hub radius from the structure.
  BladeAeroMap(const aero::Params& aero, const beam::BeamModel& blade, double precone_rad, double hub_radius_m);

  // Aero nodes of blade b (columns b·N … b·N + N − 1 of the aero input), in g.
  void place(int b, const BladeFrame& frame, const beam::BeamState& state, aero::Aero::Input& input) const;
  // Aero loads of blade b (output columns as above, g) → loads per beam segment in f
  // (beam::BeamInput::node_loads: force, and moment about the node minus arm × force since the
  // beam adds the load arm's moment itself).
  void distribute(int b, const BladeFrame& frame, const beam::BeamState& state, const aero::Aero::Output& output,
                  std::vector<Vec6>& node_loads) const;

  int nodes_per_blade() const { return static_cast<int>(aero_nodes_.size()); }

 private:
  // A point along the beam: linear between the stations root (−1), nodes 0 … N−1, tip (N).
  struct Along {
    int lower = -1;     // station index on the root side (−1 = root)
    double fraction = 0.0;
  };
  struct AeroNode {
    double span_m = 0.0;
    Along at;
    Vec3 offset_m = Vec3::Zero();     // undeformed aero centre − reference line point, in f
    Mat3 airfoil_f = Mat3::Identity();  // undeformed airfoil frame in f (T_fa0)
  };
  struct QuadraturePoint {
    int segment = 0;      // beam node the load goes to
    double weight_m = 0;  // ds of the Gauss point
    int aero_lower = 0;   // aero interval
    double aero_fraction = 0.0;
    Along at;             // where it sits along the beam
  };
  Vec3 position(const beam::BeamState& state, const Along& a) const;
  Vec3 velocity(const beam::BeamState& state, const Along& a) const;
  Vec3 angular_velocity(const beam::BeamState& state, const Along& a) const;  // relative to f, in f
  // The deformation rotation R R0ᵀ of every node of a state, once per call of place/distribute
  // (workspace: sized at construction, no allocation).
  void node_deformations(const beam::BeamState& state) const;
  Mat3 deformation(const Along& a) const;  // interpolated from node_deformations()
  Along along(double s) const;

  const beam::BeamModel& blade_;
  std::vector<double> station_s_;          // arclength of root, nodes, tip
  std::vector<AeroNode> aero_nodes_;
  std::vector<QuadraturePoint> quadrature_;
  mutable std::vector<Mat3> node_deformation_;
  mutable Eigen::Matrix3Xd force_f_, moment_f_;  // distribute: one blade's aero loads per unit span in f
};

}  // namespace fowtsim::driver
