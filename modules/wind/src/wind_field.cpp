#include "fowtsim/wind/wind_field.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"

namespace fowtsim::wind {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

bool uses_full_field(WindModel model) { return model == WindModel::bts || model == WindModel::turbulent; }

}  // namespace

double profile_speed(const WindParams& p, double z) {
  if (z <= 0.0) return 0.0;
  switch (p.model) {
    case WindModel::steady: return p.speed_m_s;
    case WindModel::power_law: return p.speed_m_s * std::pow(z / p.reference_height_m, p.shear_exponent);
    case WindModel::log:
      if (z <= p.roughness_m) return 0.0;
      return p.speed_m_s * std::log(z / p.roughness_m) / std::log(p.reference_height_m / p.roughness_m);
    case WindModel::bts:
    case WindModel::turbulent:
    case WindModel::uniform_file: break;
  }
  return 0.0;
}

WindField::WindField(WindParams params, std::shared_ptr<const FullField> field)
    : params_(std::move(params)), field_(std::move(field)) {
  validate(params_);
  if (uses_full_field(params_.model)) {
    if (!field_)
      throw InputError(ErrorContext{"wind", std::nullopt, "wind.model", "read or generate the field first"},
                       "wind model bts/turbulent needs a full field, none was given");
    validate(*field_);
  } else if (field_) {
    throw InputError(ErrorContext{"wind", std::nullopt, "wind.model", ""},
                     "a full field was given to a wind model without one (steady/power_law/log/uniform_file)");
  }
  wind_to_inertial_ = rotation_z(-params_.direction_deg * kDegree) * rotation_y(-params_.upflow_deg * kDegree);
  reference_point_m_ = Vec3(0.0, 0.0, params_.reference_height_m);
  event_ = make_wind_event(params_);
}

WindField::Frame WindField::frame_at(double time_s) const {
  Frame f{wind_to_inertial_, wind_event_at(event_, time_s), {}};
  if (params_.model == WindModel::uniform_file) f.uniform = uniform_wind_at(params_.uniform, time_s);
  // Only a turning event rebuilds R (without one, R stays bit for bit the deck's).
  if (f.event.direction_rad != 0.0)
    f.wind_to_inertial =
        rotation_z(-(params_.direction_deg * kDegree + f.event.direction_rad)) * rotation_y(-params_.upflow_deg * kDegree);
  return f;
}

Vec3 WindField::velocity(const Vec3& p, double time_s) const { return velocity_at(p, time_s, frame_at(time_s), true); }

Vec3 WindField::velocity_at(const Vec3& p, double time_s, const Frame& frame, bool count_below) const {
  const Vec3 p_wind = frame.wind_to_inertial.transpose() * (p - reference_point_m_) + reference_point_m_;
  Vec3 v_wind;
  if (params_.model == WindModel::uniform_file) {
    v_wind = uniform_wind_velocity(frame.uniform, p_wind, params_.reference_height_m, params_.reference_length_m);
  } else if (field_ && covers(*field_, p_wind)) {
    v_wind = full_field_velocity(*field_, p_wind, time_s);
  } else if (field_) {
    if (count_below || p_wind.z() >= field_->z_bottom_m) ++outside_queries_;
    const double z = std::max(p_wind.z(), 0.0);
    v_wind = Vec3(field_->u_hub_m_s * std::pow(z / field_->z_hub_m, params_.shear_exponent), 0.0, 0.0);
  } else {
    v_wind = Vec3(profile_speed(params_, p_wind.z()), 0.0, 0.0);
  }
  if (event_.type != WindEventType::none && p_wind.z() > 0.0)
    v_wind.x() += frame.event.speed_m_s + frame.event.vertical_shear_per_s * (p_wind.z() - reference_point_m_.z()) +
                  frame.event.horizontal_shear_per_s * p_wind.y();
  const Vec3 v = frame.wind_to_inertial * v_wind;
  if (!v.allFinite())
    throw NumericalError(ErrorContext{"wind", time_s, "wind velocity", "check the wind input"},
                         "non-finite wind velocity");
  return v;
}

void WindField::velocities(std::span<const Vec3> points, double time_s, std::span<Vec3> out) const {
  if (points.size() != out.size())
    throw InputError(ErrorContext{"wind", time_s, "out", ""},
                     "points.size() (" + std::to_string(points.size()) + ") != out.size() (" +
                         std::to_string(out.size()) + ")");
  const Frame frame = frame_at(time_s);
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = velocity_at(points[i], time_s, frame, true);
}

void WindField::velocities_profile_below(std::span<const Vec3> points, double time_s, std::span<Vec3> out) const {
  if (points.size() != out.size())
    throw InputError(ErrorContext{"wind", time_s, "out", ""},
                     "points.size() (" + std::to_string(points.size()) + ") != out.size() (" + std::to_string(out.size()) + ")");
  const Frame frame = frame_at(time_s);
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = velocity_at(points[i], time_s, frame, false);
}

Wind::State Wind::make_state(const Params&) { return State{}; }

void Wind::advance(const Params&, const Input&, double t, double dt, State& s) { s.time_s = t + dt; }

Wind::Output Wind::outputs(const Params& p, const Input&, const State& s) {
  return Output{p.field->velocity(p.field->params().probe_point_m, s.time_s)};
}

std::vector<ChannelInfo> Wind::channels(const Params&) {
  return {
      {"Wind1VelX", "m/s", "inertial x (downwind at 0°) wind velocity at the probe point", "wind"},
      {"Wind1VelY", "m/s", "inertial y wind velocity at the probe point", "wind"},
      {"Wind1VelZ", "m/s", "inertial z (up) wind velocity at the probe point", "wind"},
  };
}

}  // namespace fowtsim::wind
