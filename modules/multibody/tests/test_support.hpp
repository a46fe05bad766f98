#pragma once
// Helpers shared by the multibody tests.
#include <functional>

#include "fowtsim/multibody/multibody.hpp"

namespace fowtsim::multibody::testing {

// A LoadProvider from a lambda (tests only; std::function may allocate on construction, never per call).
class LambdaProvider : public LoadProvider {
 public:
  using Fn = std::function<void(double, const State&, AppliedLoads&)>;
  explicit LambdaProvider(Fn fn) : fn_(std::move(fn)) {}
  void loads(double t, const State& s, AppliedLoads& out) override { fn_(t, s, out); }

 private:
  Fn fn_;
};

// No external load, gravity off.
class FreeProvider : public LoadProvider {
 public:
  void loads(double, const State&, AppliedLoads& out) override { out.gravity = false; }
};

}  // namespace fowtsim::multibody::testing
