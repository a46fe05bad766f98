#include "decks/controller_deck.hpp"

#include <filesystem>

#include "decks/deck_helpers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;

Schema controller_schema() {
  const control::BaselineParams d{};  // the land-based NREL 5MW values as defaults
  auto num = [](double v, const char* doc) { return Schema::number().default_value(v).doc(doc); };
  return Schema::map({
      {"type", Schema::choice({"baseline", "discon"}).default_value("baseline").doc("built-in NREL 5MW law or a DISCON library")},
      {"sample_time_s", num(d.sample_time_s, "controller sample time (0: every call)")},
      {"filter_corner_rad_s", num(d.filter_corner_rad_s, "generator-speed low-pass corner")},
      {"cut_in_speed_rad_s", num(d.cut_in_speed_rad_s, "VS_CtInSp (HSS)")},
      {"region2_start_speed_rad_s", num(d.region2_start_speed_rad_s, "VS_Rgn2Sp")},
      {"region2_gain_N_m_s2", num(d.region2_gain_N_m_s2, "VS_Rgn2K")},
      {"rated_generator_speed_rad_s", num(d.rated_generator_speed_rad_s, "VS_RtGnSp")},
      {"rated_power_W", num(d.rated_power_W, "VS_RtPwr")},
      {"slip_percent", num(d.slip_percent, "VS_SlPc")},
      {"max_torque_N_m", num(d.max_torque_N_m, "VS_MaxTq")},
      {"max_torque_rate_N_m_s", num(d.max_torque_rate_N_m_s, "VS_MaxRat")},
      {"region3_min_pitch_rad", num(d.region3_min_pitch_rad, "VS_Rgn3MP")},
      {"region3_torque", Schema::choice({"constant_power", "constant_torque"}).default_value("constant_power").doc("torque above rated")},
      {"reference_speed_rad_s", num(d.reference_speed_rad_s, "PC_RefSpd")},
      {"proportional_gain_s", num(d.proportional_gain_s, "PC_KP")},
      {"integral_gain", num(d.integral_gain, "PC_KI")},
      {"gain_schedule_pitch_rad", num(d.gain_schedule_pitch_rad, "PC_KK")},
      {"min_pitch_rad", num(d.min_pitch_rad, "PC_MinPit")},
      {"max_pitch_rad", num(d.max_pitch_rad, "PC_MaxPit")},
      {"max_pitch_rate_rad_s", num(d.max_pitch_rate_rad_s, "PC_MaxRat")},
      {"generator_efficiency", num(d.generator_efficiency, "for GenPwr")},
      {"library", Schema::string().optional().doc("DISCON shared library (type discon), relative to this deck")},
      {"procedure", Schema::string().default_value("DISCON").doc("exported procedure name (type discon)")},
      {"infile", Schema::string().default_value("").doc("the controller's own input file, passed through (type discon)")},
  });
}

ControllerParams controller_params(const io::ValidatedDeck& c) {
  try {
    if (c.string("type") == "discon") {
      if (!c.has("library"))
        throw InputError({"control", std::nullopt, "controller.library", "a DISCON library path"}, "type discon needs `library`");
      control::ExternalSettings s;
      const std::filesystem::path lib = c.string("library");
      // Relative to the deck file, made absolute: a bare `libX.so` must not go to the system search path.
      s.library_path = std::filesystem::absolute(lib.is_absolute() ? lib : std::filesystem::path(c.location("library").file).parent_path() / lib)
                           .lexically_normal()
                           .string();
      s.procedure = c.string("procedure");
      s.infile = c.string("infile");
      s.min_pitch_rad = c.number("min_pitch_rad");
      s.max_pitch_rad = c.number("max_pitch_rad");
      s.max_pitch_rate_rad_s = c.number("max_pitch_rate_rad_s");
      s.generator_efficiency = c.number("generator_efficiency");
      return control::ExternalController::make_params(s);
    }
    control::BaselineParams p;
    p.sample_time_s = c.number("sample_time_s");
    p.filter_corner_rad_s = c.number("filter_corner_rad_s");
    p.cut_in_speed_rad_s = c.number("cut_in_speed_rad_s");
    p.region2_start_speed_rad_s = c.number("region2_start_speed_rad_s");
    p.region2_gain_N_m_s2 = c.number("region2_gain_N_m_s2");
    p.rated_generator_speed_rad_s = c.number("rated_generator_speed_rad_s");
    p.rated_power_W = c.number("rated_power_W");
    p.slip_percent = c.number("slip_percent");
    p.max_torque_N_m = c.number("max_torque_N_m");
    p.max_torque_rate_N_m_s = c.number("max_torque_rate_N_m_s");
    p.region3_min_pitch_rad = c.number("region3_min_pitch_rad");
    p.region3_torque = control::region3_torque_from_name(c.string("region3_torque"));
    p.reference_speed_rad_s = c.number("reference_speed_rad_s");
    p.proportional_gain_s = c.number("proportional_gain_s");
    p.integral_gain = c.number("integral_gain");
    p.gain_schedule_pitch_rad = c.number("gain_schedule_pitch_rad");
    p.min_pitch_rad = c.number("min_pitch_rad");
    p.max_pitch_rad = c.number("max_pitch_rad");
    p.max_pitch_rate_rad_s = c.number("max_pitch_rate_rad_s");
    p.generator_efficiency = c.number("generator_efficiency");
    control::validate(p);
    return p;
  } catch (const InputError& e) {
    rethrow_located(c, e);
  }
}

}  // namespace fowtsim::driver
