#pragma once
// Root attributes of one of our HDF5 outputs, for the driver tests (the HDF5 C API directly: the
// io readers read channels, not run metadata).
#include <cmath>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>
#include <hdf5.h>

#include "fowtsim/io/hdf5_handle.hpp"

namespace fowtsim::driver {

inline std::string string_attribute(const std::filesystem::path& h5, const char* name) {
  const io::hdf5::Handle file(H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  REQUIRE(file.valid());
  const io::hdf5::Handle attr(H5Aopen(file.get(), name, H5P_DEFAULT), H5Aclose);
  const io::hdf5::Handle type(H5Aget_type(attr.get()), H5Tclose);
  char* value = nullptr;
  H5Aread(attr.get(), type.get(), &value);
  std::string text = value ? value : "";
  H5free_memory(value);
  return text;
}

inline double double_attribute(const std::filesystem::path& h5, const char* name) {
  const io::hdf5::Handle file(H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  REQUIRE(file.valid());
  const io::hdf5::Handle attr(H5Aopen(file.get(), name, H5P_DEFAULT), H5Aclose);
  double value = NAN;
  H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value);
  return value;
}

}  // namespace fowtsim::driver
