#pragma once
// The error type of fowtsim: every failure carries the module that raised it, the simulation
// time when it happened (if during a run), the quantity concerned and a hint for the user.
// Library code throws; only the driver prints and chooses the exit code.
#include <optional>
#include <stdexcept>
#include <string>

namespace fowtsim {

struct ErrorContext {
  std::string module;               // raising module, e.g. "io.deck", "coupling", "toy.fast"
  std::optional<double> time_s;     // simulation time [s] when raised; empty before the run
  std::string variable;             // quantity concerned, e.g. "q (fast relative position)"
  std::string hint;                 // suggested remedy, e.g. "reduce dt"
};

class Error : public std::runtime_error {
 public:
  Error(ErrorContext context, const std::string& message);

  const ErrorContext& context() const { return context_; }
  const std::string& message() const { return message_; }

 private:
  ErrorContext context_;
  std::string message_;
};

// Thrown when a simulation state becomes non-finite or diverges; the driver catches it, keeps
// the outputs written so far and exits non-zero.
class NumericalError : public Error {
 public:
  using Error::Error;
};

// Thrown for bad input (decks, files, command line) before any time is simulated.
class InputError : public Error {
 public:
  using Error::Error;
};

}  // namespace fowtsim
