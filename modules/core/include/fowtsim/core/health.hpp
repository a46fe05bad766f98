#pragma once
// Numerical health checks run inside a step (DESIGN.md §7): a NaN, an Inf or a value beyond a
// declared divergence bound is reported in the step where it appears, naming module, variable,
// time and a remedy.
#include <string_view>

#include <Eigen/Core>

namespace fowtsim {

// Throws NumericalError if value is NaN or Inf.
void check_finite(std::string_view module, std::string_view variable, double value, double time_s);

// Throws NumericalError if any entry is NaN or Inf (names the first offending index).
void check_finite(std::string_view module, std::string_view variable,
                  const Eigen::Ref<const Eigen::VectorXd>& values, double time_s);

// Throws NumericalError if value is not finite or |value| > limit (divergence).
void check_bounded(std::string_view module, std::string_view variable, double value,
                   double limit, double time_s);

}  // namespace fowtsim
