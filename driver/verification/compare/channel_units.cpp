#include "compare/channel_units.hpp"

#include <numbers>
#include <optional>
#include <string_view>

#include <fmt/format.h>

namespace fowtsim::driver {
namespace {

struct KnownUnit {
  std::string_view name;
  std::string_view quantity;
  double to_si;  // value in this unit × to_si = value in the quantity's SI unit
};

constexpr double kDeg = std::numbers::pi / 180.0;
// The units OpenFAST's modules and ours write (moments normalised to "-": N-m, kN-m, MN-m).
constexpr KnownUnit kUnits[] = {
    {"N", "force", 1.0},           {"kN", "force", 1e3},           {"MN", "force", 1e6},
    {"N-m", "moment", 1.0},        {"kN-m", "moment", 1e3},        {"MN-m", "moment", 1e6},
    {"rad", "angle", 1.0},         {"deg", "angle", kDeg},
    {"rad/s", "angular speed", 1.0}, {"deg/s", "angular speed", kDeg}, {"rpm", "angular speed", std::numbers::pi / 30.0},
    {"rad/s^2", "angular acceleration", 1.0}, {"deg/s^2", "angular acceleration", kDeg},
    {"m", "length", 1.0},          {"mm", "length", 1e-3},
    {"W", "power", 1.0},           {"kW", "power", 1e3},           {"MW", "power", 1e6},
};

std::optional<KnownUnit> known(const std::string& unit) {
  for (const KnownUnit& u : kUnits)
    if (u.name == unit) return u;
  return std::nullopt;
}

}  // namespace

std::string normalised_unit(const std::string& unit) {
  std::string u;
  for (std::size_t i = 0; i < unit.size(); ++i) {
    const char c = unit[i];
    if (c == ' ' || c == '\t' || c == '(' || c == ')' || c == '[' || c == ']') continue;
    if (unit.compare(i, 2, "·") == 0) {  // U+00B7 MIDDLE DOT (two bytes in UTF-8): kN·m is kN-m
      u += '-';
      ++i;
      continue;
    }
    u += (c == '*' || c == '.') ? '-' : c;
  }
  if (u == "Nm" || u == "kNm" || u == "MNm") u.insert(u.size() - 1, "-");
  return u;
}

UnitMatch match_units(const std::string& reference_unit, const std::string& test_unit) {
  const std::string ref = normalised_unit(reference_unit), test = normalised_unit(test_unit);
  if (ref == test) return {};
  const auto r = known(ref), t = known(test);
  if (!r || !t)
    return {1.0, fmt::format("units ({}) and ({}) differ and ({}) has no known conversion", test, ref, !t ? test : ref)};
  if (r->quantity != t->quantity)
    return {1.0, fmt::format("units ({}) and ({}) measure different things ({} against {})", test, ref, t->quantity, r->quantity)};
  return {t->to_si / r->to_si, {}};
}

}  // namespace fowtsim::driver
