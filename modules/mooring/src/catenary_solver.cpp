// Solution of the two catenary span equations for the fairlead tensions (H, V): the H = 0
// branches in closed form, otherwise Newton on the analytic Jacobian with a backtracking line
// search (warm start, then the Peyrot–Goulois guess), and a nested bisection as the last resort.
// Every loop has a fixed iteration cap.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/LU>

#include "fowtsim/mooring/catenary.hpp"

namespace fowtsim::mooring {
namespace {

struct Target {
  double x_m;        // X [m]
  double z_m;        // Z [m]
  double tol_m;      // absolute residual tolerance [m]
};

double residual_max(const CatenarySpans& sp, const Target& t) {
  return std::max(std::abs(sp.x_m - t.x_m), std::abs(sp.z_m - t.z_m));
}

double residual_norm2(const CatenarySpans& sp, const Target& t) {
  return std::hypot(sp.x_m - t.x_m, sp.z_m - t.z_m);
}

// Hanging length l of a vertical line whose lowest point just reaches the seabed:
// Z = l + w l²/(2 EA), solved without cancellation.
double hanging_length(const CatenaryLine& line, double z_m) {
  const double k = line.weight_per_length_N_m / line.ea_N;
  return 2.0 * z_m / (1.0 + std::sqrt(1.0 + 2.0 * k * z_m));
}

// Fills anchor loads, grounded length, regime and the 2-D stiffness for an H > 0 solution whose
// spans `sp` are already evaluated.
CatenarySolution finish(const CatenaryLine& line, double h_N, double v_N, const CatenarySpans& sp, const Target& t) {
  const double l = line.unstretched_length_m, w = line.weight_per_length_N_m;
  CatenarySolution sol;
  sol.fairlead_h_N = h_N;
  sol.fairlead_v_N = v_N;
  sol.span_x_m = t.x_m;
  sol.span_z_m = t.z_m;
  if (line.seabed_contact && v_N < w * l) {
    sol.regime = CatenaryRegime::touchdown;
    sol.grounded_length_m = l - v_N / w;
    const double friction = line.seabed_friction > 0.0 ? line.seabed_friction * w * sol.grounded_length_m : 0.0;
    sol.anchor_h_N = std::max(h_N - friction, 0.0);
    sol.anchor_v_N = 0.0;
  } else {
    sol.regime = CatenaryRegime::suspended;
    sol.anchor_h_N = h_N;
    sol.anchor_v_N = v_N - w * l;
  }
  sol.stiffness = sp.jacobian.inverse();
  sol.residual_m = residual_max(sp, t);
  sol.converged = sol.residual_m <= t.tol_m && sol.stiffness.allFinite();
  return sol;
}

// H = 0 with the line hanging from the fairlead onto a slack heap on the seabed.
CatenarySolution slack_heap(const CatenaryLine& line, double hang_m, const Target& t) {
  const double w = line.weight_per_length_N_m;
  CatenarySolution sol;
  sol.regime = CatenaryRegime::slack_on_seabed;
  sol.fairlead_v_N = w * hang_m;
  sol.grounded_length_m = line.unstretched_length_m - hang_m;
  sol.span_x_m = t.x_m;
  sol.span_z_m = t.z_m;
  sol.stiffness(1, 1) = w / (1.0 + w * hang_m / line.ea_N);  // dV/dZ = w dl/dZ
  sol.converged = true;
  return sol;
}

// H = 0, anchor directly below (or above) the fairlead: Z(V) is piecewise linear in V,
//   Z = (|V| − |V − w L|)/w + (V L − w L²/2)/EA,
// straight-taut for V ≤ 0 or V ≥ w L, a U-shaped hang in between (only without seabed).
CatenarySolution vertical_line(const CatenaryLine& line, const Target& t) {
  const double l = line.unstretched_length_m, w = line.weight_per_length_N_m, ea = line.ea_N;
  const double elastic0 = 0.5 * w * l * l / ea;
  double v = 0.0, dzdv = 0.0;
  if (const double v_up = (t.z_m - l + elastic0) * ea / l; v_up >= w * l) {
    v = v_up;
    dzdv = l / ea;
  } else if (const double v_down = (t.z_m + l + elastic0) * ea / l; v_down <= 0.0) {
    v = v_down;
    dzdv = l / ea;
  } else {
    dzdv = 2.0 / w + l / ea;
    v = (t.z_m + l + elastic0) / dzdv;
  }
  CatenarySolution sol;
  sol.regime = CatenaryRegime::vertical;
  sol.fairlead_v_N = v;
  sol.anchor_v_N = v - w * l;
  sol.span_x_m = t.x_m;
  sol.span_z_m = t.z_m;
  sol.stiffness(1, 1) = 1.0 / dzdv;
  sol.converged = true;
  return sol;
}

// Damped Newton from (h, v). Returns the solution or nothing when the line search stalls or the
// cap is reached; `iterations` accumulates the iterations spent.
std::optional<CatenarySolution> newton(const CatenaryLine& line, const Target& t, double h, double v,
                                       int max_iterations, int& iterations) {
  const double h_floor = 1e-300;
  if (line.seabed_contact) v = std::max(v, 0.0);
  CatenarySpans sp = catenary_spans(line, h, v);
  for (int it = 0; it < max_iterations; ++it) {
    if (!std::isfinite(sp.x_m) || !std::isfinite(sp.z_m)) return std::nullopt;
    if (residual_max(sp, t) <= t.tol_m) return finish(line, h, v, sp, t);
    ++iterations;
    const double det = sp.jacobian.determinant();
    if (!std::isfinite(det) || det == 0.0) return std::nullopt;
    const Eigen::Vector2d step = -sp.jacobian.inverse() * Eigen::Vector2d(sp.x_m - t.x_m, sp.z_m - t.z_m);
    // Keep H positive: at most a 90 % cut per step (H → 0 is a singular limit of the equations).
    double alpha = step[0] < 0.0 ? std::min(1.0, 0.9 * h / -step[0]) : 1.0;
    const double merit = residual_norm2(sp, t);
    bool accepted = false;
    for (int ls = 0; ls < 40 && !accepted; ++ls, alpha *= 0.5) {
      const double h_new = std::max(h + alpha * step[0], h_floor);
      double v_new = v + alpha * step[1];
      if (line.seabed_contact) v_new = std::max(v_new, 0.0);  // V < 0 would bury the line
      const CatenarySpans trial = catenary_spans(line, h_new, v_new);
      if (std::isfinite(trial.x_m) && std::isfinite(trial.z_m) &&
          residual_norm2(trial, t) <= (1.0 - 1e-4 * alpha) * merit) {
        h = h_new;
        v = v_new;
        sp = trial;
        accepted = true;
      }
    }
    if (!accepted) return std::nullopt;
  }
  if (residual_max(sp, t) <= t.tol_m) return finish(line, h, v, sp, t);
  return std::nullopt;
}

// V with Z(H, V) = Z for fixed H: Z grows monotonically with V on both branches.
double vertical_tension_for(const CatenaryLine& line, const Target& t, double h, int max_iterations) {
  const double wl = line.weight_per_length_N_m * line.unstretched_length_m;
  double lo = line.seabed_contact ? 0.0 : -wl, hi = wl;
  for (int k = 0; k < max_iterations && catenary_spans(line, h, hi).z_m < t.z_m; ++k) hi += 2.0 * (hi - lo);
  for (int k = 0; k < max_iterations && !line.seabed_contact && catenary_spans(line, h, lo).z_m > t.z_m; ++k) {
    lo -= 2.0 * (hi - lo);
  }
  for (int k = 0; k < max_iterations; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // interval exhausted at double precision
    (catenary_spans(line, h, mid).z_m < t.z_m ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Nested bisection: X(H, V(H)) grows monotonically with H (positive horizontal line stiffness).
CatenarySolution bisection(const CatenaryLine& line, const Target& t, double h_start, int max_iterations,
                           int& iterations) {
  const auto x_error = [&](double h) {
    ++iterations;
    return catenary_spans(line, h, vertical_tension_for(line, t, h, max_iterations)).x_m - t.x_m;
  };
  double lo = h_start, hi = h_start;
  for (int k = 0; k < max_iterations && x_error(lo) > 0.0; ++k) lo *= 0.01;
  for (int k = 0; k < max_iterations && x_error(hi) < 0.0; ++k) hi *= 100.0;
  for (int k = 0; k < max_iterations; ++k) {
    const double mid = std::sqrt(lo * hi);
    if (mid <= lo || mid >= hi) break;
    (x_error(mid) < 0.0 ? lo : hi) = mid;
  }
  const double h = std::sqrt(lo * hi), v = vertical_tension_for(line, t, h, max_iterations);
  CatenarySolution sol = finish(line, h, v, catenary_spans(line, h, v), t);
  sol.used_fallback = true;
  return sol;
}

}  // namespace

CatenarySolution solve_catenary(const CatenaryLine& line, double span_x_m, double span_z_m,
                                const CatenaryGuess* warm_start, const CatenarySolverOptions& options) {
  const double l = line.unstretched_length_m;
  Target t{span_x_m, span_z_m, options.tolerance * l};
  CatenarySolution failed;
  failed.span_x_m = span_x_m;
  failed.span_z_m = span_z_m;
  failed.residual_m = std::numeric_limits<double>::infinity();
  if (!std::isfinite(span_x_m) || !std::isfinite(span_z_m) || span_x_m < 0.0) return failed;
  if (line.seabed_contact) {
    if (span_z_m < -t.tol_m) return failed;  // fairlead below the seabed: no equilibrium
    t.z_m = std::max(span_z_m, 0.0);
    const double hang = hanging_length(line, t.z_m);
    if (hang < l && span_x_m <= l - hang) return slack_heap(line, hang, t);
  }
  if (span_x_m <= 1e-9 * l) return vertical_line(line, t);

  int iterations = 0;
  std::optional<CatenarySolution> sol;
  if (warm_start != nullptr && warm_start->h_N > 0.0 && std::isfinite(warm_start->h_N) &&
      std::isfinite(warm_start->v_N)) {
    sol = newton(line, t, warm_start->h_N, warm_start->v_N, options.max_newton_iterations, iterations);
  }
  const CatenaryGuess guess = peyrot_goulois_guess(line, t.x_m, t.z_m);
  if (!sol) sol = newton(line, t, guess.h_N, guess.v_N, options.max_newton_iterations, iterations);
  if (!sol) sol = bisection(line, t, guess.h_N, options.max_bisection_iterations, iterations);
  sol->iterations = iterations;
  return *sol;
}

}  // namespace fowtsim::mooring
