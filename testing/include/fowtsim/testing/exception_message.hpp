#pragma once
// The message a call throws: for tests that check what an error says (file:line, key, hint).
#include <exception>
#include <functional>
#include <string>

#include <catch2/catch.hpp>

namespace fowtsim::testing {

// The what() of the exception `f` throws; a test failure if it throws none.
inline std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  FAIL("expected an exception");
  return "";
}

}  // namespace fowtsim::testing
