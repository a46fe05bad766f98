#pragma once
// Static airfoil polar: lift, drag and pitching-moment coefficients against angle of attack over
// the full circle [−180°, 180°], looked up linearly or by a natural cubic spline through the
// table points (AeroDyn's InterpOrd 1 or 3; its default is 3). One table per airfoil, no Reynolds
// dependence (AeroDyn AFTabMod 1).
#include <string>
#include <vector>

namespace fowtsim::aero {

enum class PolarInterpolation {
  linear,        // piecewise linear between table points
  cubic_spline,  // natural cubic spline (zero second derivative at ±180°) through the points
};

struct AirfoilCoefficients {
  double cl = 0.0;  // lift coefficient [-]
  double cd = 0.0;  // drag coefficient [-]
  double cm = 0.0;  // pitching-moment coefficient about the quarter chord, + nose up [-]
};

// What the model reads from a static polar (derive_separation(); every Polar holds its own,
// derived when it is built).
struct SeparationData {
  bool lifting = false;              // false: no zero-lift crossing within ±20° (cylinders): static polar
  double alpha0_rad = 0.0;           // α0: C_l^st(α0) = 0, the rising crossing nearest 0
  double lift_slope_per_rad = 0.0;   // C_l,α: least-squares slope of C_l^st over α0 − 3° … α0 + 5°
  double alpha_low_rad = 0.0;        // first α below α0 where f_st reaches 0 (fully separated)
  double alpha_high_rad = 0.0;       // first α above α0 where f_st reaches 0
  double cd0 = 0.0;                  // C_d^st(α0)
};

// α0, C_l,α and the separation range of a polar, found on a 0.05° grid of the interpolated polar
// (α0 then refined by bisection to 1e-12 rad). Defined in unsteady_airfoil.cpp.
class Polar;
SeparationData derive_separation(const Polar& polar);

class Polar {
 public:
  // Validates and precomputes the spline. alpha_deg strictly increasing, from −180 to 180
  // (within 1e-6°), at least 2 points; cd ≥ 0 everywhere (a negative drag would break the
  // bracketing argument of the induction solver). Throws InputError naming aero.airfoils[name].
  Polar(std::string name, const std::vector<double>& alpha_deg, std::vector<double> cl,
        std::vector<double> cd, std::vector<double> cm, PolarInterpolation interpolation);

  // Coefficients at alpha [rad]; alpha is first wrapped into [−π, π). Allocates nothing.
  AirfoilCoefficients evaluate(double alpha_rad) const;

  const std::string& name() const { return name_; }
  PolarInterpolation interpolation() const { return interpolation_; }
  const std::vector<double>& alpha_rad() const { return alpha_; }  // table abscissae [rad]
  const std::vector<double>& cl() const { return cl_; }
  const std::vector<double>& cd() const { return cd_; }
  const std::vector<double>& cm() const { return cm_; }
  // α0, C_l,α and the separation range for the unsteady airfoil model (unsteady_airfoil.hpp).
  const SeparationData& separation() const { return separation_; }

 private:
  std::string name_;
  PolarInterpolation interpolation_;
  std::vector<double> alpha_, cl_, cd_, cm_;    // table [rad], [-]
  std::vector<double> cl2_, cd2_, cm2_;         // spline second derivatives [1/rad²]; empty if linear
  double cells_per_rad_ = 0.0;                  // uniform lookup cells over [−π, π) [1/rad]
  std::vector<int> interval_of_cell_;           // table interval at the start of the cell before
  SeparationData separation_;

  // The table interval i of a ∈ [−π, π) (alpha_[i] <= a < alpha_[i+1], clamped to the first and
  // last interval), equal to bracket_index(alpha_, a) without its binary search.
  std::size_t interval(double a) const;
};

// Wraps an angle into [−π, π).
double wrap_angle(double angle_rad);

}  // namespace fowtsim::aero
