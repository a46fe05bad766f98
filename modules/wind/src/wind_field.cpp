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
    case WindModel::turbulent: break;
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
                     "a full field was given to an analytic wind model (steady/power_law/log)");
  }
  constexpr double deg = std::numbers::pi / 180.0;
  wind_to_inertial_ = rotation_z(-params_.direction_deg * deg) * rotation_y(-params_.upflow_deg * deg);
  reference_point_m_ = Vec3(0.0, 0.0, params_.reference_height_m);
}

Vec3 WindField::velocity(const Vec3& p, double time_s) const { return velocity_at(p, time_s, true); }

Vec3 WindField::velocity_at(const Vec3& p, double time_s, bool count_below) const {
  const Vec3 p_wind = wind_to_inertial_.transpose() * (p - reference_point_m_) + reference_point_m_;
  Vec3 v_wind;
  if (field_ && covers(*field_, p_wind)) {
    v_wind = full_field_velocity(*field_, p_wind, time_s);
  } else if (field_) {
    if (count_below || p_wind.z() >= field_->z_bottom_m) ++outside_queries_;
    const double z = std::max(p_wind.z(), 0.0);
    v_wind = Vec3(field_->u_hub_m_s * std::pow(z / field_->z_hub_m, params_.shear_exponent), 0.0, 0.0);
  } else {
    v_wind = Vec3(profile_speed(params_, p_wind.z()), 0.0, 0.0);
  }
  const Vec3 v = wind_to_inertial_ * v_wind;
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
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = velocity(points[i], time_s);
}

void WindField::velocities_profile_below(std::span<const Vec3> points, double time_s, std::span<Vec3> out) const {
  if (points.size() != out.size())
    throw InputError(ErrorContext{"wind", time_s, "out", ""},
                     "points.size() (" + std::to_string(points.size()) + ") != out.size() (" + std::to_string(out.size()) + ")");
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = velocity_at(points[i], time_s, false);
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
