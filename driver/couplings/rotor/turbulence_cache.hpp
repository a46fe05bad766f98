#pragma once
// A folder of generated turbulence fields that runs share (issue 28: a sweep pays once for a field
// that several cases ask for — the same seed, grid, spectrum and held times, e.g. the yaw or fault-time
// variants of one wind realisation). `fowtsim run --turbulence-cache DIR`; the sweep passes it to the
// cases that share a wind seed and removes the folder when they have all ended.
//
// A field's file holds its generation inputs as text (the key: every input of generate_turbulence
// that shapes the field, floating-point values in hexadecimal, and the fowtsim version), then the
// grid as the generator made it, floats bit for bit: a run on a cached field writes the same output as
// one that generated it. A file whose key differs, or that is short or inconsistent, is generated
// anew and replaced. Written under a temporary name and renamed, so two runs that generate the same
// field at once each read a whole file; a failed write (a full disk) only costs the saving.
#include <filesystem>
#include <optional>
#include <string>

#include "fowtsim/wind/full_field.hpp"
#include "fowtsim/wind/turbulence_generator.hpp"

namespace fowtsim::driver {

// The generation inputs of `params` (a turbulent wind) and `held` as text: equal texts, equal fields.
std::string turbulence_key(const wind::WindParams& params, const std::optional<wind::HeldTimes>& held);

// The field of generate_turbulence(params, held): read from `folder` when a file with the same key is
// there, else generated and stored there (the folder is created).
wind::FullField cached_turbulence(const std::filesystem::path& folder, const wind::WindParams& params,
                                  const std::optional<wind::HeldTimes>& held);

// The file of `key` in `folder` (turbulence_<64-bit FNV-1a of the key in hex>.field).
std::filesystem::path turbulence_file(const std::filesystem::path& folder, const std::string& key);

}  // namespace fowtsim::driver
