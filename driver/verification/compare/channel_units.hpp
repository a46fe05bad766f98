#pragma once
// Units of two channels that are to be compared (issue 23): the factor that brings the test's
// values into the reference's unit (N → kN, rad → deg, rpm → rad/s …), or why they cannot be
// compared. Never compares kN·m with N·m silently.
#include <string>

namespace fowtsim::driver {

struct UnitMatch {
  double factor = 1.0;  // test value × factor is in the reference's unit
  std::string problem;  // empty when comparable; else why not, for the user
  bool comparable() const { return problem.empty(); }
};

// The unit as written without its brackets or blanks ("(kN-m)" and "[kN·m]" give "kN-m").
std::string normalised_unit(const std::string& unit);

// Same spelling (after normalisation): factor 1, also for units this table does not know ("-",
// "m/s^2"). Different spellings: the factor when both are known units of one quantity (force,
// moment, angle, angular speed or acceleration, length, power), else a problem.
UnitMatch match_units(const std::string& reference_unit, const std::string& test_unit);

}  // namespace fowtsim::driver
