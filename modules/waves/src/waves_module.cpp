#include "fowtsim/waves/waves_module.hpp"

#include <fmt/format.h>

#include "fowtsim/core/module.hpp"

namespace fowtsim::waves {

static_assert(Module<Waves>);

Waves::Params Waves::make_params(const WaveParams& waves) {
  Params params;
  params.field = std::make_shared<const WaveField>(waves);
  std::vector<Vec3> probes;
  for (const auto& xy : waves.elevation_probes_m) probes.emplace_back(xy[0], xy[1], 0.0);
  PrecomputeOptions options;
  options.elevation_only = true;
  params.probes = std::make_shared<const PrecomputedKinematics>(*params.field, probes, options);
  return params;
}

Waves::State Waves::make_state(const Params&) { return {}; }

void Waves::advance(const Params&, const Input&, double t, double dt, State& state) { state.time_s = t + dt; }

Waves::Output Waves::outputs(const Params& params, const Input&, const State& state) {
  Output out;
  out.probe_count = params.probes->size();
  for (std::size_t i = 0; i < out.probe_count; ++i) out.elevation_m[i] = params.probes->elevation(i, state.time_s);
  return out;
}

std::vector<ChannelInfo> Waves::channels(const Params& params) {
  std::vector<ChannelInfo> list;
  for (std::size_t i = 0; i < params.probes->size(); ++i) {
    const Vec3& p = params.probes->point(i);
    list.push_back({fmt::format("Wave{}Elev", i + 1), "m",
                    fmt::format("incident wave elevation at (x, y) = ({}, {}) m, inertial frame, + up from the "
                                "still-water level", p.x(), p.y()),
                    "waves"});
  }
  return list;
}

}  // namespace fowtsim::waves
