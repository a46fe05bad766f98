#include "decks/slender_deck.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/slender/shape_functions.hpp"

namespace fowtsim::driver {
namespace {

using io::Schema;

// The keys as written, each once with the field it fills (decks/deck_section.hpp); read_slender_deck
// turns them into the module's BodyDescription and Environment.
struct SegmentKeys {
  double length_m = 0.0, outer_diameter_m = 0.0, inner_diameter_m = 0.0, density_kg_m3 = 0.0, youngs_modulus_Pa = 0.0;
  double cd = 0.0, ca = 0.0, contents_density_kg_m3 = 0.0;
  int strips = 1;
};
struct EndKeys {
  std::string support;
  double translational_spring_N_m = 0.0, rotational_spring_N_m_rad = 0.0;
};
struct ShapeKeys {
  std::string family;
  int count = 0;
  double rotation_centre_m = 0.0;
};
struct BodyKeys {
  std::vector<SegmentKeys> segments;
  EndKeys bottom, top;
  double top_tension_N = 0.0, rayleigh_mass_1_s = 0.0, rayleigh_stiffness_s = 0.0;
  ShapeKeys shapes;
  std::optional<std::vector<slender::PointSpring>> point_springs;
  std::optional<std::vector<slender::PointMass>> point_masses;
};
struct SeaKeys {
  std::string model;
  std::optional<double> height_m, period_s, hs_m, tp_s, record_s, max_omega_rad_s;
  double gamma = 3.3, min_omega_rad_s = 0.0;
  std::uint64_t seed = 1;
};
struct AnalysisKeys {
  std::string domain;
  int modes = 0;
  double transient_s = 0.0;
  std::vector<double> stations_m;
  double drag_tolerance = 1e-6;
};

DeckSection<EndKeys> end_section(const char* supports_doc, std::vector<std::string> supports) {
  DeckSection<EndKeys> e;
  e.key("support", Schema::choice(std::move(supports)).default_value("free").doc(supports_doc), &EndKeys::support)
      .key("translational_spring_N_m", Schema::number().unit("N_m").at_least(0.0).default_value(0.0)
                                           .doc("spring on the end's deflection (mooring, tensioner)"),
           &EndKeys::translational_spring_N_m)
      .key("rotational_spring_N_m_rad", Schema::number().unit("N_m_rad").at_least(0.0).default_value(0.0)
                                            .doc("spring on the end's slope"),
           &EndKeys::rotational_spring_N_m_rad);
  return e;
}

const DeckSection<BodyKeys>& body_section() {
  static const DeckSection<BodyKeys> section = [] {
    DeckSection<SegmentKeys> segment;
    segment.key("length_m", Schema::number().unit("m").greater_than(0.0).doc("segment length along the body"), &SegmentKeys::length_m)
        .key("outer_diameter_m", Schema::number().unit("m").greater_than(0.0).doc("outer diameter D (hydrodynamics, bending)"),
             &SegmentKeys::outer_diameter_m)
        .key("inner_diameter_m", Schema::number().unit("m").at_least(0.0).default_value(0.0).doc("bore; 0 for a solid section"),
             &SegmentKeys::inner_diameter_m)
        .key("density_kg_m3", Schema::number().unit("kg_m3").greater_than(0.0).doc("wall material density"), &SegmentKeys::density_kg_m3)
        .key("youngs_modulus_Pa", Schema::number().unit("Pa").greater_than(0.0).doc("E; EI = E π(D⁴ − Dᵢ⁴)/64"),
             &SegmentKeys::youngs_modulus_Pa)
        .key("cd", Schema::number().at_least(0.0).doc("Morison drag coefficient on D"), &SegmentKeys::cd)
        .key("ca", Schema::number().at_least(0.0).doc("added-mass coefficient (Cm = 1 + Ca)"), &SegmentKeys::ca)
        .key("contents_density_kg_m3", Schema::number().unit("kg_m3").at_least(0.0).default_value(0.0)
                                           .doc("what fills the bore (oil, ballast): mass and weight"),
             &SegmentKeys::contents_density_kg_m3)
        .key("strips", Schema::integer().at_least(1).at_most(100000).default_value(1).doc("equal strips the segment is cut into"),
             &SegmentKeys::strips);
    DeckSection<ShapeKeys> shapes;
    shapes.key("family", Schema::choice({"clamped_free", "free_clamped", "pinned_pinned", "floating"})
                             .doc("clamped_free: uniform cantilever modes; free_clamped: the same clamped at the top (a hanging "
                                  "body); pinned_pinned: sin(nπx/L); floating: sway, rotation about rotation_centre_m, then `count` sines"),
               &ShapeKeys::family)
        .key("count", Schema::integer().at_least(0).at_most(200).doc("number of shape functions (floating: of flexible sines)"),
             &ShapeKeys::count)
        .key("rotation_centre_m", Schema::number().unit("m").default_value(0.0).doc("floating: x of the rotation shape's centre"),
             &ShapeKeys::rotation_centre_m);
    DeckSection<slender::PointSpring> spring;
    spring.key("x_m", Schema::number().unit("m").at_least(0.0).doc("where, from the bottom end (0 ≤ x ≤ L)"), &slender::PointSpring::x_m)
        .key("translational_N_m", Schema::number().unit("N_m").at_least(0.0).default_value(0.0)
                                      .doc("spring on the deflection there (a fairlead's mooring stiffness)"),
             &slender::PointSpring::translational_N_m)
        .key("rotational_N_m_rad", Schema::number().unit("N_m_rad").at_least(0.0).default_value(0.0).doc("spring on the slope there"),
             &slender::PointSpring::rotational_N_m_rad);
    DeckSection<slender::PointMass> mass;
    mass.key("x_m", Schema::number().unit("m").at_least(0.0).doc("where, from the bottom end (0 ≤ x ≤ L)"), &slender::PointMass::x_m)
        .key("mass_kg", Schema::number().unit("kg").at_least(0.0).doc("lumped mass (the RNA on a tower): inertia and weight"),
             &slender::PointMass::mass_kg)
        .key("rotary_inertia_kg_m2", Schema::number().unit("kg_m2").at_least(0.0).default_value(0.0)
                                         .doc("about the axis normal to the bending plane, on the slope's acceleration"),
             &slender::PointMass::rotary_inertia_kg_m2);
    DeckSection<BodyKeys> b;
    b.list("segments", segment, &BodyKeys::segments, 1, "uniform segments from the bottom end (x = 0) to the top (x = L)")
        .section("bottom", end_section("free | pinned | clamped", {"free", "pinned", "clamped"}), &BodyKeys::bottom, true,
                 "the bottom end (x = 0)")
        .section("top", end_section("free | pinned | clamped (clamped: over a free bottom without springs, a hanging body)",
                                    {"free", "pinned", "clamped"}),
                 &BodyKeys::top, true, "the top end (x = L)")
        .key("top_tension_N", Schema::number().unit("N").at_least(0.0).default_value(0.0).doc("effective tension at the top (tensioner)"),
             &BodyKeys::top_tension_N)
        .key("rayleigh_mass_1_s", Schema::number().unit("1_s").at_least(0.0).default_value(0.0).doc("α of C = αM + βK"),
             &BodyKeys::rayleigh_mass_1_s)
        .key("rayleigh_stiffness_s", Schema::number().unit("s").at_least(0.0).default_value(0.0).doc("β of C = αM + βK"),
             &BodyKeys::rayleigh_stiffness_s)
        .section("shapes", shapes, &BodyKeys::shapes, false, "shape functions v(x, t) = Σ φ_m(x) q_m(t)")
        .list("point_springs", spring, &BodyKeys::point_springs, 1, "springs at points along the body (fairleads, guides)")
        .list("point_masses", mass, &BodyKeys::point_masses, 1, "lumped masses at points along the body (the RNA, buoys)");
    return b;
  }();
  return section;
}

const DeckSection<slender::Environment>& water_section() {
  static const DeckSection<slender::Environment> section = [] {
    DeckSection<slender::Environment> w;
    w.key("density_kg_m3", Schema::number().unit("kg_m3").greater_than(0.0).default_value(1025.0).doc("sea water density"),
          &slender::Environment::water_density_kg_m3)
        .key("gravity_m_s2", Schema::number().unit("m_s2").greater_than(0.0).default_value(9.80665).doc("gravity"),
             &slender::Environment::gravity_m_s2)
        .key("still_water_level_m", Schema::number().unit("m").doc("x of the still water surface (from the bottom end)"),
             &slender::Environment::still_water_level_m)
        .key("depth_m", Schema::number().unit("m").at_least(0.0).default_value(0.0).doc("water depth; 0 = deep water"),
             &slender::Environment::water_depth_m);
    return w;
  }();
  return section;
}

const DeckSection<SeaKeys>& sea_section() {
  static const DeckSection<SeaKeys> section = [] {
    const auto positive = [](const char* unit, const char* doc) { return Schema::number().unit(unit).greater_than(0.0).optional().doc(doc); };
    DeckSection<SeaKeys> s;
    s.key("model", Schema::choice({"regular", "jonswap"}).doc("a regular (Airy) wave or a JONSWAP sea"), &SeaKeys::model)
        .key("height_m", positive("m", "regular: wave height H = 2a"), &SeaKeys::height_m)
        .key("period_s", positive("s", "regular: wave period"), &SeaKeys::period_s)
        .key("hs_m", positive("m", "jonswap: significant wave height"), &SeaKeys::hs_m)
        .key("tp_s", positive("s", "jonswap: peak period"), &SeaKeys::tp_s)
        .key("gamma", Schema::number().at_least(1.0).default_value(3.3).doc("jonswap: peak shape γ"), &SeaKeys::gamma)
        .key("seed", Schema::integer().at_least(0).default_value(1).doc("jonswap: random phases (std::mt19937_64)"), &SeaKeys::seed)
        .key("record_s", positive("s", "jonswap: frequency step Δω = 2π/record_s; the time-domain sea repeats after it"),
             &SeaKeys::record_s)
        .key("min_omega_rad_s", Schema::number().unit("rad_s").at_least(0.0).default_value(0.0)
                                    .doc("jonswap: lowest component (ω_j = jΔω, j ≥ 1)"),
             &SeaKeys::min_omega_rad_s)
        .key("max_omega_rad_s", positive("rad_s", "jonswap: highest component"), &SeaKeys::max_omega_rad_s);
    return s;
  }();
  return section;
}

const DeckSection<AnalysisKeys>& analysis_section() {
  static const DeckSection<AnalysisKeys> section = [] {
    DeckSection<AnalysisKeys> a;
    a.key("domain", Schema::choice({"frequency", "time", "both"}).default_value("both")
                        .doc("frequency domain (linearised drag), time domain (nonlinear Morison, `simulation` span and step), or both"),
          &AnalysisKeys::domain)
        .key("modes", Schema::integer().at_least(0).default_value(0).doc("lowest undamped modes kept (0: all); mode acceleration recovers the rest"),
             &AnalysisKeys::modes)
        .key("transient_s", Schema::number().unit("s").at_least(0.0).default_value(0.0)
                                .doc("time domain: start-up left out of the amplitudes and RMS"),
             &AnalysisKeys::transient_s)
        .key("stations_m", Schema::sequence(Schema::number()).optional()
                               .doc("time-series stations, x from the bottom end (channels Stn1…)"),
             &AnalysisKeys::stations_m)
        .key("drag_tolerance", Schema::number().at_least(1e-14).at_most(1e-2).default_value(1e-6)
                                   .doc("frequency domain: the drag linearisation stops when γ changes by less than this "
                                        "share of its largest value (1e-6: far below the linearisation's own 1 % error)"),
             &AnalysisKeys::drag_tolerance);
    return a;
  }();
  return section;
}

}  // namespace

std::vector<io::SchemaField> slender_deck_fields() {
  return {
      {"slender", body_section().schema().doc("the slender body: segments, ends, tension, damping, shape functions")},
      {"water", water_section().schema().doc("sea water and the still water level")},
      {"sea", sea_section().schema().doc("regular wave or JONSWAP sea, travelling along the deflection")},
      {"analysis", analysis_section().schema().optional().doc("what to solve; absent = both domains, all modes")},
  };
}

namespace {

[[noreturn]] void bad(const io::ValidatedDeck& deck, const std::string& key, const std::string& expected, const std::string& what) {
  throw InputError({"slender", std::nullopt, key, expected}, where(deck, key) + ": " + what);
}

slender::Support support_of(const std::string& name) {
  return name == "pinned" ? slender::Support::Pinned : name == "clamped" ? slender::Support::Clamped : slender::Support::Free;
}

slender::BodyDescription body_of(const io::ValidatedDeck& deck, const BodyKeys& k) {
  slender::BodyDescription b;
  double length = 0.0;
  for (std::size_t i = 0; i < k.segments.size(); ++i) {
    const SegmentKeys& s = k.segments[i];
    if (!(s.inner_diameter_m < s.outer_diameter_m))
      bad(deck, fmt::format("slender.segments[{}].inner_diameter_m", i), "less than outer_diameter_m",
          fmt::format("the bore {} m is not inside the outer diameter {} m", s.inner_diameter_m, s.outer_diameter_m));
    const slender::Strip strip{s.length_m / s.strips, s.outer_diameter_m, s.inner_diameter_m, s.density_kg_m3,
                               s.youngs_modulus_Pa, s.cd, s.ca, s.contents_density_kg_m3};
    b.strips.insert(b.strips.end(), static_cast<std::size_t>(s.strips), strip);
    length += s.length_m;
  }
  b.bottom_support = support_of(k.bottom.support);
  b.top_support = support_of(k.top.support);
  b.bottom_springs = {k.bottom.translational_spring_N_m, k.bottom.rotational_spring_N_m_rad};
  b.top_springs = {k.top.translational_spring_N_m, k.top.rotational_spring_N_m_rad};
  b.top_tension_N = k.top_tension_N;
  if (b.top_support == slender::Support::Clamped) {
    // The inertia-relief moment then sums from the bottom end, whose conditions must be known.
    if (b.bottom_support != slender::Support::Free || b.bottom_springs.translational_N_m != 0.0 || b.bottom_springs.rotational_N_m_rad != 0.0)
      bad(deck, "slender.top.support", "a free bottom without springs under a clamped top",
          "a clamped top over a supported bottom: the inertia-relief moment would need a reaction that statics does not give");
    if (b.top_tension_N != 0.0)
      bad(deck, "slender.top_tension_N", "0 under a clamped top", "a hanging body's tension is the weight below each section");
  }
  // x ≤ L, the top end given as the segments' sum (to its rounding: then exactly L).
  const auto on_body = [&](const char* list, std::size_t i, double& x) {
    if (x > length * (1.0 + 1e-9))
      bad(deck, fmt::format("slender.{}[{}].x_m", list, i), fmt::format("at most the body's length {} m", length),
          fmt::format("x = {} m is beyond the top end", x));
    x = std::min(x, length);
  };
  if (k.point_springs) b.point_springs = *k.point_springs;
  if (k.point_masses) b.point_masses = *k.point_masses;
  for (std::size_t i = 0; i < b.point_springs.size(); ++i) on_body("point_springs", i, b.point_springs[i].x_m);
  for (std::size_t i = 0; i < b.point_masses.size(); ++i) on_body("point_masses", i, b.point_masses[i].x_m);
  b.rayleigh_mass_per_s = k.rayleigh_mass_1_s;
  b.rayleigh_stiffness_s = k.rayleigh_stiffness_s;
  const ShapeKeys& sh = k.shapes;
  if (sh.family != "floating" && sh.count < 1)
    bad(deck, "slender.shapes.count", "at least 1", sh.family + " needs at least one shape function");
  b.shapes = sh.family == "clamped_free"    ? slender::clamped_free_shapes(sh.count, length)
             : sh.family == "free_clamped"  ? slender::free_clamped_shapes(sh.count, length)
             : sh.family == "pinned_pinned" ? slender::pinned_pinned_shapes(sh.count, length)
                                            : slender::floating_shapes(sh.count, length, sh.rotation_centre_m);
  return b;
}

// The keys of the sea model in use must be there, the other model's must not.
SlenderSea sea_of(const io::ValidatedDeck& deck, const SeaKeys& k) {
  SlenderSea sea;
  sea.regular = k.model == "regular";
  const std::vector<std::pair<const char*, const std::optional<double>*>> regular = {{"height_m", &k.height_m}, {"period_s", &k.period_s}};
  const std::vector<std::pair<const char*, const std::optional<double>*>> jonswap = {
      {"hs_m", &k.hs_m}, {"tp_s", &k.tp_s}, {"record_s", &k.record_s}, {"max_omega_rad_s", &k.max_omega_rad_s}};
  for (const auto& [name, value] : sea.regular ? regular : jonswap)
    if (!value->has_value())
      throw InputError({"slender", std::nullopt, std::string("sea.") + name, "the keys of the sea model"},
                       where(deck, "sea") + fmt::format(": a {} sea needs {}", k.model, name));
  for (const auto& [name, value] : sea.regular ? jonswap : regular)
    if (value->has_value()) bad(deck, std::string("sea.") + name, "only the keys of the sea model", fmt::format("not a key of a {} sea", k.model));
  if (sea.regular) {
    sea.height_m = *k.height_m;
    sea.period_s = *k.period_s;
    return sea;
  }
  sea.hs_m = *k.hs_m;
  sea.tp_s = *k.tp_s;
  sea.gamma = k.gamma;
  sea.seed = k.seed;
  sea.record_s = *k.record_s;
  sea.min_omega_rad_s = k.min_omega_rad_s;
  sea.max_omega_rad_s = *k.max_omega_rad_s;
  if (!(sea.max_omega_rad_s > std::max(sea.min_omega_rad_s, 2 * std::numbers::pi / sea.record_s)))
    bad(deck, "sea.max_omega_rad_s", "above min_omega_rad_s and the first component 2π/record_s", "no wave component in the band");
  return sea;
}

// n with |n·step − span| within rounding, or none.
std::optional<long> whole_steps(double span, double step) {
  const long n = std::lround(span / step);
  return n >= 1 && std::abs(static_cast<double>(n) * step - span) <= 1e-9 * span ? std::optional(n) : std::nullopt;
}

// The solution holds its largest arrays whole in memory, strips × wave components values each (the
// JONSWAP transfer table, the time domain's sea coefficients and blocks): past about 2 GB a deck is
// refused here, naming the key, instead of failing as std::bad_alloc mid-solve.
void check_size(const io::ValidatedDeck& deck, const std::string& key, const std::string& expected, std::size_t strips,
                double samples, const char* what) {
  constexpr double kMaxValues = 4e7;
  if (static_cast<double>(strips) * samples > kMaxValues)
    bad(deck, key, expected,
        fmt::format("{} strips × {:.3g} {} is more than the {:.0e} values the solution can hold", strips, samples, what, kMaxValues));
}

}  // namespace

SlenderDeck read_slender_deck(const io::ValidatedDeck& deck, double time_step_s, double t_max_s) {
  SlenderDeck d;
  const BodyKeys body = body_section().read(deck.section("slender"));
  d.body = body_of(deck, body);
  water_section().read_into(deck.section("water"), d.environment);
  d.sea = sea_of(deck, sea_section().read(deck.section("sea")));
  AnalysisKeys analysis{"both", 0, 0.0, {}};
  if (deck.has("analysis")) analysis_section().read_into(deck.section("analysis"), analysis);
  d.analysis = {analysis.domain != "time", analysis.domain != "frequency", analysis.modes, analysis.transient_s, analysis.stations_m,
                analysis.drag_tolerance};
  const int shapes = static_cast<int>(d.body.shapes.size());
  if (d.analysis.modes > shapes)
    bad(deck, "analysis.modes", fmt::format("at most the {} shape functions", shapes), fmt::format("{} modes of {} shapes", d.analysis.modes, shapes));
  double length = 0.0;
  for (const slender::Strip& s : d.body.strips) length += s.length_m;
  for (std::size_t i = 0; i < d.analysis.stations_m.size(); ++i)
    if (d.analysis.stations_m[i] < 0.0 || d.analysis.stations_m[i] > length)
      bad(deck, fmt::format("analysis.stations_m[{}]", i), fmt::format("within the body, 0 … {} m", length),
          fmt::format("{} m is off the body", d.analysis.stations_m[i]));
  const std::size_t strips = d.body.strips.size();
  if (!d.sea.regular)
    check_size(deck, "sea.record_s", "a shorter record (fewer wave components) or fewer strips", strips,
               (d.sea.max_omega_rad_s - d.sea.min_omega_rad_s) * d.sea.record_s / (2 * std::numbers::pi), "wave components");
  if (d.analysis.time_domain) {
    // Nothing grows with the run (the sea comes in blocks, the statistics are sums); the sample
    // index and the random sea's phase exponents (wave_blocks.cpp) must stay exact integers.
    if (2 * t_max_s / time_step_s > 0x1p52)
      bad(deck, "simulation.t_max_s", "at most 2^51 steps of simulation.dt_s",
          fmt::format("{:.3g} half steps are more than a run can count", 2 * t_max_s / time_step_s));
    if (!d.sea.regular && 2 * d.sea.record_s / time_step_s > 0x1p30)
      bad(deck, "sea.record_s", "at most 2^30 half steps of simulation.dt_s in the record (a shorter record or a longer dt_s)",
          fmt::format("{:.3g} half steps of the record", 2 * d.sea.record_s / time_step_s));
    // The TD amplitude is a Fourier coefficient over whole wave periods; the random sea is sampled
    // at Δt/2 by an FFT of the record's length, so both must be whole numbers of steps.
    if (d.sea.regular && !whole_steps(d.sea.period_s, time_step_s))
      bad(deck, "sea.period_s", "a whole number of simulation.dt_s", fmt::format("{} s is not a whole number of {} s steps", d.sea.period_s, time_step_s));
    if (!d.sea.regular && !whole_steps(d.sea.record_s, 0.5 * time_step_s))
      bad(deck, "sea.record_s", "a whole number of half steps simulation.dt_s/2",
          fmt::format("{} s is not a whole number of {} s half steps", d.sea.record_s, 0.5 * time_step_s));
    const double kept = d.sea.regular ? d.sea.period_s : 2.0 * time_step_s;
    if (d.analysis.transient_s + kept > t_max_s)
      bad(deck, "analysis.transient_s", fmt::format("at most the simulated time less {} s", kept),
          fmt::format("{} s leaves no {} of the {} s simulated", d.analysis.transient_s, d.sea.regular ? "wave period" : "samples", t_max_s));
    if (d.sea.max_omega_rad_s >= std::numbers::pi / (0.5 * time_step_s))
      bad(deck, "sea.max_omega_rad_s", "below the Nyquist frequency 2π/dt_s of the half-step samples", "too high for simulation.dt_s");
  }
  return d;
}

}  // namespace fowtsim::driver
