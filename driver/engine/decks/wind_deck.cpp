#include "decks/wind_deck.hpp"

#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;
using wind::TurbulenceParams;
using wind::WindParams;

namespace {

// Each key once: name, schema and the Params field it fills (decks/deck_section.hpp). A range is
// the module's own (wind::validate), so a deck outside it stops at its line.
const DeckSection<WindParams>& wind_section() {
  static const DeckSection<WindParams> section = [] {
    DeckSection<TurbulenceParams> t;
    t.key("class", Schema::choice({"A", "B", "C"}).default_value("B").doc("IEC turbulence category (I_ref 0.16/0.14/0.12)"),
          &TurbulenceParams::category, wind::parse_turbulence_category)
        .key("model", Schema::choice({"NTM", "ETM"}).default_value("NTM").doc("IEC normal or extreme turbulence model"),
             &TurbulenceParams::model, wind::parse_turbulence_model)
        .key("iec_wind_class", Schema::integer().at_least(1).at_most(3).default_value(1).doc("IEC wind class I/II/III (ETM)"),
             &TurbulenceParams::iec_wind_class)
        .key("ny", Schema::integer().at_least(2).at_most(1024).default_value(31).doc("grid points across"), &TurbulenceParams::ny)
        .key("nz", Schema::integer().at_least(2).at_most(1024).default_value(31).doc("grid points vertically"), &TurbulenceParams::nz)
        .key("width_m", Schema::number().greater_than(0.0).default_value(145.0).doc("grid width, centred on y = 0"),
             &TurbulenceParams::width_m)
        .key("height_m", Schema::number().greater_than(0.0).default_value(145.0).doc("grid height, centred on the reference height"),
             &TurbulenceParams::height_m)
        .key("dt_s", Schema::number().greater_than(0.0).default_value(0.05).doc("time step of the field"), &TurbulenceParams::dt_s)
        .key("duration_s", Schema::number().greater_than(0.0).default_value(630.0).doc("length of the periodic record"),
             &TurbulenceParams::duration_s)
        .key("seed", Schema::integer().at_least(0).default_value(1).doc("random seed"), &TurbulenceParams::seed);
    DeckSection<WindParams> w;
    w.key("model", Schema::choice({"steady", "power_law", "log", "bts", "turbulent"}).default_value("steady").doc("inflow model"),
          &WindParams::model, wind::parse_wind_model)
        .key("speed_m_s", Schema::number().at_least(0.0).at_most(100.0).doc("mean horizontal speed at the reference height"), &WindParams::speed_m_s)
        .key("reference_height_m", Schema::number().greater_than(0.0).default_value(90.0).doc("reference (hub) height above SWL"),
             &WindParams::reference_height_m)
        .key("shear_exponent", Schema::number().at_least(-1.0).at_most(2.0).default_value(0.2).doc("power-law exponent"), &WindParams::shear_exponent)
        .key("roughness_m", Schema::number().greater_than(0.0).default_value(0.03).doc("log-law roughness length"),
             &WindParams::roughness_m)
        .key("direction_deg", Schema::number().at_least(-360.0).at_most(360.0).default_value(0.0).doc("propagation direction, + turns +x towards −y"),
             &WindParams::direction_deg)
        .key("upflow_deg", Schema::number().at_least(-45.0).at_most(45.0).default_value(0.0).doc("upflow angle"), &WindParams::upflow_deg)
        .custom("file", Schema::string().optional().doc("TurbSim .bts file (model bts), relative to this deck"),
                [](const io::ValidatedDeck& d, const std::string& key, WindParams& p) {
                  // `model` is declared above, so read first: only model bts reads the file.
                  p.file = (p.model == wind::WindModel::bts ? file_beside_deck(d, key) : beside_deck(d, key)).string();
                })
        .key("probe_point_m", number_vector(3, "point of Wind1VelX/Y/Z, inertial").optional(), &WindParams::probe_point_m)
        .section("turbulence", t, &WindParams::turbulence, true, "generator settings (model turbulent)");
    return w;
  }();
  return section;
}

}  // namespace

Schema wind_schema() { return wind_section().schema(); }

wind::WindParams wind_params(const io::ValidatedDeck& d) {
  wind::WindParams p = wind_section().read(d);
  located(d, [&] { wind::validate(p); });
  return p;
}

}  // namespace fowtsim::driver
