#include "decks/controller_deck.hpp"

#include <filesystem>

#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;
using control::BaselineParams;
using control::ExternalSettings;

namespace {

// What the section fills: the type, and the parameters of either controller.
struct ControllerDeck {
  std::string type;
  BaselineParams baseline;
  ExternalSettings external;
  bool has_library = false;
};

// A key of the built-in law: BaselineParams::*field, its default the land-based NREL 5MW value.
using BaselineField = double BaselineParams::*;
// Pitch limits and efficiency serve both laws (DISCON records 6–9, GenPwr): one key, two fields.
using SharedField = std::pair<double BaselineParams::*, double ExternalSettings::*>;

// ServoDyn's "SIMPLE VARIABLE-SPEED TORQUE CONTROL" inputs in SI units: no defaults, all four given.
DeckSection<control::SimpleVsParams> simple_vs_section() {
  using control::SimpleVsParams;
  DeckSection<SimpleVsParams> s;
  s.key("rated_generator_speed_rad_s", Schema::number().doc("VS_RtGnSp (ServoDyn: rpm × π/30)"), &SimpleVsParams::rated_generator_speed_rad_s)
      .key("rated_torque_N_m", Schema::number().doc("VS_RtTq: rated torque, constant in region 3"), &SimpleVsParams::rated_torque_N_m)
      .key("region2_gain_N_m_s2", Schema::number().doc("VS_Rgn2K in N·m/(rad/s)² (ServoDyn: N·m/rpm² × (30/π)²)"),
           &SimpleVsParams::region2_gain_N_m_s2)
      .key("slip_percent", Schema::number().doc("VS_SlPc: rated slip of the region-2½ line"), &SimpleVsParams::slip_percent);
  return s;
}

// Each key once: name, schema and the field it fills (decks/deck_section.hpp).
const DeckSection<ControllerDeck>& controller_section() {
  static const DeckSection<ControllerDeck> section = [] {
    const BaselineParams d{};
    auto baseline = [&](DeckSection<ControllerDeck>& s, const char* key, BaselineField field, const char* doc) {
      s.key(key, Schema::number().default_value(d.*field).doc(doc), [field](ControllerDeck& c) -> double& { return c.baseline.*field; });
    };
    auto shared = [&](DeckSection<ControllerDeck>& s, const char* key, SharedField fields, const char* doc) {
      s.custom(key, Schema::number().default_value(d.*fields.first).doc(doc),
               [fields](const io::ValidatedDeck& deck, const std::string& k, ControllerDeck& c) {
                 c.baseline.*fields.first = c.external.*fields.second = deck.number(k);
               });
    };
    DeckSection<ControllerDeck> s;
    s.key("type", Schema::choice({"baseline", "discon"}).default_value("baseline").doc("built-in NREL 5MW law or a DISCON library"),
          &ControllerDeck::type);
    s.key("generator", Schema::choice({"baseline", "simple_vs"}).default_value("baseline").doc("torque law: the baseline schedule or ServoDyn's simple variable-speed law (VSContrl 1)"),
          [](ControllerDeck& c) -> control::GeneratorLaw& { return c.baseline.generator; }, control::generator_law_from_name);
    s.key("pitch", Schema::choice({"baseline", "fixed"}).default_value("baseline").doc("pitch law: the baseline PI or none, blades held at their initial pitch (PCMode 0)"),
          [](ControllerDeck& c) -> control::PitchLaw& { return c.baseline.pitch; }, control::pitch_law_from_name);
    s.section("simple_vs", simple_vs_section(), [](ControllerDeck& c) -> control::SimpleVsParams& { return c.baseline.simple_vs; }, true,
              "ServoDyn's simple variable-speed law (generator simple_vs), HSS side");
    baseline(s, "sample_time_s", &BaselineParams::sample_time_s, "controller sample time (0: every call)");
    baseline(s, "filter_corner_rad_s", &BaselineParams::filter_corner_rad_s, "generator-speed low-pass corner");
    baseline(s, "cut_in_speed_rad_s", &BaselineParams::cut_in_speed_rad_s, "VS_CtInSp (HSS)");
    baseline(s, "region2_start_speed_rad_s", &BaselineParams::region2_start_speed_rad_s, "VS_Rgn2Sp");
    baseline(s, "region2_gain_N_m_s2", &BaselineParams::region2_gain_N_m_s2, "VS_Rgn2K");
    baseline(s, "rated_generator_speed_rad_s", &BaselineParams::rated_generator_speed_rad_s, "VS_RtGnSp");
    baseline(s, "rated_power_W", &BaselineParams::rated_power_W, "VS_RtPwr");
    baseline(s, "slip_percent", &BaselineParams::slip_percent, "VS_SlPc");
    baseline(s, "max_torque_N_m", &BaselineParams::max_torque_N_m, "VS_MaxTq");
    baseline(s, "max_torque_rate_N_m_s", &BaselineParams::max_torque_rate_N_m_s, "VS_MaxRat");
    baseline(s, "region3_min_pitch_rad", &BaselineParams::region3_min_pitch_rad, "VS_Rgn3MP");
    s.key("region3_torque", Schema::choice({"constant_power", "constant_torque"}).default_value("constant_power").doc("torque above rated"),
          [](ControllerDeck& c) -> control::Region3Torque& { return c.baseline.region3_torque; }, control::region3_torque_from_name);
    baseline(s, "reference_speed_rad_s", &BaselineParams::reference_speed_rad_s, "PC_RefSpd");
    baseline(s, "proportional_gain_s", &BaselineParams::proportional_gain_s, "PC_KP");
    baseline(s, "integral_gain", &BaselineParams::integral_gain, "PC_KI");
    baseline(s, "gain_schedule_pitch_rad", &BaselineParams::gain_schedule_pitch_rad, "PC_KK");
    shared(s, "min_pitch_rad", {&BaselineParams::min_pitch_rad, &ExternalSettings::min_pitch_rad}, "PC_MinPit");
    shared(s, "max_pitch_rad", {&BaselineParams::max_pitch_rad, &ExternalSettings::max_pitch_rad}, "PC_MaxPit");
    shared(s, "max_pitch_rate_rad_s", {&BaselineParams::max_pitch_rate_rad_s, &ExternalSettings::max_pitch_rate_rad_s}, "PC_MaxRat");
    shared(s, "generator_efficiency", {&BaselineParams::generator_efficiency, &ExternalSettings::generator_efficiency}, "for GenPwr");
    s.custom("library", Schema::string().optional().doc("DISCON shared library (type discon), relative to this deck"),
             [](const io::ValidatedDeck& deck, const std::string& k, ControllerDeck& c) {
               // Relative to the deck file, made absolute: a bare `libX.so` must not go to the system search path.
               const std::filesystem::path lib = deck.string(k);
               c.external.library_path =
                   std::filesystem::absolute(lib.is_absolute() ? lib : std::filesystem::path(deck.location(k).file).parent_path() / lib)
                       .lexically_normal()
                       .string();
               c.has_library = true;
             })
        .key("procedure", Schema::string().default_value("DISCON").doc("exported procedure name (type discon)"),
             [](ControllerDeck& c) -> std::string& { return c.external.procedure; })
        .key("infile", Schema::string().default_value("").doc("the controller's own input file, passed through (type discon)"),
             [](ControllerDeck& c) -> std::string& { return c.external.infile; });
    return s;
  }();
  return section;
}

}  // namespace

Schema controller_schema() { return controller_section().schema(); }

ControllerParams controller_params(const io::ValidatedDeck& c) {
  try {
    ControllerDeck deck;
    controller_section().read_into(c, deck);
    if (deck.type == "discon") {
      if (deck.baseline.generator != control::GeneratorLaw::baseline || deck.baseline.pitch != control::PitchLaw::baseline)
        throw InputError({"control", std::nullopt, "controller.type", "generator and pitch choose built-in laws: use type baseline"},
                         "type discon runs the library's own laws; `generator`/`pitch` apply to the built-in controller only");
      if (!deck.has_library)
        throw InputError({"control", std::nullopt, "controller.library", "a DISCON library path"}, "type discon needs `library`");
      return control::ExternalController::make_params(deck.external);
    }
    // A law's keys without the law (or the reverse) is a deck mistake, not something to ignore.
    if ((deck.baseline.generator == control::GeneratorLaw::simple_vs) != c.has("simple_vs"))
      throw InputError({"control", std::nullopt, "controller.simple_vs", "give `simple_vs` exactly when generator is simple_vs"},
                       c.has("simple_vs") ? "`simple_vs` given but generator is baseline" : "generator simple_vs needs the `simple_vs` section");
    control::validate(deck.baseline);
    return deck.baseline;
  } catch (const InputError& e) {
    rethrow_located(c, e);
  }
}

}  // namespace fowtsim::driver
