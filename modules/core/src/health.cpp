#include "fowtsim/core/health.hpp"

#include <cmath>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim {
namespace {

constexpr const char* kRemedy =
    "reduce the time step (dt_coupling_s or substeps) or check the inputs of this module";

[[noreturn]] void raise(std::string_view module, std::string variable, double time_s,
                        const std::string& message) {
  throw NumericalError({std::string(module), time_s, std::move(variable), kRemedy}, message);
}

}  // namespace

void check_finite(std::string_view module, std::string_view variable, double value,
                  double time_s) {
  if (!std::isfinite(value)) {
    raise(module, std::string(variable), time_s, fmt::format("non-finite value {}", value));
  }
}

void check_finite(std::string_view module, std::string_view variable,
                  const Eigen::Ref<const Eigen::VectorXd>& values, double time_s) {
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      raise(module, fmt::format("{}[{}]", variable, i), time_s,
            fmt::format("non-finite value {}", values[i]));
    }
  }
}

void check_bounded(std::string_view module, std::string_view variable, double value,
                   double limit, double time_s) {
  check_finite(module, variable, value, time_s);
  if (std::abs(value) > limit) {
    raise(module, std::string(variable), time_s,
          fmt::format("divergence: |{}| = {:.6g} exceeds the bound {:.6g}", variable,
                      std::abs(value), limit));
  }
}

}  // namespace fowtsim
