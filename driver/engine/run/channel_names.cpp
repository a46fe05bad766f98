#include "run/channel_names.hpp"

#include <algorithm>
#include <cctype>
#include <regex>

#include <fmt/format.h>

#include "fowtsim/io/suggest.hpp"

namespace fowtsim::driver {
namespace {

// Numbered aliases: OpenFAST's `prefix N suffix` is our `ours N`. Only pairs of one definition:
// MAP++'s T[i] and T_a[i] are the tension magnitudes at line i's fairlead and anchor, as our
// FAIRTENi and ANCHTENi (MoorDyn's names), in N both. Line i is the same line in both: in
// OpenFAST's OC3 run and ours the difference T[2] − T[3] correlates with PtfmSway as
// FAIRTEN2 − FAIRTEN3 does (−0.91 and −0.83 over 100–600 s), so MAP++'s `repeat` numbering
// matches our deck's line order.
struct NumberedAlias {
  const char* prefix;
  const char* suffix;
  const char* ours;
  const char* what;
};
constexpr NumberedAlias kAliases[] = {
    {"T[", "]", "FAIRTEN", "fairlead tension"},
    {"T_a[", "]", "ANCHTEN", "anchor tension"},
};

// OpenFAST channels fowtsim does not write, and why (patterns are case-insensitive, whole name).
struct NotWritten {
  const char* pattern;
  const char* reason;
};
constexpr NotWritten kNotWritten[] = {
    {R"(ConvIter|ConvError|NumUJac)",
     "OpenFAST's glue-code solver diagnostics (convergence iterations, Jacobian updates): no counterpart in fowtsim"},
    {R"(TTDsp(FA|SS))", "the tower-top deflection: written with the flexible tower (structure.tower.flexible: true)"},
    {R"(TTDspTwst|TwHt\d+(RD[xyz]|TP[xyz]|TDz)t|YawBr(TD|RD|TV|RV|RA)[xyz][pt])",
     "a tower twist, rotation or axial deflection, or a yaw-bearing deflection or velocity: not computed; the flexible "
     "tower has bending modes only (fowtsim writes TTDspFA/SS, TwHt<k>TD{x,y}t and YawBrTA{x,y,z}p)"},
    {R"(TwHt\d+TD[xy]t)", "a tower gauge deflection: written at the heights of structure.tower.gauge_heights_m on the "
                          "flexible tower"},
    {R"(TwHt\d+[FM]L[xyz]t)",
     "tower loads at a gauge height: written at the heights of structure.tower.gauge_heights_m; the tower-base (TwrBs*) "
     "and yaw-bearing (YawBr*) loads always"},
    {R"(TwrClrnc\d)", "blade-to-tower clearance: written with rigid and Rayleigh–Ritz blades, not yet with the MBBT blades"},
    {R"(TipClrnc\d|B\dN\d+Clrnc)", "tip-to-tower clearance along the blade (AeroDyn's): not computed; fowtsim writes TwrClrnc<b>"},
    {R"(Spn\d+[FM]L[xyz][bg]\d)",
     "ElastoDyn's blade span gauges: written at the fractions of structure.rotor.rayleigh_ritz_blade_gauges (Rayleigh–Ritz "
     "blades) or blades.gauges_eta (MBBT blades)"},
    {R"(Spn\d+(TD|RD)[xyz]b\d)", "ElastoDyn's span-gauge deflections: not computed; fowtsim writes the tip deflections"},
    {R"(LSSGag\w+|LSSTip\w+)",
     "low-speed-shaft gage/tip output: not computed; fowtsim writes LSShftFxa and LSShftMxa"},
    {R"(Ptfm[TR][VA][xyz]t)",
     "platform motion in the tower-base frame (t): fowtsim writes it in the inertial frame (PtfmTAxi, PtfmRVxi …), "
     "other components once the platform pitches"},
    {R"(NcIMU(TV|RV|RA)[xyz]s)",
     "nacelle IMU velocity or rotational acceleration: not computed; fowtsim writes NcIMUTAxs … (translational "
     "acceleration)"},
    {R"(B\d(Surge|Sway|Heave|Roll|Pitch|Yaw)|B\d[TR][VA][xyz]i)",
     "HydroDyn's WAMIT-body motion: fowtsim writes the platform's (PtfmSurge …, PtfmTVxi …, angles in deg), the same "
     "point only when the body's reference is the platform reference point"},
    {R"(B\d(Wvs|Rdt)[FM][xyz]i)", "a potential-flow load part: written only when the deck has hydro.potential_flow"},
    {R"(B\dTipRD[xyz]r)",
     "BeamDyn's tip rotation (Wiener-Milenkovic parameters): written by BeamDyn-driver runs; the turbine writes "
     "TipRDxb1 … [deg]"},
};

std::string lower(std::string_view text) {
  std::string s(text);
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// The number N of `prefix N suffix` in `name` (case-insensitive), or nothing.
std::optional<std::string> numbered(std::string_view name, std::string_view prefix, std::string_view suffix) {
  const std::string n = lower(name), p = lower(prefix), s = lower(suffix);
  if (n.size() <= p.size() + s.size() || !n.starts_with(p) || !n.ends_with(s)) return std::nullopt;
  const std::string digits = n.substr(p.size(), n.size() - p.size() - s.size());
  if (!std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); })) return std::nullopt;
  return digits;
}

const std::string* find_ignoring_case(const std::string& name, const std::vector<std::string>& available) {
  const std::string wanted = lower(name);
  for (const std::string& a : available)
    if (lower(a) == wanted) return &a;
  return nullptr;
}

}  // namespace

std::optional<ChannelAlias> builtin_alias(std::string_view name) {
  for (const NumberedAlias& a : kAliases) {
    const auto from_openfast = numbered(name, a.prefix, a.suffix);
    const auto from_ours = numbered(name, a.ours, "");
    const auto& n = from_openfast ? from_openfast : from_ours;
    if (n)
      return ChannelAlias{fmt::format("{}{}{}", a.prefix, *n, a.suffix), fmt::format("{}{}", a.ours, *n),
                          fmt::format("MAP++'s {} of line {}", a.what, *n)};
  }
  return std::nullopt;
}

std::string why_missing(const std::string& name, const std::vector<std::string>& available) {
  if (const auto alias = builtin_alias(name)) {
    const bool asked_openfast = lower(name) == lower(alias->openfast);
    const std::string& other = asked_openfast ? alias->ours : alias->openfast;
    if (const std::string* present = find_ignoring_case(other, available))
      return fmt::format("{} is {} as {} names it: did you mean `{}`?", name, alias->source,
                         asked_openfast ? "OpenFAST" : "fowtsim", *present);
  }
  for (const NotWritten& entry : kNotWritten)
    if (std::regex_match(name, std::regex(entry.pattern, std::regex::icase))) return entry.reason;
  return io::did_you_mean(name, available, io::LetterCase::ignored);
}

}  // namespace fowtsim::driver
