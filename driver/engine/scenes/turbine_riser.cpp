#include "scenes/turbine_riser.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/pipe.hpp"
#include "fowtsim/beam/reference_line.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "scenes/sea_modules.hpp"

namespace fowtsim::driver {
namespace {

using io::Schema;

// The `riser:` keys: where the line hangs, the tube and its contents, the water around it, how it
// is discretised and stepped, and its outputs.
struct RiserKeys {
  Vec3 anchor_m = Vec3::Zero(), hang_off_m = Vec3::Zero();
  double stretch_m = 0.0;
  std::string bottom_end;
  double outer_diameter_m = 0.0, inner_diameter_m = 0.0, youngs_modulus_Pa = 0.0, poisson_ratio = 0.3, density_kg_m3 = 0.0;
  double damping_mu_s = 0.0;
  double fluid_density_kg_m3 = 0.0, flow_velocity_m_s = 0.0, fluid_viscosity_Pa_s = 0.0, wall_roughness_m = 0.0;
  double top_pressure_Pa = 0.0;
  double water_density_kg_m3 = 1025.0, inertia_coefficient = 2.0, drag_coefficient = 1.0;
  Vec3 current_m_s = Vec3::Zero();
  int segments = 50, substeps = 1;
  double spectral_radius = 0.0;
  std::vector<double> moment_gauges_eta;
};

const DeckSection<RiserKeys>& riser_section() {
  static const DeckSection<RiserKeys> section = [] {
    auto positive = [](const char* unit, const char* doc) { return Schema::number().unit(unit).greater_than(0.0).doc(doc); };
    auto non_negative = [](const char* unit, const char* doc) {
      return Schema::number().unit(unit).at_least(0.0).default_value(0.0).doc(doc);
    };
    DeckSection<RiserKeys> r;
    r.key("anchor_m", number_vector(3, "bottom end of the line on the seabed, global frame g [m]"), &RiserKeys::anchor_m)
        .key("hang_off_m", number_vector(3, "hang-off point (the line's pinned top) from the platform reference point, "
                                            "platform frame b [m]"),
             &RiserKeys::hang_off_m)
        .key("stretch_m", non_negative("m", "the straight line's unstretched length is the anchor-to-hang-off distance at "
                                            "t = 0 less this: its pretension (a vertical line: EA·stretch/L + w_s L/2 at the top)"),
             &RiserKeys::stretch_m)
        .key("bottom_end", Schema::choice({"clamped", "pinned"}).default_value("clamped").doc("how the anchor holds the line"),
             &RiserKeys::bottom_end)
        .key("outer_diameter_m", positive("m", "outer diameter of the wall (also the hydrodynamic diameter)"),
             &RiserKeys::outer_diameter_m)
        .key("inner_diameter_m", non_negative("m", "bore diameter (0: a solid rod, e.g. a power cable's equivalent section)"),
             &RiserKeys::inner_diameter_m)
        .key("youngs_modulus_Pa", positive("Pa", "Young's modulus of the wall"), &RiserKeys::youngs_modulus_Pa)
        .key("poisson_ratio", Schema::number().greater_than(-1.0).less_than(0.5).default_value(0.3).doc("G = E / (2 (1 + ν))"),
             &RiserKeys::poisson_ratio)
        .key("density_kg_m3", positive("kg_m3", "density of the wall"), &RiserKeys::density_kg_m3)
        .key("damping_mu_s", non_negative("s", "stiffness-proportional damping μ_K (seed 000 §3.4.3)"), &RiserKeys::damping_mu_s)
        .key("fluid_density_kg_m3", non_negative("kg_m3", "density of the contents (0: empty, a cable)"),
             &RiserKeys::fluid_density_kg_m3)
        .key("flow_velocity_m_s", Schema::number().unit("m_s").default_value(0.0).doc("mean flow speed, + up from the anchor"),
             &RiserKeys::flow_velocity_m_s)
        .key("fluid_viscosity_Pa_s", non_negative("Pa_s", "dynamic viscosity of the contents (0: no wall friction)"),
             &RiserKeys::fluid_viscosity_Pa_s)
        .key("wall_roughness_m", non_negative("m", "wall roughness ε of the Haaland friction factor"), &RiserKeys::wall_roughness_m)
        .key("top_pressure_Pa", Schema::number().unit("Pa").default_value(0.0).doc("internal gauge pressure at the top"),
             &RiserKeys::top_pressure_Pa)
        .key("water_density_kg_m3", Schema::number().unit("kg_m3").greater_than(0.0).default_value(1025.0).doc("sea water density"),
             &RiserKeys::water_density_kg_m3)
        .key("inertia_coefficient", Schema::number().at_least(1.0).default_value(2.0)
                                        .doc("Morison C_m (smooth cylinder, DNV-RP-C205 §6.7); added mass (C_m − 1) ρ A_e normal to the axis"),
             &RiserKeys::inertia_coefficient)
        .key("drag_coefficient", Schema::number().at_least(0.0).default_value(1.0)
                                     .doc("Morison C_d on the water's velocity relative to the line, normal to it"),
             &RiserKeys::drag_coefficient)
        .key("current_m_s", number_vector(3, "uniform current, global frame g [m/s]").optional(), &RiserKeys::current_m_s)
        .key("segments", Schema::integer().at_least(2).at_most(2000).default_value(50).doc("finite volumes along the line"),
             &RiserKeys::segments)
        .key("substeps", Schema::integer().at_least(1).at_most(10000).default_value(1)
                             .doc("n = ΔT/Δt: the line's generalized-α steps per large step"),
             &RiserKeys::substeps)
        .key("spectral_radius", Schema::number().at_least(0.0).at_most(1.0).default_value(0.0).doc("generalized-α ρ∞"),
             &RiserKeys::spectral_radius)
        .key("moment_gauges_eta", Schema::sequence(Schema::number().at_least(0.0).at_most(1.0)).max_items(9).optional()
                                      .doc("arclength fractions from the anchor for RsrG<k>Mb (bending moment)"),
             &RiserKeys::moment_gauges_eta);
    return r;
  }();
  return section;
}

// A cubic Hermite through the hang-off point's positions and velocities at the large step's ends,
// at fraction x of a step of length h: the path and its derivative (its velocity).
HangOffMotion hermite(const HangOffMotion& a, const HangOffMotion& b, double x, double h) {
  const double x2 = x * x, x3 = x2 * x;
  HangOffMotion m;
  m.position_m = (2 * x3 - 3 * x2 + 1) * a.position_m + (x3 - 2 * x2 + x) * h * a.velocity_m_s + (-2 * x3 + 3 * x2) * b.position_m +
                 (x3 - x2) * h * b.velocity_m_s;
  m.velocity_m_s = ((6 * x2 - 6 * x) * (a.position_m - b.position_m)) / h + (3 * x2 - 4 * x + 1) * a.velocity_m_s +
                   (3 * x2 - 2 * x) * b.velocity_m_s;
  return m;
}

}  // namespace

Schema riser_schema() { return riser_section().schema(); }

TurbineRiser::TurbineRiser(const io::ValidatedDeck& deck, const multibody::Model& model, const SeaModules& sea) {
  const RiserKeys k = riser_section().read(deck.section("riser"));
  arm_b_m_ = k.hang_off_m;
  substeps_ = k.substeps;
  gauges_eta_ = k.moment_gauges_eta;
  // The straight line from the anchor to the hang-off point of the initial platform pose.
  const multibody::State initial = multibody::Multibody::make_state(model);
  const Vec3 top = initial.position_m + initial.orientation.toRotationMatrix() * arm_b_m_;
  const Vec3 chord = top - k.anchor_m;
  if (chord.norm() <= k.stretch_m)
    throw InputError({"floating", std::nullopt, "riser.stretch_m", "less than the anchor-to-hang-off distance"},
                     where(deck, "riser.stretch_m") + fmt::format(": {:.4g} m; the anchor is {:.4g} m from the hang-off point",
                                                                  k.stretch_m, chord.norm()));
  const Vec3 axis = chord.normalized();
  const Mat3 frame0 = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), axis).toRotationMatrix();
  beam::PipeDefinition def{.line = beam::ReferenceLine::straight(k.anchor_m, frame0, chord.norm() - k.stretch_m,
                                                                 [](double) { return 0.0; })};
  def.outer_diameter_m = k.outer_diameter_m;
  def.inner_diameter_m = k.inner_diameter_m;
  def.youngs_modulus_pa = k.youngs_modulus_Pa;
  def.poisson_ratio = k.poisson_ratio;
  def.pipe_density_kg_m3 = k.density_kg_m3;
  def.fluid_density_kg_m3 = k.fluid_density_kg_m3;
  def.flow_velocity_m_s = k.flow_velocity_m_s;
  def.fluid_viscosity_pa_s = k.fluid_viscosity_Pa_s;
  def.wall_roughness_m = k.wall_roughness_m;
  def.stiffness_damping_s = k.damping_mu_s;
  def.root_end = k.bottom_end == "pinned" ? beam::EndCondition::pinned : beam::EndCondition::clamped;
  def.tip_end = beam::EndCondition::pinned;
  def.boundary_pressure_pa = k.top_pressure_Pa;
  def.pressure_at_tip = true;
  try {  // the pipe's own checks (a bore wider than the tube, a flow without fluid), located at their key
    line_ = beam::discretise_pipe(def, k.segments);
  } catch (const InputError& e) {
    throw InputError(e.context(), where(deck, "riser") + ": " + e.message());
  }
  line_.water = beam::SurroundingWater{.density_kg_m3 = k.water_density_kg_m3,
                                       .outer_diameter_m = k.outer_diameter_m,
                                       .added_mass_coefficient = k.inertia_coefficient - 1.0,
                                       .drag_coefficient = k.drag_coefficient,
                                       .surface_z_m = 0.0,  // the still-water level of g
                                       .current_m_s = k.current_m_s};
  options_.spectral_radius = k.spectral_radius;
  stepper_ = std::make_unique<beam::DynamicStepper>(line_, options_);
  input_.frame.gravity_m_s2 = Vec3(0.0, 0.0, -model.params.gravity_m_s2);  // f = g: no frame motion
  std::vector<Vec3> nodes;
  for (const beam::NodeModel& node : line_.nodes) nodes.push_back(node.position_m);
  waves_ = sea.kinematics_at(nodes);
  if (waves_) {  // sized once: a step fills them in place
    input_.water_velocity_m_s.assign(nodes.size(), Vec3::Zero());
    input_.water_acceleration_m_s2.assign(nodes.size(), Vec3::Zero());
  }
}

void TurbineRiser::set_waves(double t) {
  if (!waves_) return;
  for (std::size_t i = 0; i < waves_->size(); ++i) {
    const waves::WaveKinematics k = waves_->at(i, t);
    input_.water_velocity_m_s[i] = k.velocity_m_s;
    input_.water_acceleration_m_s2[i] = k.acceleration_m_s2;
  }
}

TurbineRiser::~TurbineRiser() = default;

HangOffMotion TurbineRiser::hang_off(const multibody::State& body) const {
  const Mat3 r = body.orientation.toRotationMatrix();
  // ω is in b (multibody/state.hpp): v = ṙ + T_gb (ω × arm).
  return {body.position_m + r * arm_b_m_, body.velocity_m_s + r * body.angular_velocity_rad_s.cross(arm_b_m_)};
}

void TurbineRiser::set_top(const HangOffMotion& top) {
  input_.tip_displacement_m = top.position_m - line_.tip_position_m;
  input_.tip_velocity_m_s = top.velocity_m_s;
}

TurbineRiser::Data TurbineRiser::make_data(const multibody::State& body) {
  Data d{beam::make_state(line_), Vec6::Zero()};
  set_top({hang_off(body).position_m, Vec3::Zero()});
  set_waves(0.0);  // the sea at t = 0 (its kinematics only; the line starts at rest)
  beam::solve_static(line_, input_, d.line);
  d.held = top_load(d.line);
  return d;
}

void TurbineRiser::add_stage_loads(const multibody::State& body, const Data& d, multibody::AppliedLoads& out) const {
  const Vec3 arm = body.orientation.toRotationMatrix() * arm_b_m_;
  const Vec3 force = d.held.head<3>();
  out.platform_force_N += force;
  out.platform_moment_N_m += arm.cross(force) + d.held.tail<3>();
}

void TurbineRiser::advance(double t, double dt_large, const HangOffMotion& begin, const multibody::State& end, Data& d) {
  const HangOffMotion last = hang_off(end);
  const int n = substeps_;
  const double h = dt_large / n;
  const double f = stepper_->input_time_fraction();  // generalized-α balances at t + (1 − αf) Δt
  Vec6 sum = 0.5 * top_load(d.line);
  for (int i = 0; i < n; ++i) {
    set_top(hermite(begin, last, (i + f) / n, dt_large));
    set_waves(t + (i + f) * h);
    stepper_->step(input_, h, d.line);
    sum += (i + 1 < n ? 1.0 : 0.5) * top_load(d.line);
  }
  d.held = sum / n;  // the trapezoidal time average over the large step
}

Vec6 TurbineRiser::top_load(const beam::BeamState& line) const {
  // The top section's load of the outboard side (the pin, i.e. the platform) on the line; the
  // platform takes the opposite (a pin: no moment but rounding).
  return -beam::section_load_at(line_, line, 1.0);
}

Vec6 TurbineRiser::bottom_load(const beam::BeamState& line) const { return beam::beam_outputs(line_, line).root_load; }

double TurbineRiser::bending_moment_N_m(const beam::BeamState& line, double eta) const {
  const Vec3 m = beam::section_load_at(line_, line, eta).tail<3>();
  const Mat3 frame = beam::section_frame_at(line_, line, eta);
  return std::hypot(frame.col(0).dot(m), frame.col(1).dot(m));
}

std::vector<ChannelInfo> TurbineRiser::channels() const {
  std::vector<ChannelInfo> c{
      {"RsrTopTen", "kN", "riser top tension: magnitude of the line's force on the hang-off point (effective tension)", "riser"},
      {"RsrTopAng", "deg", "riser top angle: of the line's pull on the platform from the downward vertical", "riser"},
      {"RsrBotTen", "kN", "riser bottom tension: magnitude of the line's force on the anchor", "riser"}};
  for (const char* axis : {"x", "y", "z"})
    c.push_back({fmt::format("RsrTopF{}i", axis), "kN", fmt::format("riser's force on the platform at the hang-off point, global {}", axis),
                 "riser"});
  for (const char* axis : {"x", "y", "z"})
    c.push_back({fmt::format("RsrTopM{}i", axis), "kN-m",
                 fmt::format("riser's moment on the platform about its reference point, global {}", axis), "riser"});
  for (std::size_t g = 0; g < gauges_eta_.size(); ++g)
    c.push_back({fmt::format("RsrG{}Mb", g + 1), "kN-m",
                 fmt::format("riser bending moment magnitude at arclength fraction {:.3g} from the anchor", gauges_eta_[g]), "riser"});
  return c;
}

void TurbineRiser::channel_values(const multibody::State& body, const Data& d, std::span<double> out) const {
  const Vec6 top = top_load(d.line);
  const Vec3 force = top.head<3>();
  const double tension = force.norm();
  out[0] = 1e-3 * tension;
  out[1] = tension > 0.0 ? std::acos(std::clamp(-force.z() / tension, -1.0, 1.0)) * 180.0 / std::numbers::pi : 0.0;
  out[2] = 1e-3 * bottom_load(d.line).head<3>().norm();
  const Vec3 moment = (body.orientation.toRotationMatrix() * arm_b_m_).cross(force) + top.tail<3>();
  for (int i = 0; i < 3; ++i) {
    out[3 + i] = 1e-3 * force[i];
    out[6 + i] = 1e-3 * moment[i];
  }
  for (std::size_t g = 0; g < gauges_eta_.size(); ++g) out[9 + g] = 1e-3 * bending_moment_N_m(d.line, gauges_eta_[g]);
}

std::string TurbineRiser::description() const {
  return fmt::format("riser of {} volumes at {} small step{} per large step (top load staggered)", line_.node_count(), substeps_,
                     substeps_ == 1 ? "" : "s");
}

}  // namespace fowtsim::driver
