// Reader of our own HDF5 output (layout in hdf5_writer.hpp).
#include <hdf5.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "file_bytes.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "hdf5_check.hpp"

namespace fowtsim::io {
namespace {

using hdf5::check;
using hdf5::checked;
using hdf5::Handle;

herr_t collect_name(hid_t /*group*/, const char* name, const H5L_info_t* /*info*/, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}

// Root link names in creation order (the writer tracks it); by name for files that do not.
std::vector<std::string> root_names(hid_t file, const std::string& path) {
  std::vector<std::string> names;
  if (H5Literate(file, H5_INDEX_CRT_ORDER, H5_ITER_INC, nullptr, collect_name, &names) >= 0) {
    return names;
  }
  names.clear();
  check(H5Literate(file, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_name, &names), path,
        "cannot list the root group");
  return names;
}

// A string attribute, variable- or fixed-length; empty if absent or not a string.
std::optional<std::string> read_string_attribute(hid_t object, const char* name,
                                                 const std::string& path) {
  const htri_t exists = H5Aexists(object, name);
  check(exists, path, "cannot query attribute", name);
  if (exists == 0) return std::nullopt;
  const Handle attribute = checked(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, path,
                                   "cannot open attribute", name);
  const Handle file_type = checked(H5Aget_type(attribute.get()), H5Tclose, path,
                                   "cannot get attribute type", name);
  if (H5Tget_class(file_type.get()) != H5T_STRING) return std::nullopt;
  const Handle memory_type = checked(H5Tcopy(H5T_C_S1), H5Tclose, path, "cannot copy string type", name);
  check(H5Tset_cset(memory_type.get(), H5Tget_cset(file_type.get())), path, "cannot set charset", name);
  const htri_t variable = H5Tis_variable_str(file_type.get());
  check(variable, path, "cannot inspect attribute type", name);
  if (variable > 0) {
    check(H5Tset_size(memory_type.get(), H5T_VARIABLE), path, "cannot size string type", name);
    char* text = nullptr;
    check(H5Aread(attribute.get(), memory_type.get(), &text), path, "cannot read attribute", name);
    std::string value = text != nullptr ? text : "";
    H5free_memory(text);
    return value;
  }
  const std::size_t size = H5Tget_size(file_type.get());
  check(H5Tset_size(memory_type.get(), size + 1), path, "cannot size string type", name);
  check(H5Tset_strpad(memory_type.get(), H5T_STR_NULLTERM), path, "cannot set string padding", name);
  std::string value(size + 1, '\0');
  check(H5Aread(attribute.get(), memory_type.get(), value.data()), path, "cannot read attribute", name);
  value.resize(value.find('\0'));
  while (!value.empty() && value.back() == ' ') value.pop_back();
  return value;
}

std::vector<double> read_column(hid_t dataset, const std::string& name, const std::string& path) {
  const Handle space = checked(H5Dget_space(dataset), H5Sclose, path, "cannot get dataspace", name);
  if (H5Sget_simple_extent_ndims(space.get()) != 1) {
    throw InputError(ErrorContext{"io.hdf5", std::nullopt, name, ""},
                     fmt::format("{}: dataset '{}' is not one-dimensional", path, name));
  }
  hsize_t size = 0;
  check(H5Sget_simple_extent_dims(space.get(), &size, nullptr), path, "cannot get size", name);
  std::vector<double> values(static_cast<std::size_t>(size));
  if (size > 0) {
    check(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), path,
          "cannot read dataset", name);
  }
  return values;
}

}  // namespace

ChannelTable read_hdf5_channels(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (const std::string reason = detail::not_a_file_reason(path); !reason.empty()) {
    throw InputError(ErrorContext{"io.hdf5", std::nullopt, name, "check the path"}, fmt::format("'{}' {}", name, reason));
  }
  hdf5::silence_error_printing();
  const hid_t file_id = H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_id < 0) {
    throw InputError(ErrorContext{"io.hdf5", std::nullopt, name, "is it an HDF5 file?"},
                     fmt::format("cannot open '{}' as an HDF5 file", name));
  }
  const Handle file(file_id, H5Fclose);

  ChannelTable table;
  for (const std::string& link : root_names(file.get(), name)) {
    const Handle object = checked(H5Oopen(file.get(), link.c_str(), H5P_DEFAULT), H5Oclose, name,
                                  "cannot open object", link);
    if (H5Iget_type(object.get()) != H5I_DATASET) continue;  // groups are not channels
    table.names.push_back(link);
    table.units.push_back(read_string_attribute(object.get(), "unit", name).value_or(""));
    table.columns.push_back(read_column(object.get(), link, name));
  }
  const auto time = table.find("Time");
  if (!time) {
    throw InputError(ErrorContext{"io.hdf5", std::nullopt, name, ""},
                     fmt::format("{}: no 'Time' dataset; not a fowtsim output?", name));
  }
  // Time first, whatever the creation order said.
  std::rotate(table.names.begin(), table.names.begin() + *time, table.names.begin() + *time + 1);
  std::rotate(table.units.begin(), table.units.begin() + *time, table.units.begin() + *time + 1);
  std::rotate(table.columns.begin(), table.columns.begin() + *time, table.columns.begin() + *time + 1);

  // A crash in the middle of a block write can leave datasets one block apart: keep the rows that
  // every channel has.
  std::size_t rows = table.columns.front().size();
  for (const auto& column : table.columns) rows = std::min(rows, column.size());
  for (auto& column : table.columns) column.resize(rows);

  const hid_t root = file.get();
  table.status = read_string_attribute(root, "status", name).value_or("");
  table.description = fmt::format(
      "fowtsim {}; deck {} (hash {}); status {}", read_string_attribute(root, "version", name).value_or("?"),
      read_string_attribute(root, "deck_path", name).value_or("?"),
      read_string_attribute(root, "deck_hash", name).value_or("?"), table.status.empty() ? "?" : table.status);
  normalise_time_channel(table, name);
  return table;
}

}  // namespace fowtsim::io
