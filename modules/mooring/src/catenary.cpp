// The closed-form span equations of the elastic catenary, their Jacobian and the line profile
// (Jonkman 2007, NREL/TP-500-41958, §4.2). Differences of square roots and inverse hyperbolic
// sines are rearranged into cancellation-free forms where the taut and the slack limits need it.
#include <algorithm>
#include <cmath>

#include "fowtsim/mooring/catenary.hpp"

namespace fowtsim::mooring {
namespace {

// s₀ = L_B − H/(C_B w): below it the grounded line carries no tension (friction-limited).
double slack_end(const CatenaryLine& line, double grounded_m, double h_N) {
  return grounded_m - h_N / (line.seabed_friction * line.weight_per_length_N_m);
}

bool on_seabed_branch(const CatenaryLine& line, double v_N) {
  return line.seabed_contact && v_N < line.weight_per_length_N_m * line.unstretched_length_m;
}

// Horizontal position of the grounded point at s ∈ [0, L_B]: the unstretched length plus the
// stretch under T(s) = max(H − C_B w (L_B − s), 0), integrated in closed form.
double grounded_x(const CatenaryLine& line, double grounded_m, double h_N, double s_m) {
  const double ea = line.ea_N;
  if (line.seabed_friction <= 0.0) return s_m * (1.0 + h_N / ea);
  const double cbw = line.seabed_friction * line.weight_per_length_N_m;
  const double s0 = slack_end(line, grounded_m, h_N);
  if (s0 > 0.0) {
    if (s_m <= s0) return s_m;
    return s_m + 0.5 * cbw / ea * (s_m - s0) * (s_m - s0);
  }
  return s_m + ((h_N - cbw * grounded_m) * s_m + 0.5 * cbw * s_m * s_m) / ea;
}

}  // namespace

const char* regime_name(CatenaryRegime regime) {
  switch (regime) {
    case CatenaryRegime::suspended: return "suspended";
    case CatenaryRegime::touchdown: return "touchdown";
    case CatenaryRegime::slack_on_seabed: return "slack_on_seabed";
    case CatenaryRegime::vertical: return "vertical";
  }
  return "unknown";
}

CatenarySpans catenary_spans(const CatenaryLine& line, double h_N, double v_N) {
  const double l = line.unstretched_length_m, w = line.weight_per_length_N_m, ea = line.ea_N;
  CatenarySpans out;
  if (on_seabed_branch(line, v_N)) {
    const double grounded = l - v_N / w;
    const double a = v_N / h_N, sa = std::hypot(1.0, a);
    double friction_x = 0.0, friction_dxdh = 0.0, friction_dxdv = 0.0;
    if (line.seabed_friction > 0.0) {
      const double cb = line.seabed_friction;
      const double s0 = slack_end(line, grounded, h_N), s0p = std::max(s0, 0.0);
      friction_x = 0.5 * cb * w / ea * (-grounded * grounded + s0 * s0p);
      friction_dxdh = -s0p / ea;
      friction_dxdv = cb / ea * (grounded - s0p);
    }
    out.x_m = grounded + h_N / w * std::asinh(a) + h_N * l / ea + friction_x;
    out.z_m = h_N / w * a * a / (sa + 1.0) + v_N * v_N / (2.0 * ea * w);  // (H/w)(√(1+a²) − 1)
    const double inv_sa_minus_1 = -a * a / (sa * (1.0 + sa));          // 1/√(1+a²) − 1
    out.jacobian << (std::asinh(a) - a / sa) / w + l / ea + friction_dxdh,
        inv_sa_minus_1 / w + friction_dxdv,
        inv_sa_minus_1 / w, a / sa / w + v_N / (ea * w);
    return out;
  }
  const double a = v_N / h_N, b = (v_N - w * l) / h_N;  // a − b = w L / H
  const double sa = std::hypot(1.0, a), sb = std::hypot(1.0, b);
  const double asinh_diff = std::asinh(a) - std::asinh(b);
  out.x_m = h_N / w * asinh_diff + h_N * l / ea;
  out.z_m = l * (a + b) / (sa + sb) + (v_N * l - 0.5 * w * l * l) / ea;  // (H/w)(sa − sb) rewritten
  const double inv_diff = -(w * l / h_N) * (a + b) / ((sa + sb) * sa * sb);  // 1/sa − 1/sb
  out.jacobian << (asinh_diff - a / sa + b / sb) / w + l / ea, inv_diff / w,
      inv_diff / w, (a / sa - b / sb) / w + l / ea;
  return out;
}

CatenaryGuess peyrot_goulois_guess(const CatenaryLine& line, double span_x_m, double span_z_m) {
  const double l = line.unstretched_length_m, w = line.weight_per_length_N_m;
  double lambda = 0.2;  // taut: the chord is at least the unstretched length
  if (span_x_m <= 1e-9 * l) {
    lambda = 1e6;
  } else if (std::hypot(span_x_m, span_z_m) < l) {
    lambda = std::sqrt(3.0 * ((l * l - span_z_m * span_z_m) / (span_x_m * span_x_m) - 1.0));
  }
  CatenaryGuess g;
  g.h_N = std::max(std::abs(w * span_x_m / (2.0 * lambda)), 1e-6 * w * l);
  g.v_N = 0.5 * w * (span_z_m / std::tanh(lambda) + l);
  return g;
}

Eigen::Vector2d catenary_point(const CatenaryLine& line, const CatenarySolution& sol, double s_m) {
  const double l = line.unstretched_length_m, w = line.weight_per_length_N_m, ea = line.ea_N;
  const double s = std::clamp(s_m, 0.0, l), h = sol.fairlead_h_N;
  const double grounded = sol.grounded_length_m;
  switch (sol.regime) {
    case CatenaryRegime::suspended: {
      const double va = sol.fairlead_v_N - w * l, vs = va + w * s;
      const double c0 = va / h, c1 = vs / h, s0 = std::hypot(1.0, c0), s1 = std::hypot(1.0, c1);
      return {h / w * (std::asinh(c1) - std::asinh(c0)) + h * s / ea,
              s * (c1 + c0) / (s1 + s0) + (va * s + 0.5 * w * s * s) / ea};
    }
    case CatenaryRegime::touchdown: {
      if (s <= grounded) return {grounded_x(line, grounded, h, s), 0.0};
      const double sigma = s - grounded, c = w * sigma / h, sc = std::hypot(1.0, c);
      return {grounded_x(line, grounded, h, grounded) + h / w * std::asinh(c) + h * sigma / ea,
              sigma * c / (sc + 1.0) + 0.5 * w * sigma * sigma / ea};
    }
    case CatenaryRegime::slack_on_seabed: {
      // The heap has no unique shape; nodes are spread evenly over the grounded span (at most
      // as long as the grounded line) so a plot or a lumped-mass start is sensible.
      if (s <= grounded) return {grounded > 0.0 ? s / grounded * sol.span_x_m : 0.0, 0.0};
      const double sigma = s - grounded;
      return {sol.span_x_m, sigma + 0.5 * w * sigma * sigma / ea};
    }
    case CatenaryRegime::vertical: {
      const double va = sol.fairlead_v_N - w * l, vs = va + w * s;
      return {sol.span_x_m * s / l, (std::abs(vs) - std::abs(va)) / w + (va * s + 0.5 * w * s * s) / ea};
    }
  }
  return {0.0, 0.0};
}

double catenary_tension(const CatenaryLine& line, const CatenarySolution& sol, double s_m) {
  const double l = line.unstretched_length_m, w = line.weight_per_length_N_m;
  const double s = std::clamp(s_m, 0.0, l), h = sol.fairlead_h_N;
  const double grounded = sol.grounded_length_m;
  switch (sol.regime) {
    case CatenaryRegime::suspended:
      return std::hypot(h, sol.fairlead_v_N - w * (l - s));
    case CatenaryRegime::touchdown:
      if (s > grounded) return std::hypot(h, w * (s - grounded));
      if (line.seabed_friction <= 0.0) return h;
      return std::max(h - line.seabed_friction * w * (grounded - s), 0.0);
    case CatenaryRegime::slack_on_seabed:
      return s > grounded ? w * (s - grounded) : 0.0;
    case CatenaryRegime::vertical:
      return std::abs(sol.fairlead_v_N - w * (l - s));
  }
  return 0.0;
}

}  // namespace fowtsim::mooring
