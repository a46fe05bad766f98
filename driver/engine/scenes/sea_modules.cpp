#include "scenes/sea_modules.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "decks/deck_helpers.hpp"
#include "decks/hydro_deck.hpp"
#include "decks/mooring_deck.hpp"
#include "decks/waves_deck.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/mooring/stiffness.hpp"

namespace fowtsim::driver {

SeaModules::SeaModules(const io::ValidatedDeck& deck, const FrameMotion& initial_pose, double large_step_s)
    : wave_params_(deck.has("waves") ? wave_params(deck.section("waves")) : waves::WaveParams{}),
      has_waves_(deck.has("waves")),
      sea_(waves::Waves::make_params(wave_params_)) {
  std::optional<io::WamitExcitation> excitation_table;
  if (deck.has("hydro")) {
    HydroDeck h = read_hydro_deck(deck.section("hydro"), large_step_s);
    hydro_ = std::move(h.params);
    excitation_table = std::move(h.excitation);
  }
  if (deck.has("mooring")) {
    mooring_ = mooring_params(deck.section("mooring"));
    check_mooring_at_initial_pose(deck, *mooring_, initial_pose);
  }
  if (hydro_) {
    initial_.hydro_input = hydro::make_input(*hydro_);
    initial_.hydro_input.platform = initial_pose;
    initial_.hydro = hydro::Hydro::make_state(*hydro_, initial_.hydro_input);
    if (excitation_table) {
      try {
        excitation_ = std::make_unique<WaveExcitation>(*sea_.field, *excitation_table);
      } catch (const InputError& e) {
        throw InputError(e.context(), where(deck, "hydro.potential_flow") + ": " + e.message());
      }
    }
    if (!sea_.field->calm()) {
      hydro::Points points(3, hydro::node_count(*hydro_));
      hydro::strip_points(*hydro_, initial_pose, VecX::Zero(static_cast<Eigen::Index>(hydro_->members.size())), points);
      std::vector<Vec3> list;
      for (Eigen::Index i = 0; i < points.cols(); ++i) list.emplace_back(points.col(i));
      kinematics_ = std::make_unique<waves::PrecomputedKinematics>(*sea_.field, list);
      if (hydro_->surface == hydro::SurfaceModel::wave_elevation) {
        // Elevation series where each member meets the still water at the initial pose, like the
        // kinematics: no direct summation over the components at every stage.
        hydro::Points waterline(3, static_cast<Eigen::Index>(hydro_->members.size()));
        hydro::waterline_points(*hydro_, initial_pose, waterline);
        std::vector<Vec3> at_surface;
        for (Eigen::Index m = 0; m < waterline.cols(); ++m) at_surface.emplace_back(waterline(0, m), waterline(1, m), 0.0);
        waves::PrecomputeOptions options;
        options.elevation_only = true;
        waterline_elevation_ = std::make_unique<waves::PrecomputedKinematics>(*sea_.field, at_surface, options);
      }
    }
  }
  if (mooring_) initial_.mooring = mooring::QuasiStaticMooring::make_state(*mooring_);
  if (hydro_) hydro_channel_count_ = hydro::Hydro::channels(*hydro_).size();
  channel_count_ = channels().size();
}

void SeaModules::evaluate(double t, const FrameMotion& pose, Data& d) const {
  if (hydro_) {
    hydro::Hydro::Input& in = d.hydro_input;
    in.platform = pose;
    in.time_s = t;
    if (waterline_elevation_) {
      const PeriodicStencil time = waterline_elevation_->stencil(t);
      for (std::size_t m = 0; m < waterline_elevation_->size(); ++m)
        in.surface_elevation_m[static_cast<Eigen::Index>(m)] = waterline_elevation_->elevation(m, time);
    }
    if (kinematics_) {
      const PeriodicStencil time = kinematics_->stencil(t);
      for (std::size_t i = 0; i < kinematics_->size(); ++i) {
        const waves::WaveKinematics k = kinematics_->at(i, time);
        const auto c = static_cast<Eigen::Index>(i);
        in.fluid_velocity_m_s.col(c) = k.velocity_m_s;
        in.fluid_acceleration_m_s2.col(c) = k.acceleration_m_s2;
        in.dynamic_pressure_Pa[c] = k.dynamic_pressure_Pa;
      }
    }
    if (excitation_) in.wave_excitation = excitation_->at(t);
    d.hydro_output = hydro::Hydro::outputs(*hydro_, in, d.hydro);
  }
  if (mooring_) d.mooring_output = mooring::QuasiStaticMooring::evaluate(*mooring_, {pose, t}, d.mooring);
}

void SeaModules::advance(double t, const FrameMotion& pose, Data& d) const {
  if (!hydro_ || !hydro_->potential_flow) return;
  d.hydro_input.platform = pose;
  const double dt = hydro_->potential_flow->radiation.step_s;
  hydro::Hydro::advance(*hydro_, d.hydro_input, t - dt, dt, d.hydro);
}

Vec6 SeaModules::platform_load(const Data& d) const {
  Vec6 load = hydro_ ? d.hydro_output.total : Vec6::Zero();
  if (mooring_) {
    load.head<3>() += d.mooring_output.force_N;
    load.tail<3>() += d.mooring_output.moment_N_m;
  }
  return load;
}

std::vector<ChannelInfo> SeaModules::channels() const {
  std::vector<ChannelInfo> all = waves::Waves::channels(sea_);
  if (hydro_)
    for (const ChannelInfo& c : hydro::Hydro::channels(*hydro_)) all.push_back(c);
  if (mooring_)
    for (const ChannelInfo& c : mooring::QuasiStaticMooring::channels(*mooring_)) all.push_back(c);
  return all;
}

void SeaModules::channel_values(double t, const Data& d, const Vec6& platform_acceleration, std::span<double> out) const {
  const waves::Waves::Output wo = waves::Waves::outputs(sea_, {}, waves::Waves::State{t});
  std::size_t k = 0;
  for (; k < wo.probe_count; ++k) out[k] = wo.elevation_m[k];
  if (hydro_) {
    hydro::channel_values(*hydro_, d.hydro_output, platform_acceleration, out.subspan(k, hydro_channel_count_));
    k += hydro_channel_count_;
  }
  if (mooring_) mooring::QuasiStaticMooring::channel_values(*mooring_, d.mooring_output, out.subspan(k, channel_count_ - k));
}

Mat6 SeaModules::mooring_stiffness(const FrameMotion& pose) const {
  if (!mooring_) return Mat6::Zero();
  mooring::QuasiStaticMooring::State state = mooring::QuasiStaticMooring::make_state(*mooring_);
  mooring::QuasiStaticMooring::evaluate(*mooring_, {pose, 0.0}, state);
  return mooring::linearized_stiffness(*mooring_, {pose, 0.0}, state);
}

std::unique_ptr<waves::PrecomputedKinematics> SeaModules::kinematics_at(std::span<const Vec3> points_m) const {
  if (!sea_.field || sea_.field->calm()) return nullptr;
  return std::make_unique<waves::PrecomputedKinematics>(*sea_.field, points_m);
}

std::vector<std::uint64_t> SeaModules::seeds() const {
  if (has_waves_) return {wave_params_.seed};
  return {};
}

std::vector<std::string> SeaModules::warnings() const {
  std::vector<std::string> out;
  if (excitation_ && excitation_->coverage_warning()) out.push_back(*excitation_->coverage_warning());
  if (hydro_ && hydro_->potential_flow) {
    // The radiation model's own doubts: a window that cuts off more than 1 % of a kernel's peak
    // (the OC3 spar at 60 s: none), a state-space fit that missed the tolerance at its largest order.
    const hydro::RadiationModel& r = hydro_->potential_flow->radiation;
    for (const hydro::RadiationEntry& e : r.entries) {
      const std::string entry = fmt::format("radiation kernel K{}{}", e.row + 1, e.col + 1);
      if (e.tail_ratio > 0.01)
        out.push_back(fmt::format("{} is still {:.1f} % of its peak at the end of the {:.3g}-s window: lengthen "
                                  "hydro.potential_flow.radiation_window_s",
                                  entry, 100.0 * e.tail_ratio, r.window_steps * r.step_s));
      if (r.method == hydro::RadiationMethod::state_space && e.fit.relative_error > r.fit_tolerance)
        out.push_back(fmt::format("{}: the state-space fit reaches {:.2g} % relative error at order {}, above the "
                                  "tolerance {:.2g} %: raise hydro.potential_flow.state_space_max_order",
                                  entry, 100.0 * e.fit.relative_error, e.fit.order, 100.0 * r.fit_tolerance));
    }
  }
  if (!has_waves_) return out;
  // Deep-water steepness H/L against the breaking limit 1/7 (Michell 1893): a linear sea that
  // steep is outside the theory the wave model rests on.
  const bool irregular = wave_params_.model == waves::WaveModel::jonswap || wave_params_.model == waves::WaveModel::pierson_moskowitz;
  const bool regular = wave_params_.model == waves::WaveModel::regular;
  if (!irregular && !regular) return out;
  const double h = irregular ? wave_params_.hs_m : wave_params_.height_m;
  const double period = irregular ? wave_params_.tp_s : wave_params_.period_s;
  const double length = 9.80665 * period * period / (2.0 * 3.141592653589793);
  if (h / length > 1.0 / 7.0)
    out.push_back(fmt::format("the sea is steeper than the breaking limit: {} {:.3g} m at {} {:.3g} s gives H/L = {:.3f} > 1/7 "
                              "(deep water); linear waves do not hold",
                              irregular ? "Hs" : "H", h, irregular ? "Tp" : "T", period, h / length));
  return out;
}

}  // namespace fowtsim::driver
