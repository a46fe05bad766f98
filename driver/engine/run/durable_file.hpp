#pragma once
// Files that survive a kill or a full disk: written whole or not at all, and pushed to the disk
// (fsync) before the run relies on them.
#include <filesystem>
#include <string_view>

namespace fowtsim::driver {

// Writes `bytes` to `file` through `file`.tmp: every write checked, fsync, then rename over `file`
// and fsync of the folder, so `file` is either its previous content or all of `bytes`. On failure
// the temporary is removed, `file` is untouched and fowtsim::Error says why (e.g. the disk is full).
void write_file_atomically(const std::filesystem::path& file, std::string_view bytes);

// fsync of an existing file by name (its data written by another handle, e.g. the HDF5 library):
// what was written before the call is on the disk when it returns. Throws fowtsim::Error.
void sync_file(const std::filesystem::path& file);

}  // namespace fowtsim::driver
