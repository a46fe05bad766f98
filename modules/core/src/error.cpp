#include "fowtsim/core/error.hpp"

#include <fmt/format.h>

namespace fowtsim {
namespace {

std::string format_what(const ErrorContext& c, const std::string& message) {
  std::string text = c.module.empty() ? std::string("error") : c.module;
  if (c.time_s) text += fmt::format(" at t = {:.6g} s", *c.time_s);
  text += ": " + message;
  if (!c.variable.empty()) text += fmt::format(" [variable: {}]", c.variable);
  if (!c.hint.empty()) text += fmt::format(" (hint: {})", c.hint);
  return text;
}

}  // namespace

Error::Error(ErrorContext context, const std::string& message)
    : std::runtime_error(format_what(context, message)),
      context_(std::move(context)),
      message_(message) {}

}  // namespace fowtsim
