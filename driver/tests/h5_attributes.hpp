#pragma once
// Root attributes of one of our HDF5 outputs, for the driver tests (the HDF5 C API directly: the
// io readers read channels, not run metadata).
#include <cmath>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>
#include <hdf5.h>

namespace fowtsim::driver {

inline std::string string_attribute(const std::filesystem::path& h5, const char* name) {
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hid_t attr = H5Aopen(file, name, H5P_DEFAULT);
  const hid_t type = H5Aget_type(attr);
  char* value = nullptr;
  H5Aread(attr, type, &value);
  std::string text = value ? value : "";
  H5free_memory(value);
  H5Tclose(type);
  H5Aclose(attr);
  H5Fclose(file);
  return text;
}

inline double double_attribute(const std::filesystem::path& h5, const char* name) {
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hid_t attr = H5Aopen(file, name, H5P_DEFAULT);
  double value = NAN;
  H5Aread(attr, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(attr);
  H5Fclose(file);
  return value;
}

}  // namespace fowtsim::driver
