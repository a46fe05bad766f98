// Outputs: accelerations from the equations of motion, internal loads by inverse dynamics
// (d'Alembert: the load a sub-chain exerts on its support is Σ (F_ext − m a) and Σ (M_ext −
// I α − ω × I ω) plus the moments of those forces), and OpenFAST channels.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/blade_body.hpp"
#include "fowtsim/multibody/tower_body.hpp"

namespace fowtsim::multibody {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr double kRadSToRpm = 30.0 / std::numbers::pi;

// Adds the d'Alembert load of one body (weight − inertia force, − inertia moment) to a running
// [F; M about `point`] in g.
void add_body(double mass, const Mat3& inertia_body, const PointKinematics& cm, const RotationKinematics& rot,
              const GeneralisedVector& udot, const Vec3& gravity, const Vec3& point, Vec6& load) {
  const Mat3 inertia = rot.orientation * inertia_body * rot.orientation.transpose();
  const Vec3& w = rot.angular_velocity_rad_s;
  const Vec3 force = mass * (gravity - acceleration(cm, udot));
  const Vec3 moment = -(inertia * angular_acceleration(rot, udot) + w.cross(inertia * w));
  load.head<3>() += force;
  load.tail<3>() += moment + (cm.position_m - point).cross(force);
}

}  // namespace

Output Multibody::outputs(const Model& model, const AppliedLoads& loads, const State& state, double t) {
  Evaluation eval;
  evaluate(model, state, loads, t, eval);
  const ChainKinematics& k = eval.kinematics;
  const GeneralisedVector& udot = eval.acceleration;
  Output out;
  out.acceleration = udot;
  const Mat3& t_gb = k.base.orientation;
  out.platform_angles_rad = matrix_to_euler123(t_gb);
  out.platform_acceleration_m_s2 = acceleration(k.reference, udot);
  out.platform_angular_acceleration_rad_s2 = angular_acceleration(k.base, udot);

  // Yaw bearing: nacelle + rotor + generator (massless; its moment of inertia only), plus the
  // rotor loads. Generator torque and shaft spring are internal to this sub-chain and cancel.
  const Vec3 gravity(0.0, 0.0, loads.gravity ? -model.params.gravity_m_s2 : 0.0);
  const Vec3& top = k.tower_top.position_m;
  Vec6 yaw = Vec6::Zero();
  add_body(model.nacelle.mass_kg, model.nacelle.inertia_kg_m2, k.nacelle_cm, k.nacelle, udot, gravity, top, yaw);
  add_body(model.rotor.mass_kg, model.rotor.inertia_kg_m2, k.rotor_cm, k.rotor, udot, gravity, top, yaw);
  Mat3 generator_inertia = Mat3::Zero();
  generator_inertia(0, 0) = model.generator_inertia_kg_m2;  // in the shaft frame = generator's orientation
  add_body(0.0, generator_inertia, k.apex, k.generator, udot, gravity, top, yaw);
  Vec3 rotor_force = loads.rotor_force_N;
  Vec3 rotor_moment = loads.rotor_moment_N_m + (k.apex.position_m - top).cross(loads.rotor_force_N);
  for (int i = 0; i < kMaxBlades; ++i) {
    const RootLoads& root = loads.blade_root[i];
    rotor_force += root.force_N;
    rotor_moment += root.moment_N_m + (root.point_m - top).cross(root.force_N);
  }
  if (!loads.rotor_added_mass.isZero(0.0)) {  // the shaft's apparent mass at this acceleration
    Vec6 a;
    a << acceleration(k.apex, udot), angular_acceleration(k.shaft, udot);
    const Vec6 load = -(loads.rotor_added_mass * a);
    rotor_force += load.head<3>();
    rotor_moment += load.tail<3>() + (k.apex.position_m - top).cross(load.head<3>());
  }
  yaw.head<3>() += rotor_force;
  yaw.tail<3>() += rotor_moment;
  // Rayleigh–Ritz blades: each blade's load on the hub at its root — its d'Alembert load and its
  // station loads, about the root — carried to the yaw bearing.
  const RayleighRitzBlades& rr = model.rr_blades;
  for (int b = 0; b < model.blade_count && rr.mode_count > 0; ++b) {
    const FlexibleBodyDAlembert d = flexible_body_dalembert(rr.inertia, blade_motion(model, state, k, b), udot, gravity);
    const Vec3& root = k.blade_root[b].position_m;
    Vec6& load = out.blade_root_loads[b];
    load << d.force_N, d.moment_N_m;
    for (int s = 0; s < loads.blade_station_load_count; ++s) {
      const BladeStationLoad& at = loads.blade_station_loads[b][s];
      load.head<3>() += at.force_N;
      load.tail<3>() += (blade_station_point(model, state, k, b, s).position_m - root).cross(at.force_N) + at.moment_N_m;
    }
    yaw.head<3>() += load.head<3>();
    yaw.tail<3>() += load.tail<3>() + (root - top).cross(load.head<3>());
  }

  // Tower base: the tower (+ yaw-bearing mass) with its external loads, and the yaw-bearing load
  // carried down.
  const Vec3& base = k.tower_base.position_m;
  Vec6 tower = Vec6::Zero();
  const FlexibleTower& flexible = model.flexible_tower;
  if (flexible.mode_count == 0) {
    add_body(model.tower.mass_kg, model.tower.inertia_kg_m2, k.tower_cm, k.base, udot, gravity, base, tower);
  } else {
    const FlexibleBodyDAlembert d = flexible_body_dalembert(flexible.inertia, tower_motion(model, state, k), udot, gravity);
    tower.head<3>() += d.force_N;
    tower.tail<3>() += d.moment_N_m + (k.reference.position_m - base).cross(d.force_N);
  }
  std::array<Vec3, kMaxTowerLoads> load_at;  // the tower loads' points on the deflected tower, g
  for (int i = 0; i < loads.tower_load_count; ++i) {
    const TowerPointLoad& load = loads.tower_loads[i];
    load_at[i] = tower_point(model, state, k, load.height_m).position_m;
    tower.head<3>() += load.force_N;
    tower.tail<3>() += (load_at[i] - base).cross(load.force_N);
  }
  tower.head<3>() += yaw.head<3>();
  tower.tail<3>() += yaw.tail<3>() + (top - base).cross(yaw.head<3>());

  // Frame t (tower base) is parallel to b; p (yaw bearing) too for a rigid tower, else tilted
  // with the tower top.
  const Mat3& t_gp = k.tower_top_frame.orientation;
  out.tower_base_loads << t_gb.transpose() * tower.head<3>(), t_gb.transpose() * tower.tail<3>();
  out.yaw_bearing_loads << t_gp.transpose() * yaw.head<3>(), t_gp.transpose() * yaw.tail<3>();

  for (int i = 0; i < model.blade_count; ++i) {
    out.blade_root[i] = frame_motion(k.blade_root[i], k.rotor, k.blade_root_orientation[i], udot);
  }
  out.hub = frame_motion(k.apex, k.rotor, k.rotor.orientation, udot);

  // Channels, in the order of channels().
  auto& c = out.channels;
  int n = 0;
  auto put3 = [&](const Vec3& v, double scale) {
    for (int i = 0; i < 3; ++i) c[n++] = scale * v[i];
  };
  put3(state.position_m, 1.0);                                       // PtfmSurge, Sway, Heave
  put3(out.platform_angles_rad, kRadToDeg);                          // PtfmRoll, Pitch, Yaw
  put3(state.velocity_m_s, 1.0);                                     // PtfmTVxi …
  put3(k.base.angular_velocity_rad_s, kRadToDeg);                    // PtfmRVxi …
  put3(out.platform_acceleration_m_s2, 1.0);                         // PtfmTAxi …
  put3(out.platform_angular_acceleration_rad_s2, kRadToDeg);         // PtfmRAxi …
  const double two_pi = 2.0 * std::numbers::pi;
  c[n++] = kRadToDeg * (state.rotor_azimuth_rad - two_pi * std::floor(state.rotor_azimuth_rad / two_pi));  // Azimuth
  c[n++] = kRadSToRpm * state.rotor_speed_rad_s;                                      // RotSpeed
  c[n++] = kRadSToRpm * model.gearbox_ratio *
           (model.generator_dof == kGenerator ? state.generator_speed_rad_s : state.rotor_speed_rad_s);  // GenSpeed
  c[n++] = kRadToDeg * udot[kRotor];                                                  // RotAccel
  c[n++] = kRadToDeg * state.nacelle_yaw_rad;                                         // NacYaw
  c[n++] = kRadToDeg * (model.generator_dof == kGenerator
                            ? state.rotor_azimuth_rad - state.generator_azimuth_rad : 0.0);  // DrTrTwst
  put3(t_gp.transpose() * acceleration(k.tower_top, udot), 1.0);                       // YawBrTAxp …
  put3(k.shaft.orientation.transpose() * acceleration(k.imu, udot), 1.0);              // NcIMUTAxs …
  put3(out.tower_base_loads.head<3>(), 1e-3);                                         // TwrBsFxt … (kN)
  put3(out.tower_base_loads.tail<3>(), 1e-3);                                         // TwrBsMxt … (kN·m)
  put3(out.yaw_bearing_loads.head<3>(), 1e-3);                                        // YawBrFxp …
  put3(out.yaw_bearing_loads.tail<3>(), 1e-3);                                        // YawBrMxp …
  if (flexible.mode_count > 0) {
    // Tower-top deflections in b (ElastoDyn's TTDspFA/SS: relative to the undeflected tower).
    double fa = 0.0, ss = 0.0;
    for (int j = 0; j < flexible.mode_count; ++j) {
      const double d = flexible.top_shape[j] * state.tower_deflection_m[j];
      (j < flexible.fore_aft_count ? fa : ss) += d;
    }
    c[n++] = fa;  // TTDspFA
    c[n++] = ss;  // TTDspSS
  }
  // Tower gauges (ElastoDyn's TwHt{k}): the load of the part above on the part below, as at the
  // tower base: the d'Alembert load of the mass above, the tower loads at or above the gauge and the
  // yaw-bearing load carried down; moments about the deflected gauge point; in the local tower frame.
  for (int g = 0; g < model.tower_gauge_count; ++g) {
    const TowerGauge& gauge = model.tower_gauges[g];
    const Vec3 at = tower_point(model, state, k, gauge.height_m).position_m;
    const FlexibleBodyDAlembert d = flexible_body_dalembert(gauge.above, tower_motion(model, state, k), udot, gravity);
    Vec3 force = d.force_N + yaw.head<3>();
    Vec3 moment = d.moment_N_m + (k.reference.position_m - at).cross(d.force_N) + yaw.tail<3>() +
                  (top - at).cross(yaw.head<3>());
    for (int i = 0; i < loads.tower_load_count; ++i) {
      const TowerPointLoad& load = loads.tower_loads[i];
      if (std::max(load.height_m, 0.0) < gauge.height_m) continue;  // below the gauge (below the base: at it)
      force += load.force_N;
      moment += (load_at[i] - at).cross(load.force_N);
    }
    const Mat3 t_gt = tower_section_orientation(model, state, t_gb, gauge.height_m);
    put3(t_gt.transpose() * force, 1e-3);   // TwHt{k}FLxt, FLyt, FLzt (kN)
    put3(t_gt.transpose() * moment, 1e-3);  // TwHt{k}MLxt, MLyt, MLzt (kN·m)
    // ElastoDyn's TwHt{k}TDxt/TDyt: the deflection relative to the undeflected tower along x_t, y_t of
    // the tower base (its a frame), not the tilted local frame.
    const Vec3 deflection = tower_deflection(model, state, gauge.height_m);
    c[n++] = deflection.x();
    c[n++] = deflection.y();
  }
  // ElastoDyn's TwrClrnc{b}: from the deflected tower top (yaw bearing) to the blade tip, in the nacelle
  // frame: the distance from the yaw axis when the tip is below the yaw bearing, else the distance from
  // the yaw bearing (no tower radius taken off). Rigid blades: the tip on the preconed pitch axis at TipRad;
  // Rayleigh–Ritz blades: the deflected tip.
  if (!model.params.rotor.flexible_blades) {
    const double length = model.params.rotor.tip_radius_m - model.params.rotor.hub_radius_m;
    for (int i = 0; i < model.blade_count; ++i) {
      const Vec3 tip = rr.mode_count > 0 ? blade_station_point(model, state, k, i, rr.station_count - 1).position_m
                                          : Vec3(k.blade_root[i].position_m + length * k.blade_root_orientation[i].col(2));
      const Vec3 r = k.nacelle.orientation.transpose() * (tip - top);
      c[n++] = r.z() > 0.0 ? r.norm() : r.head<2>().norm();  // TwrClrnc{i+1}
    }
  }
  // Rayleigh–Ritz blades, ElastoDyn's channels: root loads (blade on hub) in the coned frame c (= r)
  // and the pitched blade frame b (= f); tip deflection relative to the undeflected blade in both
  // (no axial shortening in these shapes: no TipDz); OoPDefl = TipDxc, IPDefl = TipDyc.
  for (int b = 0; b < model.blade_count && rr.mode_count > 0; ++b) {
    const Mat3& t_gc = k.blade_root_orientation[b];
    const Mat3& t_gf = k.blade_frame_orientation[b];
    const Vec6& load = out.blade_root_loads[b];
    const Vec3 tip_f = blade_deflection(model, state, b, rr.station_count - 1);
    const Vec3 tip_c = t_gc.transpose() * (t_gf * tip_f);
    for (const Mat3* frame : {&t_gc, &t_gf}) {
      put3(frame->transpose() * load.head<3>(), 1e-3);  // RootF{x,y,z}{c,b} (kN)
      put3(frame->transpose() * load.tail<3>(), 1e-3);  // RootM{x,y,z}{c,b} (kN·m)
    }
    c[n++] = tip_c.x();  // TipDxc
    c[n++] = tip_c.y();  // TipDyc
    c[n++] = tip_f.x();  // TipDxb
    c[n++] = tip_f.y();  // TipDyb
    c[n++] = tip_c.x();  // OoPDefl
    c[n++] = tip_c.y();  // IPDefl
    // Gauges (ElastoDyn's Spn{k}FL/ML{x,y,z}b): the load of the blade beyond the gauge on the part
    // inboard — the d'Alembert load of the mass beyond it and the station loads beyond it — about the
    // deflected gauge point, in the local section frame there: ElastoDyn's element-fixed frame n,
    // aligned with the structural axes (b turned by the structural twist θ_s) and the elastic slopes.
    const FlexibleBodyMotion body = blade_motion(model, state, k, b);
    const Vec3& root = k.blade_root[b].position_m;
    for (int g = 0; g < rr.gauge_count; ++g) {
      const BladeGauge& gauge = rr.gauges[g];
      const FlexibleBodyDAlembert d = flexible_body_dalembert(gauge.outboard, body, udot, gravity);
      Vec3 force = d.force_N, moment = d.moment_N_m;  // about the root
      for (int s = 0; s < loads.blade_station_load_count; ++s) {
        if (rr.stations[s].span_m < gauge.station.span_m) continue;
        const BladeStationLoad& at = loads.blade_station_loads[b][s];
        force += at.force_N;
        moment += (blade_station_point(model, state, k, b, s).position_m - root).cross(at.force_N) + at.moment_N_m;
      }
      const Vec3 point = flexible_body_point_motion(body, Vec3(0.0, 0.0, gauge.station.span_m), gauge.station.shape).position_m;
      moment += (root - point).cross(force);
      Vec3 theta = Vec3::Zero();
      for (int j = 0; j < rr.mode_count; ++j) theta += state.blade_deflection_m[b][j] * blade_rotation_shape(gauge.station, j);
      const Mat3 local = t_gf * rotation_x(theta.x()) * rotation_y(theta.y()) * rotation_z(-gauge.station.twist_rad);
      put3(local.transpose() * force, 1e-3);   // Spn{k}FL{x,y,z}b (kN)
      put3(local.transpose() * moment, 1e-3);  // Spn{k}ML{x,y,z}b (kN·m)
    }
  }
  return out;
}

std::vector<ChannelInfo> Multibody::channels(const Model& model) {
  const char* m = "multibody";
  std::vector<ChannelInfo> c;
  auto add = [&](const char* name, const char* unit, const char* description) {
    c.push_back({name, unit, description, m});
  };
  add("PtfmSurge", "m", "platform reference point x, inertial frame");
  add("PtfmSway", "m", "platform reference point y, inertial frame");
  add("PtfmHeave", "m", "platform reference point z, inertial frame");
  add("PtfmRoll", "deg", "platform Euler 1-2-3 angle 1 (about x)");
  add("PtfmPitch", "deg", "platform Euler 1-2-3 angle 2 (about y'), in [-90, 90]");
  add("PtfmYaw", "deg", "platform Euler 1-2-3 angle 3 (about z'')");
  add("PtfmTVxi", "m/s", "platform reference point velocity, xi");
  add("PtfmTVyi", "m/s", "platform reference point velocity, yi");
  add("PtfmTVzi", "m/s", "platform reference point velocity, zi");
  add("PtfmRVxi", "deg/s", "platform angular velocity, xi component");
  add("PtfmRVyi", "deg/s", "platform angular velocity, yi component");
  add("PtfmRVzi", "deg/s", "platform angular velocity, zi component");
  add("PtfmTAxi", "m/s^2", "platform reference point acceleration, xi");
  add("PtfmTAyi", "m/s^2", "platform reference point acceleration, yi");
  add("PtfmTAzi", "m/s^2", "platform reference point acceleration, zi");
  add("PtfmRAxi", "deg/s^2", "platform angular acceleration, xi component");
  add("PtfmRAyi", "deg/s^2", "platform angular acceleration, yi component");
  add("PtfmRAzi", "deg/s^2", "platform angular acceleration, zi component");
  add("Azimuth", "deg", "rotor azimuth, blade 1 up at 0, positive about the downwind shaft axis, [0, 360)");
  add("RotSpeed", "rpm", "rotor (LSS) speed relative to the nacelle");
  add("GenSpeed", "rpm", "generator (HSS) speed relative to the nacelle");
  add("RotAccel", "deg/s^2", "rotor (LSS) angular acceleration relative to the nacelle");
  add("NacYaw", "deg", "nacelle yaw angle about the tower axis");
  add("DrTrTwst", "deg", "drivetrain torsional twist, rotor minus generator (LSS side)");
  add("YawBrTAxp", "m/s^2", "tower-top acceleration (absolute, no gravity), xp");
  add("YawBrTAyp", "m/s^2", "tower-top acceleration (absolute, no gravity), yp");
  add("YawBrTAzp", "m/s^2", "tower-top acceleration (absolute, no gravity), zp");
  add("NcIMUTAxs", "m/s^2", "nacelle IMU acceleration (absolute, no gravity), xs (along the shaft, downwind)");
  add("NcIMUTAys", "m/s^2", "nacelle IMU acceleration (absolute, no gravity), ys");
  add("NcIMUTAzs", "m/s^2", "nacelle IMU acceleration (absolute, no gravity), zs");
  add("TwrBsFxt", "kN", "tower-base fore-aft shear force (load of the tower on its base), xt");
  add("TwrBsFyt", "kN", "tower-base side-to-side shear force, yt");
  add("TwrBsFzt", "kN", "tower-base axial force, zt (negative = compression by the weight)");
  add("TwrBsMxt", "kN-m", "tower-base roll (side-to-side) moment, about xt");
  add("TwrBsMyt", "kN-m", "tower-base pitch (fore-aft) moment, about yt");
  add("TwrBsMzt", "kN-m", "tower-base yaw (torsional) moment, about zt");
  add("YawBrFxp", "kN", "yaw-bearing fore-aft shear force (load of nacelle+rotor on the tower top), xp");
  add("YawBrFyp", "kN", "yaw-bearing side-to-side shear force, yp");
  add("YawBrFzp", "kN", "yaw-bearing axial force, zp");
  add("YawBrMxp", "kN-m", "yaw-bearing roll moment, about xp");
  add("YawBrMyp", "kN-m", "yaw-bearing pitch moment, about yp");
  add("YawBrMzp", "kN-m", "yaw-bearing yaw moment, about zp");
  if (model.flexible_tower.mode_count > 0) {
    add("TTDspFA", "m", "tower-top fore-aft deflection relative to the undeflected tower, xt");
    add("TTDspSS", "m", "tower-top side-to-side deflection relative to the undeflected tower, yt");
  }
  static const char* const load_names[] = {"FLxt", "FLyt", "FLzt", "MLxt", "MLyt", "MLzt"};
  static const char* const load_descriptions[] = {
      "fore-aft shear force", "side-to-side shear force", "axial force (negative = compression)",
      "side-to-side (roll) bending moment", "fore-aft (pitch) bending moment", "torsional (yaw) moment"};
  for (int g = 0; g < model.tower_gauge_count; ++g) {
    std::ostringstream h;
    h << model.tower_gauges[g].height_m;
    for (int i = 0; i < 6; ++i)
      c.push_back({"TwHt" + std::to_string(g + 1) + load_names[i], i < 3 ? "kN" : "kN-m",
                   std::string("local tower ") + load_descriptions[i] + " at gauge " + std::to_string(g + 1) + " (" +
                       h.str() + " m above the tower base; load of the tower above, about the deflected gauge "
                       "point), local tower frame " + (i % 3 == 0 ? "xt" : i % 3 == 1 ? "yt" : "zt"),
                   m});
    c.push_back({"TwHt" + std::to_string(g + 1) + "TDxt", "m",
                 "local tower fore-aft deflection at gauge " + std::to_string(g + 1) + " relative to the undeflected tower, xt", m});
    c.push_back({"TwHt" + std::to_string(g + 1) + "TDyt", "m",
                 "local tower side-to-side deflection at gauge " + std::to_string(g + 1) + " relative to the undeflected tower, yt", m});
  }
  if (!model.params.rotor.flexible_blades)
    for (int i = 1; i <= model.blade_count; ++i)
      c.push_back({"TwrClrnc" + std::to_string(i), "m",
                   "blade " + std::to_string(i) + " tip-to-tower clearance estimate (ElastoDyn: from the yaw axis when the "
                   "tip is below the yaw bearing, else from the yaw bearing; tower radius not taken off)", m});
  if (model.rr_blades.mode_count > 0) {
    static const char* const axes = "xyz";
    for (int b = 1; b <= model.blade_count; ++b) {
      const std::string blade = std::to_string(b);
      for (const char* frame : {"c", "b"}) {
        const std::string where = std::string(frame) == "c" ? "coned root frame c" : "pitched blade frame b";
        for (int i = 0; i < 3; ++i)
          c.push_back({std::string("RootF") + axes[i] + frame + blade, "kN",
                       "blade " + blade + " root force along " + axes[i] + " of the " + where + " (blade on hub)", m});
        for (int i = 0; i < 3; ++i)
          c.push_back({std::string("RootM") + axes[i] + frame + blade, "kN-m",
                       "blade " + blade + " root moment about " + axes[i] + " of the " + where + " (blade on hub)", m});
      }
      for (const char* name : {"TipDxc", "TipDyc", "TipDxb", "TipDyb"})
        c.push_back({name + blade, "m", "blade " + blade + " tip deflection relative to the undeflected blade, " +
                                            std::string(name + 4) + " axis", m});
      c.push_back({"OoPDefl" + blade, "m", "blade " + blade + " out-of-plane tip deflection (= TipDxc)", m});
      c.push_back({"IPDefl" + blade, "m", "blade " + blade + " in-plane tip deflection (= TipDyc)", m});
      for (int g = 0; g < model.rr_blades.gauge_count; ++g) {
        std::ostringstream x;
        x << model.rr_blades.gauges[g].station.span_m;
        const std::string gauge = std::to_string(g + 1);
        for (int i = 0; i < 3; ++i)
          c.push_back({"Spn" + gauge + "FL" + axes[i] + "b" + blade, "kN",
                       "blade " + blade + " local force at gauge " + gauge + " (" + x.str() + " m from the root; the blade beyond "
                       "on the part inboard) along " + axes[i] + " of the local section frame (structural twist and deflection)", m});
        for (int i = 0; i < 3; ++i)
          c.push_back({"Spn" + gauge + "ML" + axes[i] + "b" + blade, "kN-m",
                       "blade " + blade + " local moment at gauge " + gauge + " (" + x.str() + " m from the root; about the "
                       "deflected gauge point) about " + axes[i] + " of the local section frame (structural twist and deflection)", m});
      }
    }
  }
  return c;
}

}  // namespace fowtsim::multibody
