#include "decks/wind_deck.hpp"

#include <filesystem>

#include "decks/deck_helpers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;

Schema wind_schema() {
  const Schema turbulence = Schema::map({
      {"class", Schema::choice({"A", "B", "C"}).default_value("B").doc("IEC turbulence category (I_ref 0.16/0.14/0.12)")},
      {"model", Schema::choice({"NTM", "ETM"}).default_value("NTM").doc("IEC normal or extreme turbulence model")},
      {"iec_wind_class", Schema::integer().at_least(1).at_most(3).default_value(1).doc("IEC wind class I/II/III (ETM)")},
      {"ny", Schema::integer().at_least(2).default_value(31).doc("grid points across")},
      {"nz", Schema::integer().at_least(2).default_value(31).doc("grid points vertically")},
      {"width_m", Schema::number().greater_than(0.0).default_value(145.0).doc("grid width, centred on y = 0")},
      {"height_m", Schema::number().greater_than(0.0).default_value(145.0).doc("grid height, centred on the reference height")},
      {"dt_s", Schema::number().greater_than(0.0).default_value(0.05).doc("time step of the field")},
      {"duration_s", Schema::number().greater_than(0.0).default_value(630.0).doc("length of the periodic record")},
      {"seed", Schema::integer().at_least(0).default_value(1).doc("random seed")},
  });
  return Schema::map({
      {"model", Schema::choice({"steady", "power_law", "log", "bts", "turbulent"}).default_value("steady").doc("inflow model")},
      {"speed_m_s", Schema::number().at_least(0.0).doc("mean horizontal speed at the reference height")},
      {"reference_height_m", Schema::number().greater_than(0.0).default_value(90.0).doc("reference (hub) height above SWL")},
      {"shear_exponent", Schema::number().default_value(0.2).doc("power-law exponent")},
      {"roughness_m", Schema::number().greater_than(0.0).default_value(0.03).doc("log-law roughness length")},
      {"direction_deg", Schema::number().default_value(0.0).doc("propagation direction, + turns +x towards −y")},
      {"upflow_deg", Schema::number().default_value(0.0).doc("upflow angle")},
      {"file", Schema::string().optional().doc("TurbSim .bts file (model bts), relative to this deck")},
      {"probe_point_m", number_vector(3, "point of Wind1VelX/Y/Z, inertial").optional()},
      {"turbulence", turbulence.optional().doc("generator settings (model turbulent)")},
  });
}

wind::WindParams wind_params(const io::ValidatedDeck& d) {
  wind::WindParams p;
  p.model = wind::parse_wind_model(d.string("model"));
  p.speed_m_s = d.number("speed_m_s");
  p.reference_height_m = d.number("reference_height_m");
  p.shear_exponent = d.number("shear_exponent");
  p.roughness_m = d.number("roughness_m");
  p.direction_deg = d.number("direction_deg");
  p.upflow_deg = d.number("upflow_deg");
  if (d.has("file")) {
    const std::filesystem::path file = d.string("file");
    p.file = (file.is_absolute() ? file : std::filesystem::path(d.location("file").file).parent_path() / file).string();
  }
  if (d.has("probe_point_m")) p.probe_point_m = vec3(d, "probe_point_m");
  if (d.has("turbulence")) {
    const io::ValidatedDeck t = d.section("turbulence");
    p.turbulence.category = wind::parse_turbulence_category(t.string("class"));
    p.turbulence.model = wind::parse_turbulence_model(t.string("model"));
    p.turbulence.iec_wind_class = static_cast<int>(t.integer("iec_wind_class"));
    p.turbulence.ny = static_cast<int>(t.integer("ny"));
    p.turbulence.nz = static_cast<int>(t.integer("nz"));
    p.turbulence.width_m = t.number("width_m");
    p.turbulence.height_m = t.number("height_m");
    p.turbulence.dt_s = t.number("dt_s");
    p.turbulence.duration_s = t.number("duration_s");
    p.turbulence.seed = static_cast<std::uint64_t>(t.integer("seed"));
  }
  located(d, [&] { wind::validate(p); });
  return p;
}

}  // namespace fowtsim::driver
