#pragma once
// `fowtsim run bd_driver.inp`: run a BeamDyn stand-alone driver case with the MBBT beam and write
// BeamDyn's channels (rows at the same times BeamDyn writes them, so `fowtsim compare` lines up).
#include "run/run_types.hpp"

namespace fowtsim::driver {

// True if the file is a BeamDyn driver input (its first line names the BeamDyn driver).
bool is_beamdyn_driver_file(const std::filesystem::path& path);

RunReport run_beamdyn_case(const RunRequest& request, const ProgressCallback& progress);

}  // namespace fowtsim::driver
