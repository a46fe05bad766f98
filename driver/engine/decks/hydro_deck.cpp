#include "decks/hydro_deck.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;

namespace {

Schema member_schema() {
  auto coefficient = [](const char* doc) { return Schema::number().at_least(0.0).default_value(0.0).doc(doc); };
  return Schema::map({
      {"end_a_body_m", number_vector(3, "end A in the platform body frame (origin: reference point at SWL)")},
      {"end_b_body_m", number_vector(3, "end B in the body frame; the axis runs A → B")},
      {"diameter_a_m", Schema::number().greater_than(0.0).doc("outer diameter at A")},
      {"diameter_b_m", Schema::number().greater_than(0.0).doc("outer diameter at B (linear taper between)")},
      {"cd", coefficient("transverse drag coefficient")},
      {"ca", coefficient("transverse added-mass coefficient (Cm = 1 + Ca)")},
      {"axial_ca_a", coefficient("axial added-mass coefficient at end A (on (2/3)πR³)")},
      {"axial_cd_a", coefficient("axial drag coefficient at end A")},
      {"axial_cp_a", Schema::number().at_least(0.0).default_value(1.0).doc("dynamic-pressure coefficient on end plate A")},
      {"axial_ca_b", coefficient("axial added-mass coefficient at end B")},
      {"axial_cd_b", coefficient("axial drag coefficient at end B")},
      {"axial_cp_b", Schema::number().at_least(0.0).default_value(1.0).doc("dynamic-pressure coefficient on end plate B")},
      {"strips", Schema::integer().at_least(1).at_most(10000).default_value(10).doc("Morison strips over the submerged part")},
  });
}

Schema current_schema() {
  return Schema::map({
      {"profile", Schema::choice({"none", "uniform", "power_law"}).default_value("none").doc("current profile")},
      {"surface_speed_m_s", Schema::number().at_least(0.0).default_value(0.0).doc("speed at z = 0")},
      {"heading_deg", Schema::number().default_value(0.0).doc("direction the current flows to, from +x towards +y")},
      {"reference_depth_m", Schema::number().at_least(0.0).default_value(0.0).doc("power law: depth where it vanishes")},
      {"power_law_exponent", Schema::number().greater_than(0.0).default_value(1.0 / 7.0).doc("power-law exponent")},
  });
}

Schema potential_flow_schema() {
  return Schema::map({
      {"wamit_root", Schema::string().doc("WAMIT output without extension, relative to this deck file: reads ROOT.1 "
                                          "(A, B), ROOT.3 (excitation) and ROOT.hst (HydroDyn PotFile)")},
      {"length_scale_m", Schema::number().greater_than(0.0).default_value(1.0).doc("WAMIT length scale (WAMITULEN)")},
      {"radiation", Schema::choice({"convolution", "state_space"}).default_value("convolution")
                        .doc("radiation memory: convolution of the kernel over the window (RdtnMod 1) or its "
                             "fitted state-space form (RdtnMod 2, Kung's realisation)")},
      {"radiation_window_s", Schema::number().greater_than(0.0).default_value(60.0)
                                 .doc("memory kept by the convolution, and the span the state space is fitted on (RdtnTMax)")},
      {"state_space_tolerance", Schema::number().greater_than(0.0).at_most(0.5).default_value(0.002)
                                    .doc("state_space: relative RMS error allowed per kernel entry")},
      {"state_space_max_order", Schema::integer().at_least(2).at_most(40).default_value(20)
                                    .doc("state_space: largest order per kernel entry")},
      {"excitation", Schema::boolean().default_value(true)
                         .doc("first-order wave excitation from ROOT.3 at the initial position (ExctnMod 1)")},
  });
}

}  // namespace

Schema hydro_schema() {
  return Schema::map({
      {"water_density_kg_m3", Schema::number().greater_than(0.0).default_value(1025.0).doc("water density")},
      {"gravity_m_s2", Schema::number().greater_than(0.0).default_value(9.80665).doc("gravity")},
      {"surface", Schema::choice({"still_water", "wave_elevation"}).default_value("still_water")
                      .doc("where Morison strips stop: z = 0, or the wave elevation at each member")},
      {"hydrostatics", Schema::choice({"nonlinear", "linear"}).default_value("nonlinear")
                           .doc("buoyancy of the members at the instantaneous pose, or ρgV0 − C_hst q with C_hst "
                                "from potential_flow's ROOT.hst (HydroDyn with WAMIT)")},
      {"displaced_volume_m3", Schema::number().greater_than(0.0).optional()
                                  .doc("linear hydrostatics: displaced volume at rest V0 (PtfmVol0)")},
      {"potential_flow", potential_flow_schema().optional()
                             .doc("WAMIT added mass, radiation memory and excitation; the members then carry drag only")},
      {"hydrostatic_quadrature_points", Schema::integer().at_least(2).at_most(64).default_value(16)
                                            .doc("Gauss points over an obliquely cut member")},
      {"members", Schema::sequence(member_schema()).min_items(1).doc("circular members, split at joints")},
      {"current", current_schema().optional().doc("current added to the wave velocity")},
      {"added_force", number_vector(6, "constant load F0 about the reference point [N, N·m] (AddF0)").optional()},
      {"added_stiffness", matrix6("linear stiffness C, row by row (AddCLin)").optional()},
      {"added_damping", matrix6("linear damping B, row by row (AddBLin)").optional()},
      {"added_quadratic_damping", matrix6("quadratic damping, row by row (AddBQuad)").optional()},
  });
}

HydroDeck read_hydro_deck(const io::ValidatedDeck& d, double large_step_s) {
  HydroDeck deck;
  hydro::Params& p = deck.params;
  p.water_density_kg_m3 = d.number("water_density_kg_m3");
  p.gravity_m_s2 = d.number("gravity_m_s2");
  p.surface = d.string("surface") == "wave_elevation" ? hydro::SurfaceModel::wave_elevation
                                                      : hydro::SurfaceModel::still_water;
  p.hydrostatic_quadrature_points = static_cast<int>(d.integer("hydrostatic_quadrature_points"));
  for (std::size_t i = 0; i < d.size("members"); ++i) {
    const io::ValidatedDeck m = d.section(fmt::format("members[{}]", i));
    hydro::MemberParams mp;
    mp.end_a_body_m = vec3(m, "end_a_body_m");
    mp.end_b_body_m = vec3(m, "end_b_body_m");
    mp.diameter_a_m = m.number("diameter_a_m");
    mp.diameter_b_m = m.number("diameter_b_m");
    mp.cd = m.number("cd");
    mp.ca = m.number("ca");
    mp.axial_ca_a = m.number("axial_ca_a");
    mp.axial_cd_a = m.number("axial_cd_a");
    mp.axial_cp_a = m.number("axial_cp_a");
    mp.axial_ca_b = m.number("axial_ca_b");
    mp.axial_cd_b = m.number("axial_cd_b");
    mp.axial_cp_b = m.number("axial_cp_b");
    mp.strips = static_cast<int>(m.integer("strips"));
    p.members.push_back(mp);
  }
  if (d.has("current")) {
    const io::ValidatedDeck c = d.section("current");
    const std::string profile = c.string("profile");
    p.current.profile = profile == "uniform"     ? hydro::CurrentParams::Profile::uniform
                        : profile == "power_law" ? hydro::CurrentParams::Profile::power_law
                                                 : hydro::CurrentParams::Profile::none;
    p.current.surface_speed_m_s = c.number("surface_speed_m_s");
    p.current.heading_rad = c.number("heading_deg") * 3.14159265358979323846 / 180.0;
    p.current.reference_depth_m = c.number("reference_depth_m");
    p.current.power_law_exponent = c.number("power_law_exponent");
  }
  if (d.has("added_force")) p.added_force = vec6(d, "added_force");
  p.added_stiffness = mat6(d, "added_stiffness");
  p.added_damping = mat6(d, "added_damping");
  p.added_quadratic_damping = mat6(d, "added_quadratic_damping");
  const bool linear = d.string("hydrostatics") == "linear";
  if (linear && (!d.has("potential_flow") || !d.has("displaced_volume_m3")))
    throw InputError({"hydro", std::nullopt, "hydrostatics", "potential_flow (its ROOT.hst) and displaced_volume_m3"},
                     where(d, "hydrostatics") + ": linear hydrostatics need the potential_flow section (C_hst from "
                                                "ROOT.hst) and displaced_volume_m3");
  if (d.has("potential_flow")) {
    const io::ValidatedDeck f = d.section("potential_flow");
    if (!(f.number("radiation_window_s") > large_step_s))
      throw InputError({"hydro", std::nullopt, "potential_flow.radiation_window_s", "a window longer than the time step"},
                       where(f, "radiation_window_s") + fmt::format(": {} s is not longer than the time step {} s",
                                                                    f.number("radiation_window_s"), large_step_s));
    const std::filesystem::path root = beside_deck(f, "wamit_root");
    const io::WamitScales scales{p.water_density_kg_m3, p.gravity_m_s2, f.number("length_scale_m")};
    const auto with_extension = [&](const char* extension) { return std::filesystem::path(root.string() + extension); };
    try {
      const io::WamitRadiation radiation = io::read_wamit_radiation(with_extension(".1"), scales);
      if (!radiation.added_mass_infinite_frequency)
        throw InputError({"io.wamit", std::nullopt, "PER = 0", "the infinite-frequency added mass"},
                         with_extension(".1").string() + ": no PER = 0 rows (infinite-frequency added mass)");
      hydro::RadiationOptions options;
      options.method = f.string("radiation") == "state_space" ? hydro::RadiationMethod::state_space
                                                              : hydro::RadiationMethod::convolution;
      options.window_s = f.number("radiation_window_s");
      options.step_s = large_step_s;
      options.fit_tolerance = f.number("state_space_tolerance");
      options.fit_max_order = static_cast<int>(f.integer("state_space_max_order"));
      hydro::PotentialFlowParams pf;
      pf.radiation = hydro::make_radiation_model({radiation.frequencies_rad_s, radiation.damping,
                                                  *radiation.added_mass_infinite_frequency},
                                                 options);
      pf.excitation = f.boolean("excitation");
      p.potential_flow = std::move(pf);
      if (f.boolean("excitation")) deck.excitation = io::read_wamit_excitation(with_extension(".3"), scales);
      if (linear) p.hydrostatic_stiffness = io::read_wamit_hydrostatics(with_extension(".hst"), scales);
    } catch (const InputError& e) {
      throw InputError(e.context(), where(f, "wamit_root") + ": " + e.message());
    }
  }
  if (linear) {
    p.hydrostatics = hydro::Hydrostatics::linear;
    p.displaced_volume_m3 = d.number("displaced_volume_m3");
  }
  located(d, [&] { hydro::validate(p); });
  return deck;
}

}  // namespace fowtsim::driver
