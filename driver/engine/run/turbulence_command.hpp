#pragma once
// `fowtsim turbulence DECK [-o BASE]`: generates the deck's turbulent wind field (IEC Kaimal,
// Veers method) and writes BASE.bts (TurbSim format, for OpenFAST or fowtsim) and BASE.h5.
#include <cstdio>
#include <filesystem>
#include <optional>

namespace fowtsim::driver {

// Returns the process exit code; throws InputError for a bad deck.
int run_turbulence_command(const std::filesystem::path& deck, const std::optional<std::filesystem::path>& base, std::FILE* out);

}  // namespace fowtsim::driver
