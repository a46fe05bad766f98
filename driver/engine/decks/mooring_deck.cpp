#include "decks/mooring_deck.hpp"

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;

Schema mooring_schema() {
  const Schema line = Schema::map({
      {"anchor_m", number_vector(3, "anchor position, inertial frame (z up, SWL = 0)")},
      {"fairlead_body_m", number_vector(3, "fairlead relative to the platform reference point, body frame")},
      {"unstretched_length_m", Schema::number().greater_than(0.0).doc("unstretched line length")},
      {"mass_per_length_kg_m", Schema::number().at_least(0.0).default_value(0.0).doc("mass per length in air (catenary)")},
      {"diameter_m", Schema::number().at_least(0.0).default_value(0.0).doc("volume-equivalent diameter for buoyancy (catenary)")},
      {"ea_N", Schema::number().greater_than(0.0).doc("axial stiffness EA (tension per unit strain)")},
      {"seabed_friction", Schema::number().at_least(0.0).default_value(0.0).doc("seabed friction coefficient C_B (catenary)")},
  });
  return Schema::map({
      {"model", Schema::choice({"catenary", "taut"}).default_value("catenary")
                    .doc("quasi-static elastic catenary with seabed contact, or massless taut springs")},
      {"depth_m", Schema::number().greater_than(0.0).doc("water depth (seabed at z = −depth)")},
      {"water_density_kg_m3", Schema::number().greater_than(0.0).default_value(1025.0).doc("water density")},
      {"gravity_m_s2", Schema::number().greater_than(0.0).default_value(9.80665).doc("gravity")},
      {"delta_yaw_stiffness_N_m_rad", Schema::number().at_least(0.0).default_value(0.0)
                                          .doc("yaw spring standing for a delta connection (not also in hydro)")},
      {"solver", Schema::map({
                     // The ranges are the module's own (mooring::validate), so the deck reader stops at the line.
                     {"tolerance", Schema::number().at_least(1e-15).at_most(1e-3).default_value(1e-10)
                                       .doc("closure tolerance, a fraction of the line length")},
                     {"max_newton_iterations", Schema::integer().at_least(1).at_most(1000).default_value(50).doc("per attempt")},
                     {"max_bisection_iterations", Schema::integer().at_least(60).at_most(10000).default_value(200)
                                                      .doc("per level of the nested-bisection fallback")},
                 }).optional().doc("catenary solver settings")},
      {"lines", Schema::sequence(line).min_items(1).doc("mooring lines")},
  });
}

mooring::MooringParams mooring_params(const io::ValidatedDeck& d) {
  mooring::MooringParams p;
  p.model = mooring::line_model_from_name(d.string("model"));
  p.depth_m = d.number("depth_m");
  p.water_density_kg_m3 = d.number("water_density_kg_m3");
  p.gravity_m_s2 = d.number("gravity_m_s2");
  p.delta_yaw_stiffness_N_m_rad = d.number("delta_yaw_stiffness_N_m_rad");
  if (d.has("solver")) {
    p.solver.tolerance = d.number("solver.tolerance");
    p.solver.max_newton_iterations = static_cast<int>(d.integer("solver.max_newton_iterations"));
    p.solver.max_bisection_iterations = static_cast<int>(d.integer("solver.max_bisection_iterations"));
  }
  for (std::size_t i = 0; i < d.size("lines"); ++i) {
    const io::ValidatedDeck l = d.section(fmt::format("lines[{}]", i));
    mooring::LineParams lp;
    lp.anchor_m = vec3(l, "anchor_m");
    lp.fairlead_body_m = vec3(l, "fairlead_body_m");
    lp.unstretched_length_m = l.number("unstretched_length_m");
    lp.mass_per_length_kg_m = l.number("mass_per_length_kg_m");
    lp.diameter_m = l.number("diameter_m");
    lp.ea_N = l.number("ea_N");
    lp.seabed_friction = l.number("seabed_friction");
    p.lines.push_back(lp);
  }
  located(d, [&] { mooring::validate(p); });
  return p;
}

}  // namespace fowtsim::driver
