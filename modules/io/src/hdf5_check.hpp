#pragma once
// Private error conversion of the HDF5 writer and reader: HDF5 failures become fowtsim::Error
// with module "io.hdf5" and the path.
#include <hdf5.h>

#include <string>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/hdf5_handle.hpp"

namespace fowtsim::io::hdf5 {

[[noreturn]] inline void fail(const std::string& path, const std::string& what,
                              const std::string& variable = "") {
  throw Error(ErrorContext{"io.hdf5", std::nullopt, variable, ""},
              "HDF5 failure on '" + path + "': " + what);
}

// Returns `id` as an owning handle, or throws if HDF5 returned an invalid identifier.
inline Handle checked(hid_t id, Handle::Closer closer, const std::string& path,
                      const std::string& what, const std::string& variable = "") {
  if (id < 0) fail(path, what, variable);
  return Handle(id, closer);
}

inline void check(herr_t status, const std::string& path, const std::string& what,
                  const std::string& variable = "") {
  if (status < 0) fail(path, what, variable);
}

}  // namespace fowtsim::io::hdf5
