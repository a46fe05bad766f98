#include "cli/hdf5_results.hpp"

#include "fowtsim/core/error.hpp"

namespace fowtsim::driver::hdf5_results {

using io::hdf5::Handle;

Handle created(hid_t id, Handle::Closer close, const std::string& what) {
  if (id < 0) throw Error({"hdf5 results", std::nullopt, what, ""}, "HDF5 failed to create " + what);
  return Handle(id, close);
}

void check(herr_t status, const std::string& what) {
  if (status < 0) throw Error({"hdf5 results", std::nullopt, what, ""}, "HDF5 failed to write " + what);
}

namespace {

Handle utf8_string_type() {
  Handle type = created(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_size(type.get(), H5T_VARIABLE), "string type");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "string type");
  return type;
}

}  // namespace

void write_doubles(hid_t group, const char* name, const double* data, std::initializer_list<hsize_t> dims) {
  const std::vector<hsize_t> shape(dims);
  Handle space = created(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose, name);
  Handle set = created(H5Dcreate2(group, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose, name);
  check(H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name);
}

void write_doubles(hid_t group, const char* name, const std::vector<double>& values) {
  write_doubles(group, name, values.data(), {values.size()});
}

void write_matrix(hid_t group, const char* name, const Eigen::MatrixXd& m) {
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row_major = m;
  write_doubles(group, name, row_major.data(), {static_cast<hsize_t>(m.rows()), static_cast<hsize_t>(m.cols())});
}

void write_strings(hid_t group, const char* name, const std::vector<std::string>& values) {
  std::vector<const char*> pointers;
  pointers.reserve(values.size());
  for (const std::string& v : values) pointers.push_back(v.c_str());
  const Handle type = utf8_string_type();
  const hsize_t n = values.size();
  Handle space = created(H5Screate_simple(1, &n, nullptr), H5Sclose, name);
  Handle set = created(H5Dcreate2(group, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose, name);
  if (n > 0) check(H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()), name);
}

void attribute(hid_t object, const char* name, const std::string& value) {
  const Handle type = utf8_string_type();
  Handle space = created(H5Screate(H5S_SCALAR), H5Sclose, name);
  Handle attr = created(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, name);
  const char* text = value.c_str();
  check(H5Awrite(attr.get(), type.get(), &text), name);
}

void attribute(hid_t object, const char* name, double value) {
  Handle space = created(H5Screate(H5S_SCALAR), H5Sclose, name);
  Handle attr = created(H5Acreate2(object, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, name);
  check(H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &value), name);
}

Handle group(hid_t parent, const std::string& name) {
  return created(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, name);
}

}  // namespace fowtsim::driver::hdf5_results
