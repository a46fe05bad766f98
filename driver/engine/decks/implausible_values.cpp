#include "decks/implausible_values.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"

namespace fowtsim::driver {
namespace {

// A range of sense for one key: values outside [low, high] are legal but a slip of units
// (mm or km for m, g/cm³ or g/l for kg/m³, cm/s² for m/s²) far more often than a real design.
struct Sense {
  const char* path;  // key path from the deck root; its first part is a top-level section
  double low, high;
  const char* why;   // what a value outside suggests
};

constexpr std::array<Sense, 15> kSense = {{
    {"wind.reference_height_m", 0.0, 1000.0, "a hub height in km or mm?"},
    {"wind.speed_m_s", 0.0, 100.0, "km/h or knots for m/s? (the strongest gusts measured are ≈ 110 m/s)"},
    {"structure.tower.top_height_m", -1000.0, 1000.0, "a tower height in km or mm?"},
    {"structure.rotor.tip_radius_m", 0.0, 500.0, "a diameter in mm?"},
    {"aero.air_density_kg_m3", 0.5, 2.0, "g/m³ or a density in another unit? (air: 1.225 kg/m³ at sea level)"},
    {"waves.depth_m", 0.0, 11000.0, "deeper than the deepest ocean: a depth in mm? (deep water is .inf)"},
    {"mooring.depth_m", 0.0, 11000.0, "deeper than the deepest ocean: a depth in mm?"},
    {"waves.hs_m", 0.0, 30.0, "a wave height in cm or mm? (the highest measured Hs ≈ 20 m)"},
    {"waves.water_density_kg_m3", 900.0, 1100.0, "g/l or g/cm³ for kg/m³? (sea water: 1025 kg/m³)"},
    {"hydro.water_density_kg_m3", 900.0, 1100.0, "g/l or g/cm³ for kg/m³? (sea water: 1025 kg/m³)"},
    {"mooring.water_density_kg_m3", 900.0, 1100.0, "g/l or g/cm³ for kg/m³? (sea water: 1025 kg/m³)"},
    {"structure.gravity_m_s2", 9.0, 10.5, "cm/s² or ft/s² for m/s²? (0 switches gravity off)"},
    {"waves.gravity_m_s2", 9.0, 10.5, "cm/s² or ft/s² for m/s²?"},
    {"hydro.gravity_m_s2", 9.0, 10.5, "cm/s² or ft/s² for m/s²?"},
    {"mooring.gravity_m_s2", 9.0, 10.5, "cm/s² or ft/s² for m/s²?"},
}};

}  // namespace

std::vector<std::string> implausible_values(const io::ValidatedDeck& deck) {
  const std::vector<std::string> sections = deck.keys("");
  std::vector<std::string> warnings;
  for (const Sense& s : kSense) {
    const std::string path = s.path;
    // Only the sections this deck has: other scenes' schemas do not declare these paths.
    if (std::find(sections.begin(), sections.end(), path.substr(0, path.find('.'))) == sections.end()) continue;
    if (!deck.has(path)) continue;
    const double value = deck.number(path);
    if (path.ends_with("gravity_m_s2") && value == 0.0) continue;  // weightless on purpose (tests, checks)
    // .inf is the deck's deep water, not a slip
    if (std::isinf(value) || (value >= s.low && value <= s.high)) continue;
    warnings.push_back(fmt::format("{} = {:.6g}, outside {:g} … {:g}: {}", where(deck, path), value, s.low, s.high, s.why));
  }
  return warnings;
}

}  // namespace fowtsim::driver
