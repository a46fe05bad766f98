#include "decks/waves_deck.hpp"

#include <limits>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;

Schema waves_schema() {
  return Schema::map({
      {"model", Schema::choice({"still", "regular", "jonswap", "pm"}).default_value("still")
                    .doc("still water, one Airy wave, or an irregular sea (JONSWAP / Pierson–Moskowitz)")},
      {"hs_m", Schema::number().at_least(0.0).default_value(0.0).doc("significant wave height Hs = 4√m0 (irregular)")},
      {"tp_s", Schema::number().greater_than(0.0).optional().doc("spectral peak period (irregular)")},
      {"gamma", Schema::number().at_least(1.0).optional().doc("JONSWAP peak shape; absent = IEC 61400-3 default")},
      {"rayleigh_amplitudes", Schema::boolean().default_value(false).doc("Rayleigh-random amplitudes (HydroDyn WaveNDAmp)")},
      {"seed", Schema::integer().at_least(0).default_value(1).doc("random seed of the phases")},
      {"duration_s", Schema::number().greater_than(0.0).default_value(3600.0).doc("record length; the sea repeats with it")},
      {"dt_s", Schema::number().greater_than(0.0).default_value(0.25).doc("record time step (Nyquist bounds the spectrum)")},
      {"cutoff_low_hz", Schema::number().at_least(0.0).default_value(0.0).doc("components below are dropped")},
      {"cutoff_high_hz", Schema::number().greater_than(0.0).optional().doc("components above are dropped; absent = Nyquist")},
      {"height_m", Schema::number().at_least(0.0).default_value(0.0).doc("regular wave height, crest to trough")},
      {"period_s", Schema::number().greater_than(0.0).optional().doc("regular wave period")},
      {"phase_deg", Schema::number().default_value(0.0).doc("regular wave phase at the origin")},
      {"heading_deg", Schema::number().default_value(0.0).doc("propagation direction, from +x towards +y")},
      {"depth_m", Schema::number().greater_than(0.0).optional().doc("water depth; absent = deep water")},
      {"stretching", Schema::choice({"none", "wheeler"}).default_value("none").doc("kinematics near the surface")},
      {"water_density_kg_m3", Schema::number().greater_than(0.0).default_value(1025.0).doc("water density")},
      {"gravity_m_s2", Schema::number().greater_than(0.0).default_value(9.80665).doc("gravity")},
      {"elevation_probes_m", Schema::sequence(number_vector(2, "x, y")).min_items(1).max_items(9).optional()
                                 .doc("(x, y) of Wave1Elev … Wave9Elev; absent = the origin")},
  });
}

waves::WaveParams wave_params(const io::ValidatedDeck& d) {
  waves::WaveParams p;
  p.model = waves::parse_wave_model(d.string("model"));
  p.hs_m = d.number("hs_m");
  if (d.has("tp_s")) p.tp_s = d.number("tp_s");
  if (d.has("gamma")) p.gamma = d.number("gamma");
  p.rayleigh_amplitudes = d.boolean("rayleigh_amplitudes");
  p.seed = static_cast<std::uint64_t>(d.integer("seed"));
  p.duration_s = d.number("duration_s");
  p.dt_s = d.number("dt_s");
  p.cutoff_low_hz = d.number("cutoff_low_hz");
  if (d.has("cutoff_high_hz")) p.cutoff_high_hz = d.number("cutoff_high_hz");
  p.height_m = d.number("height_m");
  if (d.has("period_s")) p.period_s = d.number("period_s");
  p.phase_deg = d.number("phase_deg");
  p.heading_deg = d.number("heading_deg");
  p.depth_m = d.has("depth_m") ? d.number("depth_m") : std::numeric_limits<double>::infinity();
  p.stretching = waves::parse_stretching(d.string("stretching"));
  p.water_density_kg_m3 = d.number("water_density_kg_m3");
  p.gravity_m_s2 = d.number("gravity_m_s2");
  if (d.has("elevation_probes_m")) {
    p.elevation_probes_m.clear();
    for (std::size_t i = 0; i < d.size("elevation_probes_m"); ++i) {
      const std::vector<double> xy = d.numbers(fmt::format("elevation_probes_m[{}]", i));
      p.elevation_probes_m.push_back({xy[0], xy[1]});
    }
  }
  located(d, [&] { waves::validate(p); });
  return p;
}

}  // namespace fowtsim::driver
