#include "decks/controller_deck.hpp"

#include <filesystem>
#include <numbers>
#include <optional>

#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;
using control::BaselineParams;
using control::ExternalSettings;

namespace {

// One `events` item as written: angles in degrees, speeds in the channel's rpm.
struct WhenDeck {
  std::string channel;
  double above = 0.0;
};
struct EventDeck {
  std::string type;
  std::optional<double> at_s;
  std::optional<WhenDeck> when;
  std::optional<double> pitch_rate_deg_s;
  std::optional<int> blade;
  std::optional<double> target_deg;
  double shutdown_delay_s = 0.2;
};

// What the section fills: the type, the parameters of either controller, and the events.
struct ControllerDeck {
  std::string type;
  BaselineParams baseline;
  ExternalSettings external;
  bool has_library = false;
  std::string operating_mode;
  std::optional<std::vector<EventDeck>> events;
  control::BrakeParams brake;
};

DeckSection<WhenDeck> when_section() {
  DeckSection<WhenDeck> s;
  s.key("channel", Schema::choice({"GenSpeed", "RotSpeed"}).doc("the measured speed the condition watches"), &WhenDeck::channel)
      .key("above", Schema::number().doc("fires the first large step the channel exceeds this, in the channel's unit (rpm)"),
           &WhenDeck::above);
  return s;
}

DeckSection<EventDeck> event_section() {
  DeckSection<EventDeck> s;
  s.key("type", Schema::choice({"shutdown", "emergency_stop", "grid_loss", "brake", "pitch_runaway", "pitch_stuck", "startup"})
                    .doc("what happens (modules/control/README.md, \"Control and fault events\")"),
        &EventDeck::type)
      .key("at_s", Schema::number().at_least(0.0).optional().doc("time of the event (or `when`)"), &EventDeck::at_s)
      .section("when", when_section(), &EventDeck::when, true, "condition of the event (or `at_s`); fires once")
      .key("pitch_rate_deg_s", Schema::number().greater_than(0.0).optional().doc(
               "pitch rate of shutdown, emergency_stop, grid_loss's shutdown, startup, pitch_runaway; default the "
               "controller's max_pitch_rate_rad_s (NREL 5MW: 8 deg/s)"),
           &EventDeck::pitch_rate_deg_s)
      .key("blade", Schema::integer().at_least(1).at_most(3).optional().doc("the faulty blade (pitch_runaway, pitch_stuck)"),
           &EventDeck::blade)
      .key("target_deg", Schema::number().at_least(-90.0).at_most(90.0).optional().doc(
               "pitch_runaway's end pitch; default the controller's min_pitch_rad (a runaway to fine pitch)"),
           &EventDeck::target_deg)
      .key("shutdown_delay_s", Schema::number().at_least(0.0).default_value(0.2).doc(
               "grid_loss: time from the loss to the pitch-to-feather manoeuvre (protection reaction)"),
           &EventDeck::shutdown_delay_s);
  return s;
}

DeckSection<control::BrakeParams> brake_section() {
  const control::BrakeParams d{};
  DeckSection<control::BrakeParams> s;
  s.key("torque_N_m", Schema::number().at_least(0.0).default_value(d.torque_N_m).doc(
            "fully deployed HSS brake torque (ServoDyn HSSBrTqF; NREL 5MW 28116.2)"),
        &control::BrakeParams::torque_N_m)
      .key("engage_time_s", Schema::number().at_least(0.0).default_value(d.engage_time_s).doc(
               "time for the brake torque to ramp from 0 to full (ServoDyn HSSBrDT, HSSBrMode 1)"),
           &control::BrakeParams::engage_time_s);
  return s;
}

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
    s.key("operating_mode", Schema::choice({"operating", "idling", "parked"}).default_value("operating").doc(
              "initial mode: the law in charge; idling (pitch at feather, generator off, rotor free); parked (idling + brake on)"),
          &ControllerDeck::operating_mode)
        .list("events", event_section(), &ControllerDeck::events, 0,
              "control and fault events, each at a time (`at_s`) or on a condition (`when`)");
    s.section("brake", brake_section(), &ControllerDeck::brake, true, "the high-speed-shaft brake");
    return s;
  }();
  return section;
}

}  // namespace

Schema controller_schema() { return controller_section().schema(); }

namespace {

// The events of the deck in SI, defaults from the law (controller_deck.hpp).
control::EventsParams events_of(const io::ValidatedDeck& c, const ControllerDeck& deck) {
  constexpr double kRad = std::numbers::pi / 180.0, kRadPerRpm = std::numbers::pi / 30.0;
  const bool discon = deck.type == "discon";
  const double rate = discon ? deck.external.max_pitch_rate_rad_s : deck.baseline.max_pitch_rate_rad_s;
  const double min_pitch = discon ? deck.external.min_pitch_rad : deck.baseline.min_pitch_rad;
  control::EventsParams p;
  p.mode = control::operating_mode_from_name(deck.operating_mode);
  p.brake = deck.brake;
  p.feather_pitch_rad = discon ? deck.external.max_pitch_rad : deck.baseline.max_pitch_rad;
  p.cut_in_speed_rad_s = deck.baseline.cut_in_speed_rad_s;  // a DISCON's: the 5MW's VS_CtInSp (the key's default)
  if (!deck.events) return p;
  for (std::size_t i = 0; i < deck.events->size(); ++i) {
    const EventDeck& d = (*deck.events)[i];
    const std::string key = fmt::format("events[{}]", i);
    control::EventParams e;
    e.type = control::event_type_from_name(d.type);
    if (d.at_s.has_value() == d.when.has_value())
      throw InputError({"control", std::nullopt, "controller." + key, "either at_s or when"},
                       where(c, key) + ": give exactly one of `at_s` (a time) and `when` (a condition)");
    const bool fault = e.type == control::EventType::pitch_runaway || e.type == control::EventType::pitch_stuck;
    if (fault != d.blade.has_value())
      throw InputError({"control", std::nullopt, "controller." + key + ".blade", "a blade exactly for pitch faults"},
                       where(c, key) + (fault ? ": a pitch fault needs `blade` (1..3)" : ": `blade` applies to pitch faults only"));
    if (d.target_deg && e.type != control::EventType::pitch_runaway)
      throw InputError({"control", std::nullopt, "controller." + key + ".target_deg", "pitch_runaway"},
                       where(c, key + ".target_deg") + ": `target_deg` applies to pitch_runaway only");
    if (d.at_s) {
      e.at_s = *d.at_s;
    } else {
      e.channel = control::trigger_channel_from_name(d.when->channel);
      e.above = d.when->above * kRadPerRpm;
    }
    e.pitch_rate_rad_s = d.pitch_rate_deg_s ? *d.pitch_rate_deg_s * kRad : rate;
    e.blade = d.blade ? *d.blade - 1 : 0;
    e.target_pitch_rad = d.target_deg ? *d.target_deg * kRad : min_pitch;
    e.shutdown_delay_s = d.shutdown_delay_s;
    p.events.push_back(e);
  }
  return p;
}

ControllerParams law_of(const io::ValidatedDeck& c, const ControllerDeck& deck) {
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
}

}  // namespace

ControllerParams controller_params(const io::ValidatedDeck& c) { return controller_setup(c).law; }

ControllerSetup controller_setup(const io::ValidatedDeck& c) {
  ControllerDeck deck;
  try {
    controller_section().read_into(c, deck);
  } catch (const InputError& e) {
    rethrow_located(c, e);
  }
  control::EventsParams events = events_of(c, deck);  // located at their own keys
  try {
    control::validate(events);
    return {law_of(c, deck), std::move(events)};
  } catch (const InputError& e) {
    rethrow_located(c, e);
  }
}

}  // namespace fowtsim::driver
