#include "fowtsim/aero/bem.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "fowtsim/core/brent.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::aero {

// Largest induced velocity of a momentum solution, in units of the section's inflow speed |V|:
// twice what a = 1 gives in axial flow, so every state of the windmill branch (Buhl's a up to ~1.1)
// keeps its root.
constexpr double kMaxInducedToInflow = 2.0;
// Smallest axial induction of a momentum solution: below −1 the disk would more than double the
// flow through it, beyond the propeller branch of momentum theory.
constexpr double kMinAxialInduction = -1.0;
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kBracketOffset = 1e-6;  // ε of Ning's brackets (0+ε, π/2], [−π/4, −ε) [rad]
constexpr int kScanIntervals = 72;       // per half circle when Ning's brackets fail

double sign_of(double x) { return x < 0.0 ? -1.0 : 1.0; }

// R(φ_c) of Ning 2014 in the reflected (first-quadrant) frame, with the induction it implies.
class Residual {
 public:
  Residual(const SectionInflow& in, const Polar& polar, const Params& params)
      : in_(in), polar_(polar), params_(params), sx_(sign_of(in.axial_velocity_m_s)),
        sy_(sign_of(in.tangential_velocity_m_s)),
        velocity_ratio_(std::abs(in.axial_velocity_m_s) / std::abs(in.tangential_velocity_m_s)),
        solidity_(in.number_of_blades * in.chord_m / (2.0 * kPi * in.local_radius_m)) {}

  struct Value {
    double residual = 0.0;
    double a = 0.0;      // axial induction implied by φ_c
    double kappa_t = 0.0;  // κ'
    double loss = 1.0;   // F
  };

  Value operator()(double phi_c) const {
    ++evaluations;
    const double s = std::sin(phi_c), c = std::cos(phi_c);
    const double sin_phi = sx_ * s, cos_phi = sy_ * c;  // physical φ
    // φ = atan2(sin φ, cos φ) in closed form: the reflections of φ_c (the polar wraps α itself).
    const double phi = sy_ > 0.0 ? sx_ * phi_c : sx_ * (kPi - phi_c);
    const AirfoilCoefficients k = polar_.evaluate(phi - in_.theta_rad);
    const double cn = k.cl * cos_phi + (params_.drag_in_axial_induction ? k.cd * sin_phi : 0.0);
    const double ct = k.cl * sin_phi - (params_.drag_in_tangential_induction ? k.cd * cos_phi : 0.0);
    Value v;
    v.loss = prandtl_loss_factor(in_, std::abs(s), params_.tip_loss, params_.hub_loss);
    const double kappa = solidity_ * sx_ * cn / (4.0 * v.loss * s * s);
    // cos φ_c (1 − κ') written without the 1/cos φ_c of κ' so that φ_c = π/2 is regular.
    double tangential = c;
    if (params_.tangential_induction) {
      const double q = solidity_ * sy_ * ct / (4.0 * v.loss * s);
      tangential = c - q;
      v.kappa_t = q / c;
    }
    double axial;
    if (phi_c > 0.0) {
      if (params_.high_induction_correction == HighInductionCorrection::buhl && kappa > 2.0 / 3.0) {
        v.a = buhl_axial_induction(kappa, v.loss);
        axial = s / (1.0 - v.a);
      } else {
        v.a = kappa / (1.0 + kappa);
        axial = s * (1.0 + kappa);
      }
    } else {
      v.a = kappa / (kappa - 1.0);
      axial = s * (1.0 - kappa);
    }
    v.residual = axial - velocity_ratio_ * tangential;
    return v;
  }

  mutable int evaluations = 0;

 private:
  const SectionInflow& in_;
  const Polar& polar_;
  const Params& params_;
  double sx_, sy_, velocity_ratio_, solidity_;
};

constexpr double kTolerance = 1e-12;  // on φ [rad], both ways below
constexpr double kWarmHalfWidth = 0.01;  // [rad]: a few times the change of φ over one small step
constexpr double kSecantHalfWidth = 0.1;  // [rad]: how far Newton–secant may follow the root

// The root of R(φ_c) in a bracket [a, b] with R(a) R(b) <= 0, by Brent's method.
double root_in_bracket(const Residual& f, double a, double b, double fa, double fb) {
  constexpr int kMaxIterations = 200;   // bisection alone halves π in 45 steps
  return fowtsim::brent_root([&f](double phi_c) { return f(phi_c).residual; }, a, b, fa, fb, kTolerance,
                             kMaxIterations);
}

bool opposite(double fa, double fb) { return (fa <= 0.0 && fb >= 0.0) || (fa >= 0.0 && fb <= 0.0); }

// Brent's stopping width at φ_c (brent.hpp): a secant step below it ends the iteration.
double converged_step(double phi_c) { return 2.0 * std::numeric_limits<double>::epsilon() * std::abs(phi_c) + 0.5 * kTolerance; }

// A root with R's value there, when the search already has it (saves the caller one evaluation).
struct Root {
  double phi_c = 0.0;
  bool has_value = false;
  Residual::Value value;
  double slope = std::numeric_limits<double>::quiet_NaN();  // dR/dφ_c near the root (secant) [1/rad]
};

// Newton–secant from the warm start, inside the window ±kSecantHalfWidth around it clipped to its
// half circle clear of the poles: the first step is Newton's with the slope of the previous solve
// (or a secant over a 1e-7 rad probe without one), then secant steps. Stops when the next step
// would be below Brent's tolerance (the iterate is then within it of the root: the secant step
// estimates its error to first order) and returns that iterate with its residual. Any sign change
// seen brackets the root; a step leaving that bracket hands it to Brent. Returns false, for the
// brackets of find_root, when a step leaves the window with no sign change seen, the secant is
// flat, or 12 steps did not converge.
bool secant_from_warm_start(const Residual& f, double warm_start, double warm_slope, Root& root) {
  constexpr int kMaxSteps = 12;
  constexpr double kProbe = 1e-7;  // [rad]
  // The window, clipped to the warm start's half circle clear of its poles.
  const double side_low = warm_start > 0.0 ? kBracketOffset : -(kPi - kBracketOffset);
  const double side_high = warm_start > 0.0 ? kPi - kBracketOffset : -kBracketOffset;
  const double window_low = std::max(warm_start - kSecantHalfWidth, side_low);
  const double window_high = std::min(warm_start + kSecantHalfWidth, side_high);
  double x0 = warm_start;
  Residual::Value v0 = f(x0);
  double x1 = std::isfinite(warm_slope) && warm_slope != 0.0 ? x0 - v0.residual / warm_slope : x0 + kProbe;
  if (std::abs(x1 - x0) <= converged_step(x0)) {  // the inflow has not moved the root (repeated inputs)
    root = {x0, true, v0, warm_slope};
    return true;
  }
  // A sign change seen so far: R(low) <= 0 <= R(high) or the reverse (NaN: none yet).
  double bracket_a = std::numeric_limits<double>::quiet_NaN(), bracket_b = bracket_a, f_a = 0.0, f_b = 0.0;
  for (int step = 0; step < kMaxSteps; ++step) {
    if (v0.residual == 0.0) {
      root = {x0, true, v0, warm_slope};
      return true;
    }
    const bool bracketed = std::isfinite(bracket_a);
    const bool inside = bracketed ? (x1 - bracket_a) * (x1 - bracket_b) < 0.0 : (x1 > window_low && x1 < window_high);
    if (!inside) {
      if (!bracketed) return false;
      root.phi_c = root_in_bracket(f, bracket_a, bracket_b, f_a, f_b);
      return true;
    }
    const Residual::Value v1 = f(x1);
    if (opposite(v0.residual, v1.residual)) {
      bracket_a = x0, bracket_b = x1, f_a = v0.residual, f_b = v1.residual;
    } else if (bracketed && opposite(v1.residual, f_a)) {
      bracket_b = x1, f_b = v1.residual;
    } else if (bracketed) {
      bracket_a = x1, f_a = v1.residual;
    }
    const double slope = (v1.residual - v0.residual) / (x1 - x0);
    if (!(std::abs(slope) > 0.0) || !std::isfinite(slope)) return false;
    const double next = -v1.residual / slope;
    if (std::abs(next) <= converged_step(x1) || v1.residual == 0.0) {
      root = {x1, true, v1, slope};
      return true;
    }
    x0 = x1;
    v0 = v1;
    x1 += next;
  }
  return false;
}

// Finds a root of R(φ_c): from the warm start (Newton–secant, then the bracket of its window),
// then Ning's three brackets in order, then a scan of both half circles (the poles at φ_c = 0, ±π
// are never inside a bracket). Returns false when there is none.
bool find_root(const Residual& f, Root& root, double warm_start, double warm_slope) {
  const double a = warm_start - kWarmHalfWidth, b = warm_start + kWarmHalfWidth;
  // Only inside one half circle, clear of the poles at 0 and ±π that no bracket may contain.
  if (std::isfinite(warm_start) && (a > kBracketOffset || b < -kBracketOffset) && std::abs(a) < kPi - kBracketOffset &&
      std::abs(b) < kPi - kBracketOffset) {
    if (secant_from_warm_start(f, warm_start, warm_slope, root)) return true;
    const double fa = f(a).residual, fb = f(b).residual;
    if (opposite(fa, fb)) {
      root.phi_c = root_in_bracket(f, a, b, fa, fb);
      return true;
    }
  }
  const double pairs[3][2] = {{kBracketOffset, 0.5 * kPi},
                              {-0.25 * kPi, -kBracketOffset},
                              {0.5 * kPi, kPi - kBracketOffset}};
  for (const auto& ab : pairs) {
    const double fa = f(ab[0]).residual, fb = f(ab[1]).residual;
    if (opposite(fa, fb)) {
      root.phi_c = root_in_bracket(f, ab[0], ab[1], fa, fb);
      return true;
    }
  }
  for (const double side : {1.0, -1.0}) {
    const double h = (kPi - 2.0 * kBracketOffset) / kScanIntervals;
    double a = side * kBracketOffset, fa = f(a).residual;
    for (int i = 1; i <= kScanIntervals; ++i) {
      const double b = side * (kBracketOffset + i * h), fb = f(b).residual;
      if (opposite(fa, fb)) {
        root.phi_c = side > 0.0 ? root_in_bracket(f, a, b, fa, fb) : root_in_bracket(f, b, a, fb, fa);
        return true;
      }
      a = b;
      fa = fb;
    }
  }
  return false;
}

[[noreturn]] void non_finite(const SectionInflow& in, const char* what) {
  throw NumericalError({"aero.bem", std::nullopt, what,
                        "check the inflow and blade motion handed to the aero module"},
                       fmt::format("non-finite {} at r = {} m (V_x = {} m/s, V_y = {} m/s)", what,
                                   in.local_radius_m, in.axial_velocity_m_s, in.tangential_velocity_m_s));
}

}  // namespace

double prandtl_loss_factor(const SectionInflow& in, double abs_sin_phi, bool tip_loss, bool hub_loss) {
  double loss = 1.0;
  const double b = in.number_of_blades;
  if (tip_loss) {
    const double gap = in.tip_radius_m - in.local_radius_m;
    if (gap <= 0.0) return 0.0;
    if (abs_sin_phi > 0.0) {
      loss *= 2.0 / kPi * std::acos(std::exp(-0.5 * b * gap / (in.local_radius_m * abs_sin_phi)));
    }
  }
  if (hub_loss) {
    const double gap = in.local_radius_m - in.hub_radius_m;
    if (gap <= 0.0) return 0.0;
    if (abs_sin_phi > 0.0) {
      loss *= 2.0 / kPi * std::acos(std::exp(-0.5 * b * gap / (in.hub_radius_m * abs_sin_phi)));
    }
  }
  return loss;
}

double buhl_axial_induction(double kappa, double loss_factor) {
  const double f = loss_factor;
  const double g1 = 2.0 * f * kappa - (10.0 / 9.0 - f);
  const double g2 = 2.0 * f * kappa - f * (4.0 / 3.0 - f);
  const double g3 = 2.0 * f * kappa - (25.0 / 9.0 - 2.0 * f);
  if (std::abs(g3) < 1e-6) return 1.0 - 1.0 / (2.0 * std::sqrt(g2));
  return (g1 - std::sqrt(g2)) / g3;
}

SectionSolution section_with_induction(const SectionInflow& in, const Polar& polar,
                                       double axial_induction, double tangential_induction,
                                       const SectionSolution& base) {
  SectionSolution s = base;
  s.axial_induction = axial_induction;
  s.tangential_induction = tangential_induction;
  const double u = in.axial_velocity_m_s * (1.0 - axial_induction);
  const double v = in.tangential_velocity_m_s * (1.0 + tangential_induction);
  s.phi_rad = std::atan2(u, v);
  s.alpha_rad = wrap_angle(s.phi_rad - in.theta_rad);
  s.relative_speed_m_s = std::hypot(u, v);
  s.coefficients = polar.evaluate(s.alpha_rad);
  // sin φ, cos φ of the velocity triangle itself (φ = atan2(u, v)); (0, 1) in still air, where
  // atan2 gives φ = 0.
  const double w = s.relative_speed_m_s;
  const double sp = w > 0.0 ? u / w : 0.0, cp = w > 0.0 ? v / w : 1.0;
  s.cn = s.coefficients.cl * cp + s.coefficients.cd * sp;
  s.ct = s.coefficients.cl * sp - s.coefficients.cd * cp;
  if (!std::isfinite(s.phi_rad) || !std::isfinite(s.relative_speed_m_s) || !std::isfinite(s.cn) ||
      !std::isfinite(s.ct) || !std::isfinite(s.coefficients.cm)) {
    non_finite(in, "section state");
  }
  return s;
}

SectionSolution solve_section(const SectionInflow& in, const Polar& polar, const Params& params, double warm_start,
                              double warm_slope) {
  const double vx = in.axial_velocity_m_s, vy = in.tangential_velocity_m_s;
  if (!std::isfinite(vx) || !std::isfinite(vy) || !std::isfinite(in.theta_rad) ||
      !std::isfinite(in.local_radius_m)) {
    non_finite(in, "section inflow");
  }
  SectionSolution base;
  const double speed = std::hypot(vx, vy);
  const bool at_tip = params.tip_loss && in.local_radius_m >= in.tip_radius_m;
  const bool at_hub = params.hub_loss && in.local_radius_m <= in.hub_radius_m;
  if (at_tip || at_hub) {
    base.status = InductionStatus::zero_loss_factor;
    base.loss_factor = 0.0;
    return section_with_induction(in, polar, 1.0, 0.0, base);
  }
  if (speed < 1e-8) {
    base.status = InductionStatus::still_air;
    return section_with_induction(in, polar, 0.0, 0.0, base);
  }
  if (std::abs(vx) <= 1e-9 * speed) {
    base.status = InductionStatus::no_axial_flow;
    return section_with_induction(in, polar, 0.0, 0.0, base);
  }
  if (std::abs(vy) <= 1e-9 * speed) {
    // φ = ±π/2 whatever a is: the axial balance alone fixes a (evaluated at φ_c = π/2 with a
    // unit tangential velocity standing in for V_y, which the residual then ignores).
    SectionInflow axial = in;
    axial.tangential_velocity_m_s = 1.0;
    const Residual f(axial, polar, params);
    const Residual::Value v = f(0.5 * kPi);
    base.status = InductionStatus::no_tangential_flow;
    base.loss_factor = v.loss;
    base.residual_evaluations = f.evaluations;
    return section_with_induction(in, polar, v.a, 0.0, base);
  }
  const Residual f(in, polar, params);
  Root root;
  if (!find_root(f, root, warm_start, warm_slope)) {
    base.status = InductionStatus::no_root;
    base.residual_evaluations = f.evaluations;
    return section_with_induction(in, polar, 0.0, 0.0, base);
  }
  const double phi_c = root.phi_c;
  const Residual::Value v = root.has_value ? root.value : f(phi_c);
  base.root_phi_c_rad = phi_c;
  base.root_slope_per_rad = root.slope;
  base.loss_factor = v.loss;
  base.residual_evaluations = f.evaluations;
  // a and a' consistent with tan φ = V_x(1−a)/(V_y(1+a')) at the root: take the better-conditioned
  // of the two momentum relations and close the triangle with the other.
  const double phi = std::atan2(sign_of(vx) * std::sin(phi_c), sign_of(vy) * std::cos(phi_c));
  const double sp = std::sin(phi), cp = std::cos(phi);
  double a = v.a, ap = 0.0;
  if (std::abs(sp) >= std::abs(cp) || !params.tangential_induction) {
    if (params.tangential_induction) {
      const double w = vx * (1.0 - a) / sp;
      ap = w * cp / vy - 1.0;
    }
  } else {
    ap = v.kappa_t / (1.0 - v.kappa_t);
    const double w = vy * (1.0 + ap) / cp;
    a = 1.0 - w * sp / vx;
  }
  if (!std::isfinite(a) || !std::isfinite(ap)) {
    base.status = InductionStatus::no_root;
    return section_with_induction(in, polar, 0.0, 0.0, base);
  }
  // Momentum theory bounds the induction by the flow through the disk (a ≤ 1, Buhl's branch a
  // little beyond; a propeller state above a = −1). Where φ nears 0 or π with V_x ≪ V_y the relations
  // above turn a root of R into any a at all: measured on a parked rotor yawed 85° in 50 m/s steady
  // wind, a = −204 at V_x = 6 mm/s, then a = 1.6e5 at another node, 12,700 m/s of relative speed and
  // 2.4e10 N·m on the rotor within one step. Such a root is not a momentum solution: the section
  // takes the geometric inflow.
  if (a < kMinAxialInduction || std::abs(a * vx) > kMaxInducedToInflow * speed ||
      std::abs(ap * vy) > kMaxInducedToInflow * speed) {
    base.status = InductionStatus::beyond_momentum;
    return section_with_induction(in, polar, 0.0, 0.0, base);
  }
  return section_with_induction(in, polar, a, ap, base);
}

}  // namespace fowtsim::aero
