#include "decks/mooring_deck.hpp"

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;
using mooring::CatenarySolverOptions;
using mooring::LineParams;
using mooring::MooringParams;

namespace {

// Each key once: name, schema and the Params field it fills (decks/deck_section.hpp).
const DeckSection<MooringParams>& mooring_section() {
  static const DeckSection<MooringParams> section = [] {
    DeckSection<LineParams> line;
    line.key("anchor_m", number_vector(3, "anchor position, inertial frame (z up, SWL = 0)"), &LineParams::anchor_m)
        .key("fairlead_body_m", number_vector(3, "fairlead relative to the platform reference point, body frame"),
             &LineParams::fairlead_body_m)
        .key("unstretched_length_m", Schema::number().greater_than(0.0).doc("unstretched line length"),
             &LineParams::unstretched_length_m)
        .key("mass_per_length_kg_m", Schema::number().at_least(0.0).default_value(0.0).doc("mass per length in air (catenary)"),
             &LineParams::mass_per_length_kg_m)
        .key("diameter_m", Schema::number().at_least(0.0).default_value(0.0).doc("volume-equivalent diameter for buoyancy (catenary)"),
             &LineParams::diameter_m)
        .key("ea_N", Schema::number().greater_than(0.0).doc("axial stiffness EA (tension per unit strain)"), &LineParams::ea_N)
        .key("seabed_friction", Schema::number().at_least(0.0).default_value(0.0).doc("seabed friction coefficient C_B (catenary)"),
             &LineParams::seabed_friction);
    // The ranges are the module's own (mooring::validate), so the deck reader stops at the line.
    DeckSection<CatenarySolverOptions> solver;
    solver.key("tolerance", Schema::number().at_least(1e-15).at_most(1e-3).default_value(1e-10)
                                .doc("closure tolerance, a fraction of the line length"),
               &CatenarySolverOptions::tolerance)
        .key("max_newton_iterations", Schema::integer().at_least(1).at_most(1000).default_value(50).doc("per attempt"),
             &CatenarySolverOptions::max_newton_iterations)
        .key("max_bisection_iterations", Schema::integer().at_least(60).at_most(10000).default_value(200)
                                             .doc("per level of the nested-bisection fallback"),
             &CatenarySolverOptions::max_bisection_iterations);
    DeckSection<MooringParams> m;
    m.key("model", Schema::choice({"catenary", "taut"}).default_value("catenary")
                       .doc("quasi-static elastic catenary with seabed contact, or massless taut springs"),
          &MooringParams::model, mooring::line_model_from_name)
        .key("depth_m", Schema::number().greater_than(0.0).doc("water depth (seabed at z = −depth)"), &MooringParams::depth_m)
        .key("water_density_kg_m3", Schema::number().greater_than(0.0).default_value(1025.0).doc("water density"),
             &MooringParams::water_density_kg_m3)
        .key("gravity_m_s2", Schema::number().greater_than(0.0).default_value(9.80665).doc("gravity"), &MooringParams::gravity_m_s2)
        .key("delta_yaw_stiffness_N_m_rad", Schema::number().at_least(0.0).default_value(0.0)
                                                .doc("yaw spring standing for a delta connection (not also in hydro)"),
             &MooringParams::delta_yaw_stiffness_N_m_rad)
        .section("solver", solver, &MooringParams::solver, true, "catenary solver settings")
        .list("lines", line, &MooringParams::lines, 1, "mooring lines");
    return m;
  }();
  return section;
}

}  // namespace

Schema mooring_schema() { return mooring_section().schema(); }

void check_mooring_at_initial_pose(const io::ValidatedDeck& deck, const mooring::MooringParams& mooring,
                                   const FrameMotion& initial_pose) {
  // Chain and wire rope break at a few per cent of strain, fibre ropes below 30 %: a line this much
  // longer than its unstretched length at the start is a wrong initial position or anchor.
  constexpr double kMaxStrain = 0.3;
  const std::string position_key = "structure.initial_conditions.platform_position_m";
  const auto refuse = [&](const std::string& line_key, const std::string& message) {
    const std::string key = deck.has(position_key) ? position_key : line_key;
    throw InputError({"mooring", std::nullopt, key, ""}, where(deck, key) + ": " + message);
  };
  if (!(initial_pose.position_m.z() > -mooring.depth_m))
    refuse("mooring.depth_m", fmt::format("the platform starts at z = {:g} m, at or below the seabed (mooring.depth_m {:g} m)",
                                          initial_pose.position_m.z(), mooring.depth_m));
  for (std::size_t i = 0; i < mooring.lines.size(); ++i) {
    const mooring::LineParams& line = mooring.lines[i];
    const Vec3 fairlead = initial_pose.position_m + initial_pose.orientation * line.fairlead_body_m;
    const double span_m = (fairlead - line.anchor_m).norm();
    if (span_m > (1.0 + kMaxStrain) * line.unstretched_length_m)
      refuse(fmt::format("mooring.lines[{}]", i),
             fmt::format("line {} spans {:.1f} m from anchor to fairlead at the initial pose, {:.0f} % more than its unstretched "
                         "length {:g} m (no line material stretches beyond {:.0f} %): check the initial position and the anchors",
                         i + 1, span_m, 100.0 * (span_m / line.unstretched_length_m - 1.0), line.unstretched_length_m,
                         100.0 * kMaxStrain));
  }
}

mooring::MooringParams mooring_params(const io::ValidatedDeck& d) {
  mooring::MooringParams p = mooring_section().read(d);
  located(d, [&] { mooring::validate(p); });
  return p;
}

}  // namespace fowtsim::driver
