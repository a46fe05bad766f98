#pragma once
// The request the driver tests start from: run `deck`, writing `base`.<format> (default the
// OpenFAST-style text .out the tests read back; std::nullopt leaves the deck's own choice).
#include <filesystem>
#include <optional>
#include <string>

#include "run/run_types.hpp"

namespace fowtsim::driver {

inline RunRequest run_request(const std::filesystem::path& deck, const std::filesystem::path& base,
                              std::optional<std::string> format = std::string("out")) {
  RunRequest r;
  r.deck_path = deck;
  r.output_base = base;
  r.output_format = std::move(format);
  return r;
}

}  // namespace fowtsim::driver
