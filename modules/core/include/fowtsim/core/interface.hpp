#pragma once
// The two quantities exchanged across the rigid–flexible interface of the coupled scheme
// (seed 000 §4.4.1): the motion of the floating frame a flexible body is attached to, and the
// loads that body returns at its root.
#include <stdexcept>

#include "fowtsim/core/types.hpp"

namespace fowtsim {

// Motion of a floating frame f (e.g. a blade root on the hub) relative to the inertial frame g.
struct FrameMotion {
  Vec3 position_m = Vec3::Zero();                    // R_g^{OW}: origin of f, in g [m]
  Mat3 orientation = Mat3::Identity();               // T_gf: rotates f-components into g [-]
  Vec3 velocity_m_s = Vec3::Zero();                  // v_g^W [m/s], in g
  Vec3 acceleration_m_s2 = Vec3::Zero();             // a_g^W [m/s²], in g (seed 000 eq. 2.9: a_f = T_fg a_g)
  Vec3 angular_velocity_rad_s = Vec3::Zero();        // Ω_f, in f (eq. 2.2) [rad/s]
  Vec3 angular_acceleration_rad_s2 = Vec3::Zero();   // Ω̇_f, in f (eq. 2.4) [rad/s²]
};

// Motion between two snapshots at fraction s in [0, 1]: vectors linearly, orientation by
// spherical interpolation (stays a rotation). Used by the glue code to feed the fast subsystem
// inside a large step.
FrameMotion interpolate(const FrameMotion& a, const FrameMotion& b, double s);

// Resultant loads that a flexible body exerts on the body it is attached to.
struct RootLoads {
  Vec3 force_N = Vec3::Zero();      // resultant force on the carrying body, in g [N]
  Vec3 moment_N_m = Vec3::Zero();   // resultant moment about point_m, in g [N·m]
  Vec3 point_m = Vec3::Zero();      // application point (root position), in g [m]
};

// Field lists (core/fields.hpp).
template <class Archive>
void fields(Archive& a, FrameMotion& m) {
  a.io(m.position_m, m.orientation, m.velocity_m_s, m.acceleration_m_s2, m.angular_velocity_rad_s,
       m.angular_acceleration_rad_s2);
}
template <class Archive>
void fields(Archive& a, RootLoads& r) {
  a.io(r.force_N, r.moment_N_m, r.point_m);
}

// Loads combine as vectors, field by field (LoadAverager).
inline RootLoads& operator+=(RootLoads& a, const RootLoads& b) {
  a.force_N += b.force_N;
  a.moment_N_m += b.moment_N_m;
  a.point_m += b.point_m;
  return a;
}
inline RootLoads operator*(double w, const RootLoads& a) { return {w * a.force_N, w * a.moment_N_m, w * a.point_m}; }

// Weighted running average of interface loads over the small steps of one large step (seed 000
// §4.4.2: "averaged over each large time-step to apply at the averaged root positions"). With
// weights ½, 1, …, 1, ½ on the n+1 samples of a large step it is the exact time average of the
// piecewise-linear load history (trapezoidal rule). `Load` has `+=` and `double * Load`.
template <class Load>
class LoadAverager {
 public:
  void add(const Load& loads, double weight = 1.0) {
    if (weight_ == 0.0) sum_ = weight * loads;
    else sum_ += weight * loads;
    weight_ += weight;
  }
  Load average() const {  // throws std::logic_error when nothing was added
    if (!(weight_ > 0.0)) throw std::logic_error("LoadAverager::average() with no samples");
    return (1.0 / weight_) * sum_;
  }
  void reset() { weight_ = 0.0; }
  double total_weight() const { return weight_; }

 private:
  Load sum_{};
  double weight_ = 0.0;
};

}  // namespace fowtsim
