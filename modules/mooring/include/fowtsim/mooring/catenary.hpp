#pragma once
// Quasi-static elastic catenary of one mooring line in its own vertical plane, with optional
// seabed contact and Coulomb-like seabed friction — the analytic solution used by FAST's
// quasi-static mooring and MAP (Jonkman 2007, NREL/TP-500-41958, §4.2, "Quasi-static mooring
// line"), implemented here from the theory.
//
// Plane of the line: x horizontal from anchor towards fairlead, z up, origin at the anchor.
// Unknowns: the horizontal and vertical tension H, V that the line carries at the fairlead
// (H ≥ 0; V > 0 means the line pulls the fairlead down). Arc length s is unstretched, from the
// anchor (s = 0) to the fairlead (s = L). w is the apparent (submerged) weight per unit
// unstretched length, EA the axial stiffness, C_B the seabed friction coefficient.
//
// Fully suspended (no seabed contact, or V ≥ w L):
//   X = (H/w) [asinh(V/H) − asinh(V_A/H)] + H L/EA,                 V_A = V − w L
//   Z = (H/w) [√(1+(V/H)²) − √(1+(V_A/H)²)] + (V L − w L²/2)/EA
// Resting on the seabed over L_B = L − V/w (anchor on the seabed, 0 ≤ V < w L):
//   X = L_B + (H/w) asinh(V/H) + H L/EA + (C_B w/2EA) [−L_B² + s₀ max(s₀, 0)],  s₀ = L_B − H/(C_B w)
//   Z = (H/w) [√(1+(V/H)²) − 1] + V²/(2 EA w)
// The friction term follows from the tension on the seabed, T(s) = max(H − C_B w (L_B − s), 0):
// friction builds the tension up from the anchor towards the touchdown point; where s < s₀ the
// line lies slack (the friction-limited case, zero anchor tension).
#include <Eigen/Core>

namespace fowtsim::mooring {

// One line as the catenary sees it (2-D, independent of where the line sits in 3-D).
struct CatenaryLine {
  double unstretched_length_m = 0.0;   // L [m], > 0
  double weight_per_length_N_m = 0.0;  // w [N/m], apparent weight in water per unstretched length, > 0
  double ea_N = 0.0;                   // EA [N], axial stiffness (tension per unit strain), > 0
  double seabed_friction = 0.0;        // C_B [-], ≥ 0; used only with seabed_contact
  bool seabed_contact = false;         // the anchor lies on a flat seabed the line can rest on
};

// Which analytic branch the solution lies on.
enum class CatenaryRegime {
  suspended,        // no point of the line touches the seabed (includes taut, stretched lines)
  touchdown,        // part of the line rests on the seabed, H > 0
  slack_on_seabed,  // H = 0: a vertical hanging part above a slack heap on the seabed
  vertical,         // H = 0: anchor directly below the fairlead, line hanging vertically
};

const char* regime_name(CatenaryRegime regime);

// Spans X, Z of a line carrying fairlead tensions (H, V) and their Jacobian ∂(X, Z)/∂(H, V)
// (the line's flexibility). Requires H > 0; V ≥ 0 when the line can touch the seabed.
struct CatenarySpans {
  double x_m = 0.0;                               // X [m], horizontal span anchor → fairlead
  double z_m = 0.0;                               // Z [m], vertical span anchor → fairlead
  Eigen::Matrix2d jacobian = Eigen::Matrix2d::Zero();  // [∂X/∂H ∂X/∂V; ∂Z/∂H ∂Z/∂V] [m/N]
};
CatenarySpans catenary_spans(const CatenaryLine& line, double h_N, double v_N);

// A starting point for the iteration: the previous solution (warm start) or the guess below.
struct CatenaryGuess {
  double h_N = 0.0;  // H [N]
  double v_N = 0.0;  // V [N]
};

// Peyrot & Goulois (1979) starting values, as used by FAST/MAP: λ from the span ratio,
// H₀ = |w X / (2λ)|, V₀ = (w/2) (Z / tanh λ + L).
CatenaryGuess peyrot_goulois_guess(const CatenaryLine& line, double span_x_m, double span_z_m);

struct CatenarySolverOptions {
  double tolerance = 1e-10;     // converged when |X(H,V) − X| and |Z(H,V) − Z| ≤ tolerance · L [-]
  int max_newton_iterations = 50;   // Newton iterations per attempt (warm, then cold start)
  int max_bisection_iterations = 200;  // per level of the nested-bisection fallback
};

struct CatenarySolution {
  double fairlead_h_N = 0.0;       // H [N], horizontal tension at the fairlead, ≥ 0
  double fairlead_v_N = 0.0;       // V [N], vertical tension at the fairlead (line pulls it down when > 0)
  double anchor_h_N = 0.0;         // H_A [N], horizontal tension at the anchor, ≥ 0
  double anchor_v_N = 0.0;         // V_A [N], vertical tension at the anchor (line pulls it up when > 0)
  double grounded_length_m = 0.0;  // L_B [m], unstretched length resting on the seabed
  double span_x_m = 0.0;           // X [m] the solution was computed for (anchor → fairlead)
  double span_z_m = 0.0;           // Z [m] the solution was computed for
  CatenaryRegime regime = CatenaryRegime::suspended;
  // ∂(H, V)/∂(X, Z) at the solution [N/m]: the line's 2-D stiffness (inverse of the span
  // Jacobian; on the H = 0 branches only the vertical entry is non-zero).
  Eigen::Matrix2d stiffness = Eigen::Matrix2d::Zero();
  double residual_m = 0.0;  // max(|X(H,V) − X|, |Z(H,V) − Z|) [m] at the returned solution
  int iterations = 0;       // Newton (+ bisection) iterations spent
  bool used_fallback = false;  // Newton failed and the nested bisection found the solution
  bool converged = false;   // residual_m ≤ tolerance · L; when false the caller must not use it
};

// Solves the two span equations for (H, V) given the spans X ≥ 0 and Z (fairlead relative to the
// anchor). Newton on the analytic Jacobian with a backtracking line search, from `warm_start`
// when given (and H > 0) else from the Peyrot–Goulois guess; then from the guess; finally a
// nested bisection (V from Z for fixed H, then H from X in log scale), which always brackets
// since Z grows with V and X grows with H. The H = 0 branches (slack heap, vertical line) are
// recognised before iterating. Never loops unbounded; returns converged = false on failure
// (e.g. Z < 0 with seabed contact: the fairlead below the seabed) — the caller reports it.
CatenarySolution solve_catenary(const CatenaryLine& line, double span_x_m, double span_z_m,
                                const CatenaryGuess* warm_start = nullptr,
                                const CatenarySolverOptions& options = {});

// Position (x, z) [m] of the point at unstretched arc length s ∈ [0, L] from the anchor, in the
// line's plane, for a solution of solve_catenary. For plots and for initialising a lumped-mass
// line model.
Eigen::Vector2d catenary_point(const CatenaryLine& line, const CatenarySolution& solution, double s_m);

// Tension magnitude [N] at unstretched arc length s ∈ [0, L] from the anchor.
double catenary_tension(const CatenaryLine& line, const CatenarySolution& solution, double s_m);

}  // namespace fowtsim::mooring
