#include "cli/post_config.hpp"

#include <cmath>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

namespace {

io::Schema channel_fatigue_schema() {
  return io::Schema::map({
      {"wohler_exponent", io::Schema::number().greater_than(0.0).doc("Wöhler (S-N slope) exponent m: ~3–4 steel, ~10 composite blades")},
      {"ultimate_load", io::Schema::number().greater_than(0.0).optional().doc(
                            "ultimate load L_ult in the channel's unit; given = Goodman correction on")},
      {"goodman_fixed_mean", io::Schema::number().default_value(0.0).doc(
                                 "fixed mean L_MF the Goodman correction refers every cycle to, channel unit")},
  });
}

post::FatigueParams fatigue_params(const io::ValidatedDeck& entry, double equivalent_frequency_hz) {
  post::FatigueParams p;
  p.wohler_exponent = entry.number("wohler_exponent");
  if (entry.has("ultimate_load")) p.ultimate_load = entry.number("ultimate_load");
  p.goodman_fixed_mean = entry.number("goodman_fixed_mean");
  p.equivalent_frequency_hz = equivalent_frequency_hz;
  if (p.ultimate_load && std::abs(p.goodman_fixed_mean) >= *p.ultimate_load)
    throw InputError({"post", std::nullopt, "goodman_fixed_mean", "L_MF must lie inside ±L_ult"},
                     fmt::format("{}: |goodman_fixed_mean| = {} reaches ultimate_load = {}", where(entry, "goodman_fixed_mean"),
                                 std::abs(p.goodman_fixed_mean), *p.ultimate_load));
  return p;
}

FatigueConfig fatigue_config(const io::ValidatedDeck& deck) {
  FatigueConfig config;
  config.equivalent_frequency_hz = deck.number("equivalent_frequency_hz");
  if (deck.has("calculated")) {
    for (const std::string& name : deck.keys("calculated")) {
      const std::string key = "calculated." + name;
      config.calculated.push_back({name, deck.strings(key + ".magnitude_of"), where(deck, key)});
    }
  }
  for (const std::string& name : deck.keys("channels")) {
    const io::ValidatedDeck entry = deck.section("channels." + name);
    const post::FatigueParams params = fatigue_params(entry, config.equivalent_frequency_hz);
    if (name == "default") {
      config.default_params = params;
    } else {
      config.channels[name] = params;
      config.channel_locations[name] = where(deck, "channels." + name);
    }
  }
  return config;
}

io::Schema wind_distribution_schema() {
  return io::Schema::map({
      {"model", io::Schema::choice({"rayleigh", "weibull"}).doc("wind-speed distribution at hub height")},
      {"iec_class", io::Schema::integer().at_least(1).at_most(3).optional().doc(
                        "IEC 61400-1 wind turbine class: V_ave = 10, 8.5, 7.5 m/s (rayleigh only)")},
      {"mean_speed_m_s", io::Schema::number().greater_than(0.0).optional().doc("mean wind speed V_ave")},
      {"scale_m_s", io::Schema::number().greater_than(0.0).optional().doc("Weibull scale A (weibull only)")},
      {"shape", io::Schema::number().greater_than(0.0).optional().doc("Weibull shape k (weibull only; default 2)")},
  });
}

// Exactly one way to set the scale, and only the keys the model uses.
post::WindSpeedDistribution wind_distribution(const io::ValidatedDeck& d, std::string& text) {
  const auto refuse = [&](const std::string& why) -> post::WindSpeedDistribution {
    throw InputError({"post", std::nullopt, "wind_distribution", "see `fowtsim post --help`"}, fmt::format("{}: {}", where(d, ""), why));
  };
  const int scales = d.has("iec_class") + d.has("mean_speed_m_s") + d.has("scale_m_s");
  if (d.string("model") == "rayleigh") {
    if (d.has("scale_m_s") || d.has("shape")) return refuse("a Rayleigh distribution takes iec_class or mean_speed_m_s, not scale_m_s or shape");
    if (scales != 1) return refuse("a Rayleigh distribution needs exactly one of iec_class and mean_speed_m_s");
    const double mean = d.has("iec_class") ? post::iec_class_mean_speed_m_s(static_cast<int>(d.integer("iec_class"))) : d.number("mean_speed_m_s");
    text = d.has("iec_class") ? fmt::format("Rayleigh, V_ave {} m/s (IEC class {})", mean, d.integer("iec_class"))
                              : fmt::format("Rayleigh, V_ave {} m/s", mean);
    return post::WindSpeedDistribution::rayleigh(mean);
  }
  if (d.has("iec_class")) return refuse("iec_class sets a Rayleigh distribution (model: rayleigh)");
  if (scales != 1) return refuse("a Weibull distribution needs exactly one of scale_m_s and mean_speed_m_s");
  const double shape = d.has("shape") ? d.number("shape") : 2.0;
  const post::WindSpeedDistribution w = d.has("scale_m_s") ? post::WindSpeedDistribution::weibull(shape, d.number("scale_m_s"))
                                                            : post::WindSpeedDistribution::weibull_with_mean(shape, d.number("mean_speed_m_s"));
  text = fmt::format("Weibull, k {}, A {:.4g} m/s (mean {:.4g} m/s)", shape, w.scale_m_s, w.mean_speed_m_s());
  return w;
}

}  // namespace

std::optional<post::FatigueParams> FatigueConfig::params_for(const std::string& channel) const {
  if (const auto it = channels.find(channel); it != channels.end()) return it->second;
  return default_params;
}

io::Schema fatigue_config_schema() {
  return io::Schema::map({
      {"equivalent_frequency_hz", io::Schema::number().unit("hz").greater_than(0.0).default_value(1.0).doc(
                                      "f_eq of the DEL: n_eq = f_eq T (MLife; 1 Hz as the seed's Table 4.3)")},
      {"calculated", io::Schema::map_of(io::Schema::map({
                         {"magnitude_of", io::Schema::sequence(io::Schema::string()).min_items(2).doc(
                                              "channels whose vector magnitude √(a² + b² + …) this channel is; unit of the first")},
                     })).optional().doc("channels computed in every file before the statistics, e.g. the combined flap-edge "
                                        "root moment RootMxyb1: {magnitude_of: [RootMxb1, RootMyb1]} (MLife's calculated channels)")},
      {"channels", io::Schema::map_of(channel_fatigue_schema()).doc(
                       "per channel name (or `default` for every channel not listed) its S-N parameters")},
  });
}

io::Schema lifetime_spec_schema() {
  return io::Schema::map({
      {"design_life_years", io::Schema::number().unit("years").greater_than(0.0).default_value(20.0).doc("design life T_life")},
      {"bin_width_m_s", io::Schema::number().unit("m_s").greater_than(0.0).default_value(2.0).doc(
                            "width of the wind-speed bin centred on each run's speed")},
      {"renormalise", io::Schema::boolean().default_value(false).doc(
                          "scale the bin probabilities to sum to one (pCrunch) instead of leaving time outside the bins undamaged (MLife)")},
      {"wind_distribution", wind_distribution_schema()},
      {"runs", io::Schema::sequence(io::Schema::map({
                                        {"file", io::Schema::string().doc("run output (.h5, .out, .outb), relative to this file")},
                                        {"wind_speed_m_s", io::Schema::number().unit("m_s").greater_than(0.0).doc("mean hub-height wind speed")},
                                    }))
                   .min_items(1)},
      {"fatigue", fatigue_config_schema()},
  });
}

FatigueConfig read_fatigue_config(const std::filesystem::path& file) {
  return fatigue_config(io::read_deck(fatigue_config_schema(), file));
}

LifetimeSpec read_lifetime_spec(const std::filesystem::path& file) {
  const io::ValidatedDeck deck = io::read_deck(lifetime_spec_schema(), file);
  LifetimeSpec spec;
  spec.design_life_years = deck.number("design_life_years");
  spec.bin_width_m_s = deck.number("bin_width_m_s");
  spec.renormalise = deck.boolean("renormalise");
  spec.distribution = wind_distribution(deck.section("wind_distribution"), spec.distribution_text);
  for (std::size_t i = 0; i < deck.size("runs"); ++i) {
    const std::string item = fmt::format("runs[{}]", i);
    const std::filesystem::path run_file = deck.string(item + ".file");
    const std::filesystem::path base = std::filesystem::path(deck.location(item + ".file").file).parent_path();
    spec.runs.push_back({run_file.is_absolute() ? run_file : base / run_file, deck.number(item + ".wind_speed_m_s")});
  }
  spec.fatigue = fatigue_config(deck.section("fatigue"));
  return spec;
}

}  // namespace fowtsim::driver
