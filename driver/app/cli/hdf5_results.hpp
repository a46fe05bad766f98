#pragma once
// Writing result tables (not time series) to HDF5 — datasets of numbers, strings and matrices,
// attributes, groups — as `fowtsim post -o OUT.h5` and `fowtsim modes -o OUT.h5` do; h5py reads
// strings as str and matrices rows × columns. Every HDF5 failure throws fowtsim::Error naming what.
#include <hdf5.h>

#include <initializer_list>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "fowtsim/io/hdf5_handle.hpp"

namespace fowtsim::driver::hdf5_results {

// `id` as an owning handle; throws naming `what` when HDF5 failed to create it.
io::hdf5::Handle created(hid_t id, io::hdf5::Handle::Closer close, const std::string& what);
void check(herr_t status, const std::string& what);

void write_doubles(hid_t group, const char* name, const double* data, std::initializer_list<hsize_t> dims);
void write_doubles(hid_t group, const char* name, const std::vector<double>& values);
// A column-major Eigen matrix written row-major (HDF5's order): rows × cols as h5py shows it.
void write_matrix(hid_t group, const char* name, const Eigen::MatrixXd& m);
void write_strings(hid_t group, const char* name, const std::vector<std::string>& values);
void attribute(hid_t object, const char* name, const std::string& value);
void attribute(hid_t object, const char* name, double value);
io::hdf5::Handle group(hid_t parent, const std::string& name);

}  // namespace fowtsim::driver::hdf5_results
