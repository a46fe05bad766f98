#pragma once
// Reads an ElastoDyn blade deck (the `elastodyn_blade:` section of a YAML file, keys and units as
// in inputs/nrel5mw/blade_elastodyn.yaml). In the fowtsim_flexbody_deck library, so that the
// flexbody library itself needs no YAML parser.
#include "fowtsim/flexbody/elastodyn_blade.hpp"

#include <filesystem>

namespace fowtsim::flexbody {

// Throws InputError naming the file and key for a missing or malformed entry, and whatever
// validate() refuses.
ElastoDynBlade read_elastodyn_blade(const std::filesystem::path& file);

}  // namespace fowtsim::flexbody
