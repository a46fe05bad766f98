#include "scenes/floating_screening.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "decks/controller_deck.hpp"
#include "fowtsim/multibody/coordinates.hpp"
#include "decks/hydro_deck.hpp"
#include "decks/waves_deck.hpp"
#include "decks/wind_deck.hpp"
#include "fowtsim/control/baseline_law.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/deck.hpp"
#include "scenes/floating_modes.hpp"
#include "scenes/floating_scene.hpp"
#include "scenes/screening_inputs.hpp"
#include "sea/wave_excitation.hpp"

namespace fowtsim::driver {
namespace {

using Clock = std::chrono::steady_clock;
using cd = std::complex<double>;
constexpr double kPi = std::numbers::pi;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The deck of the linearisation: the deck itself in still water (no `waves`), its wind steady with
// the turbulent field's mean profile (power law at the hub speed: no field to generate), writing the
// screened channels.
io::ValidatedDeck linearisation_deck(io::LoadedDeck deck, const std::vector<std::string>& channels) {
  auto& root = deck.root.entries;
  std::erase_if(root, [](const io::DeckEntry& e) { return e.key == "waves"; });
  std::vector<std::string> settings;
  std::string list;
  for (const std::string& c : channels) list += (list.empty() ? "" : ", ") + c;
  settings.push_back("output.channels=[" + list + "]");
  for (io::DeckEntry& e : root)
    if (e.key == "wind") {
      const io::DeckNode* model = e.value.find("model");
      if (model && (model->scalar == "turbulent" || model->scalar == "bts")) {
        std::erase_if(e.value.entries, [](const io::DeckEntry& w) { return w.key == "turbulence" || w.key == "file"; });
        settings.push_back("wind.model=power_law");
      }
    }
  // The linearisation holds the radiation memory (A(∞) only; A(ω) − A(∞) and B(ω) enter per
  // frequency): the shortest kernel window spares the scene its set-up (seconds of a 60-s window).
  if (const io::DeckNode* hydro = deck.root.find("hydro"); hydro && hydro->find("potential_flow")) {
    const io::DeckNode* dt = deck.root.find("simulation") ? deck.root.find("simulation")->find("dt_s") : nullptr;
    const double window = std::max(1.0, 4.0 * (dt ? std::stod(dt->scalar) : 0.0));
    settings.push_back("hydro.potential_flow.radiation=convolution");
    settings.push_back(fmt::format("hydro.potential_flow.radiation_window_s={}", window));
    // Still water: the scene needs no excitation table. The screening reads WAMIT's .3 (2 MB for
    // OC3, most of a WAMIT deck's set-up) once itself (wamit_excitation).
    settings.push_back("hydro.potential_flow.excitation=false");
  }
  io::apply_settings(deck, settings);
  return io::validate(floating_scene_schema(), std::move(deck));
}


// What the static balance solves for besides the coordinates: the rotor speed (region 2, a free
// rotor) or the collective pitch (region 3); nothing for a parked rotor.
enum class RotorUnknown { none, speed, pitch };

struct Controller {
  bool present = false;              // a baseline controller acting on a rotor in wind
  control::BaselineParams params;
  control::TorqueCurve curve;
  control::SimpleVsCurve simple;
  double gearbox_ratio = 1.0;
  // The torque law at generator speed ω (HSS) below rated, with its region (the law's own choice).
  double torque(double w, double pitch) const {
    if (params.generator == control::GeneratorLaw::simple_vs)
      return control::simple_vs_torque(params.simple_vs, simple, control::simple_vs_region(params.simple_vs, simple, w), w);
    return control::scheduled_torque(params, curve, control::torque_region(params, curve, w, pitch), w);
  }
};

// The static balance: every acceleration zero, by block Gauss–Seidel — the rotor's torque balance
// in its one unknown (bracketed, then Brent-like secant/bisection: robust wherever a root exists),
// then the platform and elastic coordinates by Newton's method on a central-difference Jacobian
// (the catenary's and hydrostatics' curvature), repeated until neither moves: the two couple only
// through the rotor's inflow and tilt, so each pass gains about two digits.
class Balance {
 public:
  Balance(FloatingScene& scene, FloatingState& s, const std::vector<int>& dofs) : scene_(scene), s_(s), dofs_(dofs) {
    for (std::size_t i = 0; i < dofs_.size(); ++i) {
      if (dofs_[i] == multibody::kRotor) rotor_ = static_cast<int>(i);
      else coordinates_.push_back(static_cast<int>(i));
      if (dofs_[i] == multibody::kGenerator) generator_ = static_cast<int>(i);
    }
  }

  // Returns the evaluations' Newton iterations; NumericalError when 30 passes do not converge or the
  // rotor's torque has no root in its range.
  int solve(RotorUnknown unknown, const Controller& c, double rotor_speed, double pitch) {
    unknown_ = unknown;
    controller_ = &c;
    rotor_speed_ = rotor_speed;
    pitch_ = pitch;
    apply();
    // A flexible shaft's spring is internal to the drivetrain: the balance of the rotor and the
    // generator together, J_r a_r + J_g a_g = Q_aero − N T_g, is the rotor's equation, with the
    // inertias' ratio J_g/J_r = −(∂a_r/∂θ_g)/(∂a_g/∂θ_g) from the spring's pull on both.
    if (generator_ >= 0 && unknown_ != RotorUnknown::none) {
      const multibody::State base = s_.body;
      multibody::displace_coordinate(s_.body, multibody::kGenerator, 1e-4);
      const Eigen::VectorXd plus = scene_.accelerations(0.0, s_, {});
      s_.body = base;
      multibody::displace_coordinate(s_.body, multibody::kGenerator, -1e-4);
      const Eigen::VectorXd minus = scene_.accelerations(0.0, s_, {});
      s_.body = base;
      generator_weight_ = -(plus[rotor_] - minus[rotor_]) / (plus[generator_] - minus[generator_]);
    }
    int iterations = 0;
    for (int pass = 0; pass < 30; ++pass) {
      // The coordinates first: the rotor's acceleration is relative to the nacelle, whose own
      // acceleration (a flexible tower's vibration) it carries until they are balanced.
      const double platform_step = solve_coordinates(iterations);
      const double before = unknown_value();
      if (unknown_ != RotorUnknown::none) solve_rotor();
      if (platform_step < 1e-8 && std::abs(unknown_value() - before) < 1e-9) return iterations;
    }
    throw NumericalError({"screen", 0.0, "operating point", "check the deck's wind, controller and mooring"},
                         "the static balance (every acceleration zero) did not converge in 30 passes");
  }
  double rotor_speed() const { return rotor_speed_; }
  double pitch() const { return pitch_; }

 private:
  double unknown_value() const { return unknown_ == RotorUnknown::pitch ? pitch_ : rotor_speed_; }
  // The demands and speeds of the present unknowns on the state.
  void apply() {
    s_.body.rotor_speed_rad_s = rotor_speed_;
    s_.body.generator_speed_rad_s = rotor_speed_;
    s_.body.blade_pitch_rad.fill(pitch_);
    s_.held.pitch_rad.fill(pitch_);  // collective
    if (controller_->present)
      s_.held.generator_torque_N_m = controller_->torque(controller_->gearbox_ratio * rotor_speed_, pitch_);
  }
  double rotor_acceleration(double value) {
    (unknown_ == RotorUnknown::pitch ? pitch_ : rotor_speed_) = value;
    apply();
    const Eigen::VectorXd a = scene_.accelerations(0.0, s_, {});
    return a[rotor_] + (generator_ >= 0 ? generator_weight_ * a[generator_] : 0.0);
  }
  // The rotor's acceleration falls with pitch (above rated) and with speed (the torque law rises,
  // the aerodynamic torque falls past the optimum): a bracket by doubling steps, then regula falsi
  // with bisection (Illinois) to 1e-12 rad or rad/s.
  void solve_rotor() {
    const bool pitch = unknown_ == RotorUnknown::pitch;
    const double lo_limit = pitch ? -0.5 : 1e-3, hi_limit = pitch ? 1.5 : 5.0;  // [rad], [rad/s]
    double x0 = unknown_value(), f0 = rotor_acceleration(x0);
    double step = pitch ? 0.02 : 0.05, x1 = x0, f1 = f0;
    while (f0 * f1 > 0.0) {
      x1 = std::clamp(f0 > 0.0 ? x1 + step : x1 - step, lo_limit, hi_limit);
      f1 = rotor_acceleration(x1);
      if ((x1 == lo_limit || x1 == hi_limit) && f0 * f1 > 0.0)
        throw NumericalError({"screen", 0.0, "operating point", "a wind speed the controller can balance"},
                             pitch ? "no blade pitch balances the rated generator torque" : "no rotor speed balances the torque schedule");
      step *= 2.0;
    }
    double a = x0, fa = f0, b = x1, fb = f1;
    int side = 0;
    for (int i = 0; i < 100 && std::abs(b - a) > 1e-12; ++i) {
      const double x = (a * fb - b * fa) / (fb - fa);
      const double fx = rotor_acceleration(x);
      if (fx == 0.0) {
        a = b = x;
        break;
      }
      if (fx * fb < 0.0) {
        a = b;
        fa = fb;
        if (side == -1) fa *= 0.5;
        side = -1;
      } else {
        if (side == 1) fa *= 0.5;
        side = 1;
      }
      b = x;
      fb = fx;
    }
    rotor_acceleration(b);
  }
  // Newton's method on the coordinates (the rotor held); returns the last step's largest entry.
  double solve_coordinates(int& iterations) {
    const auto m = static_cast<Eigen::Index>(coordinates_.size());
    auto residual = [&]() {
      const Eigen::VectorXd a = scene_.accelerations(0.0, s_, {});
      Eigen::VectorXd r(m);
      for (Eigen::Index i = 0; i < m; ++i) r[i] = a[coordinates_[static_cast<std::size_t>(i)]];
      return r;
    };
    constexpr double h = 1e-4;  // [m, rad], as linearised_system
    double largest = 0.0;
    for (int iteration = 0; iteration < 20; ++iteration) {
      ++iterations;
      const multibody::State base = s_.body;
      const Eigen::VectorXd r = residual();
      Eigen::MatrixXd j(m, m);
      for (Eigen::Index k = 0; k < m; ++k) {
        const int dof = dofs_[static_cast<std::size_t>(coordinates_[static_cast<std::size_t>(k)])];
        multibody::displace_coordinate(s_.body, dof, h);
        const Eigen::VectorXd plus = residual();
        s_.body = base;
        multibody::displace_coordinate(s_.body, dof, -h);
        j.col(k) = (plus - residual()) / (2.0 * h);
        s_.body = base;
      }
      Eigen::VectorXd step = j.fullPivLu().solve(-r);
      largest = step.cwiseAbs().maxCoeff();
      if (!std::isfinite(largest)) break;
      if (largest > 5.0) step *= 5.0 / largest;  // at most 5 m (rad) a step, far from the start
      for (Eigen::Index k = 0; k < m; ++k) multibody::displace_coordinate(s_.body, dofs_[static_cast<std::size_t>(coordinates_[static_cast<std::size_t>(k)])], step[k]);
      if (largest < 1e-8) return largest;
      if (largest < 1e-4) return largest;  // the rotor's balance moves next; the next pass polishes
    }
    return largest;
  }

  FloatingScene& scene_;
  FloatingState& s_;
  const std::vector<int>& dofs_;
  int rotor_ = -1, generator_ = -1;
  double generator_weight_ = 0.0;  // J_g/J_r of a flexible shaft
  std::vector<int> coordinates_;  // indices into dofs_ other than the rotor's azimuth
  RotorUnknown unknown_ = RotorUnknown::none;
  const Controller* controller_ = nullptr;
  double rotor_speed_ = 0.0, pitch_ = 0.0;
};

// The trapezoid rule of y over the (non-uniform) grid x.
double integral(const std::vector<double>& x, const Eigen::Ref<const Eigen::VectorXd>& y) {
  double sum = 0.0;
  for (std::size_t i = 1; i < x.size(); ++i)
    sum += 0.5 * (x[i] - x[i - 1]) * (y[static_cast<Eigen::Index>(i)] + y[static_cast<Eigen::Index>(i - 1)]);
  return sum;
}

// [I; [r]×]: a force at r → [F; M] about the reference point.
Eigen::Matrix<double, 6, 3> force_at(const Vec3& r) {
  Eigen::Matrix<double, 6, 3> t;
  t.topRows<3>().setIdentity();
  t.bottomRows<3>() << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return t;
}

}  // namespace

std::vector<std::string> screening_channels(bool with_rotor) {
  std::vector<std::string> c{"PtfmSurge", "PtfmHeave", "PtfmPitch", "TwrBsMyt", "NcIMUTAxs"};
  if (with_rotor) {
    c.push_back("RotSpeed");
    c.push_back("BldPitch1");
  }
  return c;
}

std::vector<std::string> time_domain_settings(const ScreeningOperatingPoint& op, double t_max_s) {
  return {fmt::format("structure.initial_conditions.rotor_speed_rpm={}", op.rotor_speed_rpm),
          fmt::format("structure.initial_conditions.blade_pitch_deg={}", op.pitch_deg),
          fmt::format("structure.initial_conditions.platform_position_m=[{}, 0, {}]", op.platform[0], op.platform[2]),
          fmt::format("structure.initial_conditions.platform_angles_deg=[0, {}, 0]", op.platform[4]),
          fmt::format("simulation.t_max_s={}", t_max_s),
          std::string("output={format: out, decimation: 4, channels: [PtfmHeave, PtfmPitch, TwrBsMyt]}")};
}

ScreeningResult screen_floating(const std::filesystem::path& deck_path, const std::vector<std::string>& settings,
                                const ScreeningOptions& options) {
  ScreeningResult result;
  const Clock::time_point start = Clock::now();
  io::LoadedDeck loaded = io::load_deck(deck_path);
  io::apply_settings(loaded, settings);
  const io::ValidatedDeck source = io::validate(floating_scene_schema(), loaded);
  if (source.has("blades"))
    throw InputError({"screen", std::nullopt, "blades", "rigid blades (a deck without the `blades` section)"},
                     "the flexible MBBT blades' states are not linearised: the screening takes rigid (or Rayleigh-Ritz, parked) blades");
  const bool with_rotor = source.has("aero");
  result.outputs = screening_channels(with_rotor);
  const io::ValidatedDeck deck = linearisation_deck(loaded, result.outputs);

  // The sea and wind screened, from the deck as written.
  const waves::WaveParams sea = source.has("waves") ? wave_params(source.section("waves")) : waves::WaveParams{};
  const WaveSpectrum wave_spectrum(sea);
  result.hs_m = sea.model == waves::WaveModel::still ? 0.0 : sea.hs_m;
  result.tp_s = sea.model == waves::WaveModel::still ? 0.0 : sea.tp_s;
  std::optional<wind::WindParams> wind;
  if (with_rotor) wind = wind_params(source.section("wind"));
  const double tip_radius = source.number("structure.rotor.tip_radius_m");
  const RotorEffectiveWind rotor_wind = wind ? RotorEffectiveWind(*wind, wind->reference_height_m, tip_radius)
                                             : RotorEffectiveWind(wind::WindParams{}, 90.0, tip_radius);
  result.sigma_u_m_s = rotor_wind.sigma_u_m_s();
  // The hydro deck: strips for Morison and drag, WAMIT's tables for radiation and excitation.
  std::optional<HydroDeck> hydro;
  std::optional<RadiationCoefficients> radiation;
  PlatformStrips strips;
  if (deck.has("hydro")) {  // the linearisation's: its radiation kernel is the short one
    hydro = read_hydro_deck(deck.section("hydro"), deck.number("simulation.dt_s"));
    radiation = radiation_coefficients(deck.section("hydro"), hydro->params);
    hydro->excitation = wamit_excitation(source.section("hydro"), hydro->params);
    strips = platform_strips(hydro->params);
  }

  Controller controller;
  if (source.has("controller") && with_rotor) {
    const ControllerParams cp = controller_params(source.section("controller"));
    const auto* b = std::get_if<control::BaselineParams>(&cp);
    if (!b)
      throw InputError({"screen", std::nullopt, "controller.type", "baseline"},
                       "the screening linearises the built-in baseline controller only, not an external DISCON library");
    controller.present = true;
    controller.params = *b;
    controller.curve = control::torque_curve(*b);
    if (b->generator == control::GeneratorLaw::simple_vs) controller.simple = control::simple_vs_curve(b->simple_vs);
    controller.gearbox_ratio = source.number("structure.drivetrain.gearbox_ratio");
  }
  // The scene last: a deck the screening refuses stops above, before its set-up.
  FloatingScene scene(deck);
  for (const ChannelInfo& c : scene.written()) result.units.push_back(c.unit);
  result.seconds_set_up = seconds_since(start);

  // ── The operating point ────────────────────────────────────────────────────────────────────────
  Clock::time_point clock = Clock::now();
  FloatingState s = scene.make_state();
  const std::vector<int> dofs = scene.coordinates();
  const int n = static_cast<int>(dofs.size());
  auto index_of = [&](int k) {
    const auto it = std::find(dofs.begin(), dofs.end(), k);
    return it == dofs.end() ? -1 : static_cast<int>(it - dofs.begin());
  };
  const int rotor = index_of(multibody::kRotor), generator = index_of(multibody::kGenerator);
  const bool rigid_shaft = generator < 0;
  s.body.velocity_m_s.setZero();
  s.body.angular_velocity_rad_s.setZero();
  s.body.generator_speed_rad_s = s.body.rotor_speed_rad_s;
  ScreeningOperatingPoint& op = result.operating_point;
  op.wind_speed_m_s = wind ? wind->speed_m_s : 0.0;
  Balance balance(scene, s, dofs);
  const multibody::State initial = s.body;
  const double initial_pitch = s.held.pitch_rad[0];
  RotorUnknown unknown = RotorUnknown::none;
  if (rotor >= 0 && with_rotor && op.wind_speed_m_s > 0.0) unknown = RotorUnknown::speed;
  const control::BaselineParams& cp = controller.params;
  const double min_pitch = controller.present && cp.pitch != control::PitchLaw::fixed ? cp.min_pitch_rad : initial_pitch;
  if (!controller.present) s.held.generator_torque_N_m = 0.0;
  // Above rated the PI holds the generator at its reference speed and the pitch balances the
  // torque: tried first; it stands when that pitch is above the minimum. Below rated (or where no
  // pitch balances the rated torque) the rotor speed balances the torque schedule at minimum pitch.
  const bool pitch_loop = controller.present && cp.pitch == control::PitchLaw::baseline;
  bool region3 = false;
  if (pitch_loop && unknown == RotorUnknown::speed) {
    try {
      op.newton_iterations = balance.solve(RotorUnknown::pitch, controller, cp.reference_speed_rad_s / controller.gearbox_ratio, 0.1);
      region3 = balance.pitch() > min_pitch;
    } catch (const NumericalError&) {
      region3 = false;
    }
  }
  if (!region3) {
    s.body = initial;
    op.newton_iterations += balance.solve(unknown, controller, initial.rotor_speed_rad_s, min_pitch);
  }
  op.region = region3 ? "region 3" : unknown == RotorUnknown::none ? "parked" : controller.present ? "region 2" : "free rotor";
  op.rotor_speed_rpm = s.body.rotor_speed_rad_s * 30.0 / kPi;
  op.pitch_deg = s.held.pitch_rad[0] * 180.0 / kPi;
  op.generator_torque_N_m = s.held.generator_torque_N_m;
  {
    // Roll, pitch, yaw of R = R_z(ψ) R_y(θ) R_x(φ) (small at an operating point; labels only).
    const Mat3 r = s.body.orientation.toRotationMatrix();
    for (int i = 0; i < 3; ++i) op.platform[i] = s.body.position_m[i];
    op.platform[3] = std::atan2(r(2, 1), r(2, 2)) * 180.0 / kPi;
    op.platform[4] = -std::asin(std::clamp(r(2, 0), -1.0, 1.0)) * 180.0 / kPi;
    op.platform[5] = std::atan2(r(1, 0), r(0, 0)) * 180.0 / kPi;
  }
  result.seconds_operating_point = seconds_since(clock);

  // ── The linear model ẋ = A x + B w, y = C x + D w about it ──────────────────────────────────────
  clock = Clock::now();
  const Eigen::MatrixXd a_open = scene.linearised_system(0.0, s);
  const auto rows_out = static_cast<Eigen::Index>(result.outputs.size());
  std::vector<double> y0(static_cast<std::size_t>(rows_out));
  scene.row(0.0, s, y0, {});
  result.mean = y0;
  // Central differences of the accelerations and the channels in one input.
  auto difference = [&](auto&& change, double h, Eigen::VectorXd& da, Eigen::VectorXd& dy) {
    FloatingState plus = s, minus = s;
    InputOffsets op_plus, op_minus;
    change(plus, op_plus, h);
    change(minus, op_minus, -h);
    std::vector<double> yp(y0.size()), ym(y0.size());
    da = (scene.accelerations(0.0, plus, op_plus) - scene.accelerations(0.0, minus, op_minus)) / (2.0 * h);
    scene.row(0.0, plus, yp, op_plus);
    scene.row(0.0, minus, ym, op_minus);
    dy.resize(rows_out);
    for (Eigen::Index i = 0; i < rows_out; ++i) dy[i] = (yp[static_cast<std::size_t>(i)] - ym[static_cast<std::size_t>(i)]) / (2.0 * h);
  };
  Eigen::VectorXd da, dy;
  // Inputs: the held pitch [rad], the generator torque [N·m, HSS], the rotor-effective wind [m/s],
  // the platform load [N, N·m]. Steps: 1e-4 rad as the linearisation; the torque and the loads
  // enter linearly (any step); 0.01 m/s of wind, 1e-3 of the mean, where BEM's curvature is ~1e-5.
  Eigen::VectorXd b_pitch = Eigen::VectorXd::Zero(n), b_torque = Eigen::VectorXd::Zero(n), b_wind = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd d_pitch = Eigen::VectorXd::Zero(rows_out), d_torque = Eigen::VectorXd::Zero(rows_out), d_wind = Eigen::VectorXd::Zero(rows_out);
  if (with_rotor) {
    difference([](FloatingState& x, InputOffsets&, double h) { for (double& p : x.held.pitch_rad) p += h; x.body.blade_pitch_rad.fill(x.held.pitch_rad[0]); }, 1e-4,
               b_pitch, d_pitch);
    difference([](FloatingState& x, InputOffsets&, double h) { x.held.generator_torque_N_m += h; }, 100.0, b_torque, d_torque);
    if (op.wind_speed_m_s > 0.0)
      difference([](FloatingState&, InputOffsets& o, double h) { o.wind_speed_m_s = h; }, 0.01, b_wind, d_wind);
  }
  Eigen::MatrixXd b_load(n, 6), d_load(rows_out, 6);
  for (int k = 0; k < 6; ++k) {
    difference([k](FloatingState&, InputOffsets& o, double h) { o.platform_load[k] = h; }, k < 3 ? 1e5 : 1e7, da, dy);
    b_load.col(k) = da;
    d_load.col(k) = dy;
  }
  Eigen::MatrixXd c_state(rows_out, 2 * n);
  for (int i = 0; i < n; ++i) {
    const int k = dofs[static_cast<std::size_t>(i)];
    difference([k](FloatingState& x, InputOffsets&, double h) { multibody::displace_coordinate(x.body, k, h); }, 1e-4, da, dy);
    c_state.col(i) = dy;
    difference([k, rigid_shaft](FloatingState& x, InputOffsets&, double h) { multibody::change_coordinate_rate(x.body, k, h, rigid_shaft); }, 1e-4, da, dy);
    c_state.col(n + i) = dy;
  }

  // The controller's linearised dynamics (38060 §7): the filter ω̇_f = ω_c (N Ω_g − ω_f), the
  // integrator İ = ω_f − ω_ref, the pitch δθ = G (K_P δω_f + K_I δI) with the gain schedule's own
  // slope, G = G_K/(1 + G_K θ₀/θ_K) (θ = G_K(θ) (K_P e + K_I I) about e = 0), and the torque law's slope.
  // Only a free rotor closes the loop (a held rotor's speed gives the controller nothing to act on).
  const bool closed_loop = controller.present && unknown != RotorUnknown::none;
  const int nc = closed_loop ? (region3 && pitch_loop ? 2 : 1) : 0;
  const int nx = 2 * n + nc;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(nx, nx);
  a.topLeftCorner(2 * n, 2 * n) = a_open;
  Eigen::RowVectorXd k_pitch = Eigen::RowVectorXd::Zero(nx), k_torque = Eigen::RowVectorXd::Zero(nx);
  if (closed_loop) {
    const int filter = 2 * n, speed = n + (rigid_shaft ? rotor : generator);
    const double ratio = controller.gearbox_ratio, w0 = ratio * s.body.rotor_speed_rad_s, theta0 = s.held.pitch_rad[0];
    a(filter, speed) = cp.filter_corner_rad_s * ratio;
    a(filter, filter) = -cp.filter_corner_rad_s;
    constexpr double dw = 1e-3;  // [rad/s] of generator speed: the torque law is piecewise smooth
    const double slope = (controller.torque(w0 + dw, theta0) - controller.torque(w0 - dw, theta0)) / (2.0 * dw);
    if (region3) {
      // Region 3: the baseline law's T = P/ω_f (constant power) on the filtered speed; its rated
      // torque, or the simple law's VS_RtTq, have no slope.
      const double wf = cp.reference_speed_rad_s;
      if (cp.generator == control::GeneratorLaw::baseline && cp.region3_torque == control::Region3Torque::constant_power)
        k_torque[filter] = -cp.rated_power_W / (wf * wf);
    } else if (cp.generator == control::GeneratorLaw::simple_vs) {
      k_torque[speed] = slope * ratio;  // the simple law acts on the measured speed
    } else {
      k_torque[filter] = slope;
    }
    if (nc == 2) {
      const int integral_state = 2 * n + 1;
      a(integral_state, filter) = 1.0;
      const double gk = control::gain_correction(cp, theta0);
      const double g = gk / (1.0 + gk * theta0 / cp.gain_schedule_pitch_rad);
      k_pitch[filter] = g * cp.proportional_gain_s;
      k_pitch[integral_state] = g * cp.integral_gain;
    }
  }
  a.block(n, 0, n, nx) += b_pitch * k_pitch + b_torque * k_torque;
  const Eigen::MatrixXd c = [&] {
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(rows_out, nx);
    full.leftCols(2 * n) = c_state;
    return Eigen::MatrixXd(full + d_pitch * k_pitch + d_torque * k_torque);
  }();
  // The platform's coordinates among the δq (radiation and drag act on them).
  Eigen::MatrixXd select = Eigen::MatrixXd::Zero(6, nx);
  for (int k = 0; k < 6; ++k)
    if (const int i = index_of(k); i >= 0) select(k, i) = 1.0;
  Eigen::MatrixXd b_load_full = Eigen::MatrixXd::Zero(nx, 6);
  b_load_full.middleRows(n, n) = b_load;
  Eigen::VectorXd b_wind_full = Eigen::VectorXd::Zero(nx);
  b_wind_full.segment(n, n) = b_wind;
  result.seconds_linearisation = seconds_since(clock);

  // ── Frequency domain ───────────────────────────────────────────────────────────────────────────
  clock = Clock::now();
  const int nf = options.frequencies;
  result.frequency_hz.resize(static_cast<std::size_t>(nf));
  for (int i = 0; i < nf; ++i)
    result.frequency_hz[static_cast<std::size_t>(i)] =
        options.min_frequency_hz * std::pow(options.max_frequency_hz / options.min_frequency_hz, static_cast<double>(i) / (nf - 1));
  const std::vector<double>& f = result.frequency_hz;
  result.wave_spectrum.resize(f.size());
  result.wind_spectrum.resize(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) {
    result.wave_spectrum[i] = wave_spectrum.at_hz(f[i]);
    result.wind_spectrum[i] = rotor_wind.spectrum_hz(f[i]);
  }
  const double heading = sea.heading_deg * kPi / 180.0;
  const double depth = sea.depth_m, rho = hydro ? hydro->params.water_density_kg_m3 : 1025.0;
  // Per frequency: the excitation (per unit amplitude), radiation's ΔA and B, the strips' wave velocity.
  std::vector<Vec6c> excitation(f.size(), Vec6c::Zero());
  std::vector<Mat6> added(f.size(), Mat6::Zero()), damping(f.size(), Mat6::Zero());
  std::vector<std::vector<Eigen::Vector3cd>> water(f.size());
  for (std::size_t i = 0; i < f.size() && hydro; ++i) {
    const double w = 2.0 * kPi * f[i];
    if (hydro->params.potential_flow) {
      if (hydro->excitation)
        for (int k = 0; k < 6; ++k) excitation[i][k] = excitation_transfer(*hydro->excitation, k, w, sea.heading_deg);
      if (radiation) radiation->at(w, added[i], damping[i]);
    } else {
      excitation[i] = morison_excitation(strips, hydro->params, w, heading, depth);
    }
    water[i] = strip_wave_velocity(strips, w, heading, depth, hydro->params.gravity_m_s2);
  }
  // Drag linearised on each strip's σ of the normal relative velocity, iterated with the response.
  const std::size_t ns = strips.strips.size();
  std::vector<double> sigma(ns, 0.0), drag(ns, 0.0);
  for (std::size_t j = 0; j < ns; ++j) {  // first guess: the waves' own velocity
    Eigen::VectorXd v2(static_cast<Eigen::Index>(f.size()));
    for (std::size_t i = 0; i < f.size(); ++i) v2[static_cast<Eigen::Index>(i)] = water[i][j].squaredNorm() * result.wave_spectrum[i];
    sigma[j] = std::sqrt(integral(f, v2));
  }
  result.wave_rao.resize(rows_out, nf);
  result.wind_rao.resize(rows_out, nf);
  std::vector<Vec6c> platform_wave(f.size()), platform_wind(f.size());  // platform velocity RAOs
  // Complex copies once: the loop below is the screening's cost (nx ≈ 20 states, ~10³ frequencies).
  const Eigen::MatrixXcd a_c = a.cast<cd>(), c_c = c.cast<cd>(), d_load_c = d_load.cast<cd>();
  const Eigen::MatrixXcd b_load_c = b_load_full.cast<cd>();
  const Eigen::VectorXcd b_wind_c = b_wind_full.cast<cd>(), d_wind_c = d_wind.cast<cd>();
  std::vector<int> platform_index(6);
  for (int k = 0; k < 6; ++k) platform_index[static_cast<std::size_t>(k)] = index_of(k);
  std::vector<Eigen::Matrix<double, 6, 3>> arm(ns);      // [I; [r]×] of each strip
  std::vector<Mat3> normal(ns);                          // I − e eᵀ: the part across the axis
  for (std::size_t j = 0; j < ns; ++j) {
    arm[j] = force_at(strips.strips[j].centre_m);
    normal[j] = Mat3::Identity() - strips.strips[j].axis * strips.strips[j].axis.transpose();
  }
  Mat6 drag_matrix = Mat6::Zero();
  Eigen::MatrixXcd z(nx, nx), rhs(nx, 2), x(nx, 2);
  Eigen::PartialPivLU<Eigen::MatrixXcd> lu(nx);
  // The responses at every stride-th frequency (and the last) with the strips' present σ.
  auto solve = [&](std::size_t stride) {
    drag_matrix.setZero();
    for (std::size_t j = 0; j < ns; ++j) {
      const PlatformStrip& st = strips.strips[j];
      drag[j] = 0.5 * rho * st.cd * st.diameter_m * st.length_m * std::sqrt(8.0 / kPi) * sigma[j];
      drag_matrix += drag[j] * arm[j] * normal[j] * arm[j].transpose();  // v at r = [I, −[r]×] q̇ = armᵀ q̇
    }
    for (std::size_t i = 0; i < f.size(); i += (i + stride < f.size() || i + 1 == f.size()) ? stride : f.size() - 1 - i) {
      const double w = 2.0 * kPi * f[i];
      // Platform load per δq_p: F = (ω² ΔA − iω (B + B_drag)) q_p.
      const Eigen::Matrix<cd, 6, 6> h = (w * w * added[i]).cast<cd>() - cd(0.0, w) * (damping[i] + drag_matrix).cast<cd>();
      Vec6c drag_excitation = Vec6c::Zero();
      for (std::size_t j = 0; j < ns; ++j) drag_excitation += drag[j] * (arm[j].cast<cd>() * water[i][j]);
      const Vec6c wave_load = excitation[i] + drag_excitation;
      const Eigen::MatrixXcd b_h = b_load_c * h;  // nx × 6: the feedback's columns of the platform coordinates
      z = -a_c;
      z.diagonal().array() += cd(0.0, w);
      for (int k = 0; k < 6; ++k)
        if (platform_index[static_cast<std::size_t>(k)] >= 0) z.col(platform_index[static_cast<std::size_t>(k)]) -= b_h.col(k);
      rhs.col(0) = b_load_c * wave_load;
      rhs.col(1) = b_wind_c;
      lu.compute(z);
      x = lu.solve(rhs);
      Vec6c q_wave = Vec6c::Zero(), q_wind = Vec6c::Zero();
      for (int k = 0; k < 6; ++k)
        if (const int p = platform_index[static_cast<std::size_t>(k)]; p >= 0) {
          q_wave[k] = x(p, 0);
          q_wind[k] = x(p, 1);
        }
      const auto col = static_cast<Eigen::Index>(i);
      result.wave_rao.col(col) = c_c * x.col(0) + d_load_c * (wave_load + h * q_wave);
      result.wind_rao.col(col) = c_c * x.col(1) + d_load_c * (h * q_wind) + d_wind_c;
      platform_wave[i] = cd(0.0, w) * q_wave;
      platform_wind[i] = cd(0.0, w) * q_wind;
      if (i + 1 == f.size()) break;
    }
  };
  // σ of each strip's normal relative velocity from the responses on that grid; returns the
  // largest relative change.
  auto update_sigma = [&](std::size_t stride) {
    std::vector<double> grid;
    for (std::size_t i = 0; i < f.size(); i += stride) grid.push_back(f[i]);
    double change = 0.0;
    Eigen::VectorXd v2(static_cast<Eigen::Index>(grid.size()));
    for (std::size_t j = 0; j < ns; ++j) {
      const Eigen::Matrix<cd, 3, 6> velocity = (normal[j] * arm[j].transpose()).cast<cd>();
      for (std::size_t g = 0, i = 0; g < grid.size(); ++g, i += stride) {
        const Eigen::Vector3cd relative_wave = water[i][j] - velocity * platform_wave[i];
        const Eigen::Vector3cd relative_wind = velocity * platform_wind[i];
        v2[static_cast<Eigen::Index>(g)] =
            relative_wave.squaredNorm() * result.wave_spectrum[i] + relative_wind.squaredNorm() * result.wind_spectrum[i];
      }
      const double updated = std::sqrt(integral(grid, v2));
      if (sigma[j] > 0.0) change = std::max(change, std::abs(updated / sigma[j] - 1.0));
      sigma[j] = updated;
    }
    return change;
  };
  // The drag linearisation converges on every 8th frequency (4 % apart: σ is an integral over the
  // broad relative-velocity spectrum), to 1 % of every strip's σ (the linear drag coefficient is
  // proportional to it); then one pass over the whole grid.
  constexpr std::size_t kCoarse = 8;
  for (int iteration = 1; ns > 0 && iteration <= options.max_drag_iterations; ++iteration) {
    result.drag_iterations = iteration;
    solve(kCoarse);
    if (update_sigma(kCoarse) < 1e-2) break;
  }
  solve(1);
  result.psd.resize(rows_out, nf);
  for (Eigen::Index o = 0; o < rows_out; ++o) {
    Eigen::VectorXd wave(nf), wind_part(nf);
    for (int i = 0; i < nf; ++i) {
      wave[i] = std::norm(result.wave_rao(o, i)) * result.wave_spectrum[static_cast<std::size_t>(i)];
      wind_part[i] = std::norm(result.wind_rao(o, i)) * result.wind_spectrum[static_cast<std::size_t>(i)];
    }
    result.psd.row(o) = (wave + wind_part).transpose();
    result.std_waves.push_back(std::sqrt(integral(f, wave)));
    result.std_wind.push_back(std::sqrt(integral(f, wind_part)));
    result.std_total.push_back(std::hypot(result.std_waves.back(), result.std_wind.back()));
  }

  // ── Modes of the closed loop, radiation and drag (the last iteration's) at each mode's own frequency
  auto system_at = [&](double w) {
    Mat6 dadd = Mat6::Zero(), damp = Mat6::Zero();
    if (radiation) radiation->at(std::max(w, 1e-6), dadd, damp);
    // q̈ = a₀(x) − B_p (ΔA q̈_p + (B + B_drag) q̇_p)  ⇒  (I + B_p ΔA S) q̈ = a₀(x) − B_p (B + B_drag) S q̇.
    const Eigen::MatrixXd platform = select.leftCols(n);  // picks q_p from δq, and q̇_p from u alike
    Eigen::MatrixXd m = Eigen::MatrixXd::Identity(n, n) + b_load * dadd * platform;
    Eigen::MatrixXd rows = a.middleRows(n, n);
    rows.middleCols(n, n) -= b_load * (damp + drag_matrix) * platform;
    Eigen::MatrixXd out = a;
    out.middleRows(n, n) = m.partialPivLu().solve(rows);
    return out;
  };
  const std::vector<std::string> names = [&] {
    std::vector<std::string> v = coordinate_names(dofs, scene.tower_fore_aft_modes());
    for (const std::string& x : std::vector<std::string>(v)) v.push_back(x + "Rate");
    if (nc >= 1) v.push_back("FilteredGenSpeed");
    if (nc >= 2) v.push_back("PitchIntegral");
    return v;
  }();
  result.coordinates.assign(names.begin(), names.begin() + n);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(system_at(0.0));
  const Eigen::VectorXcd first = solver.eigenvalues();
  const double resolution = 1e-6 * first.cwiseAbs().maxCoeff();
  for (Eigen::Index e = 0; e < first.size(); ++e) {
    if (first[e].imag() < 0.0 || std::abs(first[e]) < resolution) continue;
    cd lambda = first[e];
    Eigen::VectorXcd vector = solver.eigenvectors().col(e);
    // A few fixed-point passes: the eigenvalue nearest the last at A(|λ|), B(|λ|).
    for (int pass = 0; pass < (radiation ? 4 : 0); ++pass) {
      Eigen::EigenSolver<Eigen::MatrixXd> at(system_at(std::abs(lambda)));
      Eigen::Index nearest = 0;
      (at.eigenvalues().array() - lambda).abs().minCoeff(&nearest);
      lambda = at.eigenvalues()[nearest];
      vector = at.eigenvectors().col(nearest);
    }
    if (lambda.imag() < 0.0) lambda = std::conj(lambda);
    ScreeningMode mode;
    mode.frequency_hz = std::abs(lambda) / (2.0 * kPi);
    mode.damping_ratio = -lambda.real() / std::abs(lambda);
    Eigen::Index largest = 0;
    vector.head(n).cwiseAbs().maxCoeff(&largest);
    mode.dominant = names[static_cast<std::size_t>(largest)];
    mode.shape = (vector.head(n) / vector[largest]).real();
    result.modes.push_back(mode);
  }
  std::sort(result.modes.begin(), result.modes.end(),
            [](const ScreeningMode& x, const ScreeningMode& y) { return x.frequency_hz < y.frequency_hz; });
  result.seconds_solve = seconds_since(clock);
  return result;
}

}  // namespace fowtsim::driver
