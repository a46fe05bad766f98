#include "decks/hydro_deck.hpp"

#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;

namespace {

// The potential_flow keys as written. The model they describe is built after read_into
// (add_potential_flow): it needs the platform's step and the WAMIT files.
struct PotentialFlowKeys {
  std::filesystem::path wamit_root;  // beside the deck file that names it
  double length_scale_m = 1.0;
  hydro::RadiationOptions radiation;  // step_s: the platform's step, set when the model is built
  bool excitation = true;
};

// hydro::Params and, for the potential_flow keys that are no Params field, PotentialFlowKeys.
struct HydroKeys : hydro::Params {
  std::optional<PotentialFlowKeys> potential_flow_keys;
};

// Each key once: name, schema and the field it fills (decks/deck_section.hpp).
const DeckSection<HydroKeys>& hydro_section() {
  using namespace hydro;
  static const DeckSection<HydroKeys> section = [] {
    auto coefficient = [](const char* doc) { return Schema::number().at_least(0.0).default_value(0.0).doc(doc); };
    DeckSection<MemberParams> member;
    member.key("end_a_body_m", number_vector(3, "end A in the platform body frame (origin: reference point at SWL)"),
               &MemberParams::end_a_body_m)
        .key("end_b_body_m", number_vector(3, "end B in the body frame; the axis runs A → B"), &MemberParams::end_b_body_m)
        .key("diameter_a_m", Schema::number().greater_than(0.0).doc("outer diameter at A"), &MemberParams::diameter_a_m)
        .key("diameter_b_m", Schema::number().greater_than(0.0).doc("outer diameter at B (linear taper between)"),
             &MemberParams::diameter_b_m)
        .key("cd", coefficient("transverse drag coefficient"), &MemberParams::cd)
        .key("ca", coefficient("transverse added-mass coefficient (Cm = 1 + Ca)"), &MemberParams::ca)
        .key("axial_ca_a", coefficient("axial added-mass coefficient at end A (on (2/3)πR³)"), &MemberParams::axial_ca_a)
        .key("axial_cd_a", coefficient("axial drag coefficient at end A"), &MemberParams::axial_cd_a)
        .key("axial_cp_a", Schema::number().at_least(0.0).default_value(1.0).doc("dynamic-pressure coefficient on end plate A"),
             &MemberParams::axial_cp_a)
        .key("axial_ca_b", coefficient("axial added-mass coefficient at end B"), &MemberParams::axial_ca_b)
        .key("axial_cd_b", coefficient("axial drag coefficient at end B"), &MemberParams::axial_cd_b)
        .key("axial_cp_b", Schema::number().at_least(0.0).default_value(1.0).doc("dynamic-pressure coefficient on end plate B"),
             &MemberParams::axial_cp_b)
        .key("strips", Schema::integer().at_least(1).at_most(10000).default_value(10).doc("Morison strips over the submerged part"),
             &MemberParams::strips);
    DeckSection<CurrentParams> current;
    current
        .key("profile", Schema::choice({"none", "uniform", "power_law"}).default_value("none").doc("current profile"),
             &CurrentParams::profile,
             [](const std::string& v) {
               return v == "uniform"     ? CurrentParams::Profile::uniform
                      : v == "power_law" ? CurrentParams::Profile::power_law
                                         : CurrentParams::Profile::none;
             })
        .key("surface_speed_m_s", Schema::number().at_least(0.0).default_value(0.0).doc("speed at z = 0"),
             &CurrentParams::surface_speed_m_s)
        .key("heading_deg", Schema::number().default_value(0.0).doc("direction the current flows to, from +x towards +y"),
             &CurrentParams::heading_rad, [](double deg) { return deg * 3.14159265358979323846 / 180.0; })
        .key("reference_depth_m", Schema::number().at_least(0.0).default_value(0.0).doc("power law: depth where it vanishes"),
             &CurrentParams::reference_depth_m)
        .key("power_law_exponent", Schema::number().greater_than(0.0).default_value(1.0 / 7.0).doc("power-law exponent"),
             &CurrentParams::power_law_exponent);
    DeckSection<PotentialFlowKeys> flow;
    flow.custom("wamit_root", Schema::string().doc("WAMIT output without extension, relative to this deck file: reads ROOT.1 "
                                                   "(A, B), ROOT.3 (excitation) and ROOT.hst (HydroDyn PotFile)"),
                [](const io::ValidatedDeck& d, const std::string& key, PotentialFlowKeys& f) { f.wamit_root = beside_deck(d, key); })
        .key("length_scale_m", Schema::number().greater_than(0.0).default_value(1.0).doc("WAMIT length scale (WAMITULEN)"),
             &PotentialFlowKeys::length_scale_m)
        .key("radiation", Schema::choice({"convolution", "state_space"}).default_value("convolution")
                              .doc("radiation memory: convolution of the kernel over the window (RdtnMod 1) or its "
                                   "fitted state-space form (RdtnMod 2, Kung's realisation)"),
             [](PotentialFlowKeys& f) -> RadiationMethod& { return f.radiation.method; },
             [](const std::string& v) { return v == "state_space" ? RadiationMethod::state_space : RadiationMethod::convolution; })
        .key("radiation_window_s", Schema::number().greater_than(0.0).default_value(60.0)
                                       .doc("memory kept by the convolution, and the span the state space is fitted on (RdtnTMax)"),
             [](PotentialFlowKeys& f) -> double& { return f.radiation.window_s; })
        .key("state_space_tolerance", Schema::number().greater_than(0.0).at_most(0.5).default_value(0.002)
                                          .doc("state_space: relative RMS error allowed per kernel entry"),
             [](PotentialFlowKeys& f) -> double& { return f.radiation.fit_tolerance; })
        .key("state_space_max_order", Schema::integer().at_least(2).at_most(40).default_value(20)
                                          .doc("state_space: largest order per kernel entry"),
             [](PotentialFlowKeys& f) -> int& { return f.radiation.fit_max_order; })
        .key("excitation", Schema::boolean().default_value(true)
                               .doc("first-order wave excitation from ROOT.3 at the initial position (ExctnMod 1)"),
             &PotentialFlowKeys::excitation);
    DeckSection<HydroKeys> h;
    h.key("water_density_kg_m3", Schema::number().greater_than(0.0).default_value(1025.0).doc("water density"),
          &Params::water_density_kg_m3)
        .key("gravity_m_s2", Schema::number().greater_than(0.0).default_value(9.80665).doc("gravity"), &Params::gravity_m_s2)
        .key("surface", Schema::choice({"still_water", "wave_elevation"}).default_value("still_water")
                            .doc("where Morison strips stop: z = 0, or the wave elevation at each member"),
             &Params::surface,
             [](const std::string& v) { return v == "wave_elevation" ? SurfaceModel::wave_elevation : SurfaceModel::still_water; })
        .key("hydrostatics", Schema::choice({"nonlinear", "linear"}).default_value("nonlinear")
                                 .doc("buoyancy of the members at the instantaneous pose, or ρgV0 − C_hst q with C_hst "
                                      "from potential_flow's ROOT.hst (HydroDyn with WAMIT)"),
             &Params::hydrostatics,
             [](const std::string& v) { return v == "linear" ? Hydrostatics::linear : Hydrostatics::nonlinear; })
        .key("displaced_volume_m3", Schema::number().greater_than(0.0).optional()
                                        .doc("linear hydrostatics: displaced volume at rest V0 (PtfmVol0)"),
             &Params::displaced_volume_m3)
        .section("potential_flow", flow, &HydroKeys::potential_flow_keys, true,
                 "WAMIT added mass, radiation memory and excitation; the members then carry drag only")
        .key("hydrostatic_quadrature_points", Schema::integer().at_least(2).at_most(64).default_value(16)
                                                  .doc("Gauss points over an obliquely cut member"),
             &Params::hydrostatic_quadrature_points)
        .list("members", member, &Params::members, 1, "circular members, split at joints")
        .section("current", current, &Params::current, true, "current added to the wave velocity")
        .key("added_force", number_vector(6, "constant load F0 about the reference point [N, N·m] (AddF0)").optional(),
             &Params::added_force)
        .key("added_stiffness", matrix6("linear stiffness C, row by row (AddCLin)").optional(), &Params::added_stiffness)
        .key("added_damping", matrix6("linear damping B, row by row (AddBLin)").optional(), &Params::added_damping)
        .key("added_quadratic_damping", matrix6("quadratic damping, row by row (AddBQuad)").optional(),
             &Params::added_quadratic_damping);
    return h;
  }();
  return section;
}

// The potential-flow model from its keys (f: the potential_flow section, for error locations):
// A(∞) and the radiation memory from ROOT.1, the excitation table from ROOT.3, and with linear
// hydrostatics C_hst from ROOT.hst.
void add_potential_flow(const io::ValidatedDeck& f, const PotentialFlowKeys& keys, double large_step_s, HydroDeck& deck) {
  hydro::Params& p = deck.params;
  if (!(keys.radiation.window_s > large_step_s))
    throw InputError({"hydro", std::nullopt, "potential_flow.radiation_window_s", "a window longer than the time step"},
                     where(f, "radiation_window_s") + fmt::format(": {} s is not longer than the time step {} s",
                                                                  keys.radiation.window_s, large_step_s));
  const io::WamitScales scales{p.water_density_kg_m3, p.gravity_m_s2, keys.length_scale_m};
  const auto with_extension = [&](const char* extension) { return std::filesystem::path(keys.wamit_root.string() + extension); };
  try {
    const io::WamitRadiation radiation = io::read_wamit_radiation(with_extension(".1"), scales);
    if (!radiation.added_mass_infinite_frequency)
      throw InputError({"io.wamit", std::nullopt, "PER = 0", "the infinite-frequency added mass"},
                       with_extension(".1").string() + ": no PER = 0 rows (infinite-frequency added mass)");
    hydro::RadiationOptions options = keys.radiation;
    options.step_s = large_step_s;
    hydro::PotentialFlowParams pf;
    pf.radiation = hydro::make_radiation_model({radiation.frequencies_rad_s, radiation.damping,
                                                *radiation.added_mass_infinite_frequency},
                                               options);
    pf.excitation = keys.excitation;
    p.potential_flow = std::move(pf);
    if (keys.excitation) {
      deck.excitation = io::read_wamit_excitation(with_extension(".3"), scales);
      io::check_same_frequencies(radiation, with_extension(".1"), *deck.excitation, with_extension(".3"));
    }
    if (p.hydrostatics == hydro::Hydrostatics::linear)
      p.hydrostatic_stiffness = io::read_wamit_hydrostatics(with_extension(".hst"), scales);
  } catch (const InputError& e) {
    throw InputError(e.context(), where(f, "wamit_root") + ": " + e.message());
  }
}

}  // namespace

Schema hydro_schema() { return hydro_section().schema(); }

HydroDeck read_hydro_deck(const io::ValidatedDeck& d, double large_step_s) {
  HydroKeys keys;
  hydro_section().read_into(d, keys);
  // Cross-key check: linear hydrostatics take C_hst from ROOT.hst and need V0.
  if (keys.hydrostatics == hydro::Hydrostatics::linear && (!keys.potential_flow_keys || !d.has("displaced_volume_m3")))
    throw InputError({"hydro", std::nullopt, "hydrostatics", "potential_flow (its ROOT.hst) and displaced_volume_m3"},
                     where(d, "hydrostatics") + ": linear hydrostatics need the potential_flow section (C_hst from "
                                                "ROOT.hst) and displaced_volume_m3");
  HydroDeck deck{static_cast<const hydro::Params&>(keys), std::nullopt};
  if (keys.potential_flow_keys) add_potential_flow(d.section("potential_flow"), *keys.potential_flow_keys, large_step_s, deck);
  located(d, [&] { hydro::validate(deck.params); });
  return deck;
}

}  // namespace fowtsim::driver
