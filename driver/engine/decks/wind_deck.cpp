#include "decks/wind_deck.hpp"

#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;
using wind::TurbulenceParams;
using wind::WindEventParams;
using wind::WindParams;

namespace {

// Each key once: name, schema and the Params field it fills (decks/deck_section.hpp). A range is
// the module's own (wind::validate), so a deck outside it stops at its line.
const DeckSection<WindParams>& wind_section() {
  static const DeckSection<WindParams> section = [] {
    DeckSection<TurbulenceParams> t;
    t.key("class", Schema::choice({"A", "B", "C"}).default_value("B").doc("IEC turbulence category (I_ref 0.16/0.14/0.12)"),
          &TurbulenceParams::category, wind::parse_turbulence_category)
        .key("model", Schema::choice({"NTM", "ETM", "EWM"}).default_value("NTM")
                 .doc("IEC normal, extreme or extreme-wind-speed (σ1 = 0.11 V_hub) turbulence model"),
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
    DeckSection<WindEventParams> e;
    e.key("type", Schema::choice({"none", "EOG", "EDC", "ECD", "EWS_vertical", "EWS_horizontal"}).default_value("none")
                      .doc("IEC 61400-1 event superposed on the model's wind"),
          &WindEventParams::type, wind::parse_wind_event_type)
        .key("start_s", Schema::number().at_least(0.0).default_value(0.0).doc("time the event starts [s]"), &WindEventParams::start_s)
        .key("sign", Schema::integer().at_least(-1).at_most(1).default_value(1)
                         .doc("1 or -1: sense of the EDC/ECD turn (as direction_deg), sign of the EWS shear"),
             &WindEventParams::sign)
        .key("rotor_diameter_m", Schema::number().greater_than(0.0).optional().doc("rotor diameter D (required with an event)"),
             &WindEventParams::rotor_diameter_m)
        .key("iec_wind_class", Schema::integer().at_least(1).at_most(3).default_value(1).doc("IEC wind class I/II/III (V_ref 50/42.5/37.5 m/s)"),
             &WindEventParams::iec_wind_class)
        .key("turbulence_class", Schema::choice({"A", "B", "C"}).default_value("B").doc("IEC turbulence category of the events' NTM σ1"),
             &WindEventParams::turbulence_class, wind::parse_turbulence_category);
    DeckSection<WindParams> w;
    w.key("model", Schema::choice({"steady", "power_law", "log", "bts", "turbulent", "uniform_file"}).default_value("steady").doc("inflow model"),
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
        .custom("file", Schema::string().optional().doc("TurbSim .bts (model bts) or OpenFAST uniform wind .hh file (model uniform_file), relative to this deck"),
                [](const io::ValidatedDeck& d, const std::string& key, WindParams& p) {
                  // `model` is declared above, so read first: only models bts and uniform_file read the file.
                  const bool read = p.model == wind::WindModel::bts || p.model == wind::WindModel::uniform_file;
                  p.file = (read ? file_beside_deck(d, key) : beside_deck(d, key)).string();
                  // A uniform wind file is small: read here, so a bad row stops the deck at its file:line.
                  if (p.model == wind::WindModel::uniform_file) p.uniform = wind::read_uniform_wind_file(p.file);
                })
        .key("reference_length_m", Schema::number().greater_than(0.0).optional()
                                       .doc("InflowWind RefLength of the uniform file's linear shears (model uniform_file)"),
             &WindParams::reference_length_m)
        .key("probe_point_m", number_vector(3, "point of Wind1VelX/Y/Z, inertial").optional(), &WindParams::probe_point_m)
        .section("turbulence", t, &WindParams::turbulence, true, "generator settings (model turbulent)")
        .section("event", e, &WindParams::event, true, "IEC 61400-1 wind event (EOG, EDC, ECD, EWS)");
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
