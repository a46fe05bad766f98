#pragma once
// The inflow seen by the turbine: velocity vectors at inertial points and times, for every model
// of WindParams. Stateless and const: the aero module queries it at its own points each step.
//
// Direction and upflow rotate the whole wind "box" about the reference point (0, 0, z_ref), as
// InflowWind does (OpenFAST docs, "Angles Specified in InflowWind": [U V W] = R(direction) R(upflow)
// [u v w], the box rotated about the hub-height tower centre line). A point p is mapped into the
// wind frame, p_w = Rᵀ (p − p_ref) + p_ref, the wind-frame velocity is evaluated there, and turned
// back, v = R v_w, with
//   R(upflow)    = rotation about +y by −upflow   (u along (cos φ, 0, sin φ): + is up),
//   R(direction) = rotation about +z by −direction (u along (cos θ, −sin θ, 0)).
// Below or at the sea surface (wind-frame z <= 0) the steady, power-law, log and uniform-file models
// return zero. An IEC event (iec_events.hpp) adds its turn θ(t) to the direction (the same rotation
// with direction + θ(t)) and its speed ΔV(y, z, t) along the wind frame's x above the sea surface,
// as a pure function of time: the field stays stateless.
#include <memory>
#include <span>
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/core/types.hpp"
#include "fowtsim/wind/full_field.hpp"
#include "fowtsim/wind/iec_events.hpp"
#include "fowtsim/wind/params.hpp"

namespace fowtsim::wind {

// Mean horizontal speed U(z) [m/s] of the analytic profiles at wind-frame height z [m]:
//   steady: U_ref; power_law: U_ref (z/z_ref)^alpha; log: U_ref ln(z/z0)/ln(z_ref/z0) (0 for z <= z0).
double profile_speed(const WindParams& params, double z_m);

class WindField {
 public:
  // steady/power_law/log/uniform_file: `field` must be null (uniform_file: the rows are in
  // params.uniform). bts/turbulent: `field` holds the grid (from io::read_turbsim_bts or
  // generate_turbulence) and is shared read-only. Validates both.
  explicit WindField(WindParams params, std::shared_ptr<const FullField> field = nullptr);

  // Velocity [m/s, inertial] at inertial point p [m] and time t [s]. No heap allocation. A point a
  // full field does not cover (a deflected tip or a displaced platform beyond the grid's edge)
  // gets the mean profile, u_hub (z/z_hub)^α with the deck's shear exponent, and is counted.
  Vec3 velocity(const Vec3& p_m, double time_s) const;
  // Same for many points; out.size() must equal points.size().
  void velocities(std::span<const Vec3> points_m, double time_s, std::span<Vec3> out_m_s) const;
  // As velocities(), for points that lie below a full field by design (the tower's foot when the
  // field has no tower column): they take the mean profile without being counted as outside.
  void velocities_profile_below(std::span<const Vec3> points_m, double time_s, std::span<Vec3> out_m_s) const;

  const WindParams& params() const { return params_; }
  const FullField* full_field() const { return field_.get(); }
  // Queries that fell outside the full field so far (for a warning in the run summary).
  long outside_queries() const { return outside_queries_; }

 private:
  WindParams params_;
  std::shared_ptr<const FullField> field_;
  Mat3 wind_to_inertial_;  // R above, without an event's turn
  Vec3 reference_point_m_; // (0, 0, z_ref): pivot of the box rotation
  WindEvent event_;        // amplitudes of params.event (type none: adds nothing)
  // What every point shares at one time: the rotation (with the event's turn), the event's ΔV terms
  // and the uniform file's columns interpolated to the time.
  struct Frame {
    Mat3 wind_to_inertial;
    WindEventValue event;
    UniformWindRow uniform;
  };
  Frame frame_at(double time_s) const;
  Vec3 velocity_at(const Vec3& p_m, double time_s, const Frame& frame, bool count_below) const;
  mutable long outside_queries_ = 0;  // a diagnostic count: the velocity itself stays a pure function
};

// The module contract of DESIGN.md §2 for the channel outputs: the inflow has no state of its own
// but the time; outputs are Wind1VelX/Y/Z at params.probe_point_m (OpenFAST names, m/s, inertial).
struct Wind {
  struct Params {
    std::shared_ptr<const WindField> field;  // shared read-only
  };
  struct State {
    double time_s = 0.0;  // time the outputs refer to [s]
  };
  struct Input {};
  struct Output {
    Vec3 probe_velocity_m_s = Vec3::Zero();  // Wind1VelX/Y/Z [m/s], inertial
  };
  static State make_state(const Params& p);
  static void advance(const Params& p, const Input& u, double t, double dt, State& s);
  static Output outputs(const Params& p, const Input& u, const State& s);
  static std::vector<ChannelInfo> channels(const Params& p);
};

}  // namespace fowtsim::wind
