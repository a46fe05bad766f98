#include "sweep/case_outcome.hpp"

#include <hdf5.h>

#include <fstream>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/hdf5_handle.hpp"

namespace fowtsim::driver::sweep {

namespace fs = std::filesystem;

const char* state_name(CaseState state) {
  switch (state) {
    case CaseState::completed: return "completed";
    case CaseState::failed: return "failed";
    case CaseState::interrupted: return "interrupted";
    case CaseState::running: return "running";
    case CaseState::stale: return "stale";
    case CaseState::missing: return "missing";
  }
  return "?";
}

namespace {

using io::hdf5::Handle;

std::optional<std::string> string_attribute(hid_t object, const char* name) {
  if (H5Aexists(object, name) <= 0) return std::nullopt;
  const Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  const Handle type(H5Aget_type(attribute.get()), H5Tclose);
  if (!attribute.valid() || !type.valid() || H5Tget_class(type.get()) != H5T_STRING) return std::nullopt;
  if (H5Tis_variable_str(type.get()) > 0) {
    const Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(memory.get(), H5T_VARIABLE);
    H5Tset_cset(memory.get(), H5Tget_cset(type.get()));
    char* text = nullptr;
    if (H5Aread(attribute.get(), memory.get(), &text) < 0 || text == nullptr) return std::nullopt;
    std::string value(text);
    H5free_memory(text);
    return value;
  }
  std::string value(H5Tget_size(type.get()), '\0');
  if (H5Aread(attribute.get(), type.get(), value.data()) < 0) return std::nullopt;
  value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
  return value;
}

std::optional<double> double_attribute(hid_t object, const char* name) {
  if (H5Aexists(object, name) <= 0) return std::nullopt;
  const Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  double value = 0.0;
  if (!attribute.valid() || H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0) return std::nullopt;
  return value;
}

// The line of the log that says why the run stopped: fowtsim writes its errors as "fowtsim: …"
// (a deck error continues on the lines after it, one problem per line: the first is kept).
std::string failure_line(const fs::path& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line)) {
    if (line.rfind("fowtsim: ", 0) == 0) {
      std::string next;
      if (line.back() == ':' && std::getline(in, next)) line += " " + next;
      return line.substr(9);
    }
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  return last;
}

std::optional<int> read_exit_code(const fs::path& file) {
  std::ifstream in(file);
  int code = 0;
  if (in >> code) return code;
  return std::nullopt;
}

}  // namespace

RunAttributes read_run_attributes(const fs::path& h5) {
  io::hdf5::silence_error_printing();  // errors are ours to report, not HDF5's to print
  const Handle file(H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw Error({"sweep", std::nullopt, "output", "remove it to rerun the case"}, "cannot open " + h5.string() + " as HDF5");
  RunAttributes a;
  a.status = string_attribute(file.get(), "status").value_or("");
  a.deck_hash = string_attribute(file.get(), "deck_hash").value_or("");
  a.wall_time_s = double_attribute(file.get(), "wall_time_s");
  a.end_time_s = double_attribute(file.get(), "end_time_s");
  return a;
}

CaseOutcome read_case_outcome(const SweepLayout& layout, const std::string& name, const std::string& deck_hash) {
  CaseOutcome o;
  o.exit_code = read_exit_code(layout.exit_code(name));
  const fs::path output = layout.output(name);
  if (fs::exists(output)) {
    RunAttributes a;
    try {
      a = read_run_attributes(output);
    } catch (const Error& e) {
      return {CaseState::failed, o.exit_code, e.what(), 0.0, 0.0};
    }
    o.wall_time_s = a.wall_time_s.value_or(0.0);
    o.end_time_s = a.end_time_s.value_or(0.0);
    if (a.deck_hash != deck_hash) {
      o.state = CaseState::stale;
      o.message = "output of another version of the case deck (deck_hash " + a.deck_hash + ")";
    } else if (a.status == "completed") {
      o.state = CaseState::completed;
    } else if (a.status.rfind("interrupted", 0) == 0) {
      o.state = CaseState::interrupted;
      o.message = a.status;
    } else {
      o.state = CaseState::failed;
      // "running" in a file renamed to its final name: the process died without closing it.
      o.message = a.status == "running" ? "the run was killed (its output still says running)" : failure_line(layout.log(name));
      if (o.message.empty()) o.message = a.status;
    }
    return o;
  }
  if (fs::exists(layout.running_output(name)) && !o.exit_code) {
    o.state = CaseState::running;
    return o;
  }
  if (o.exit_code) {
    o.state = *o.exit_code == 130 || *o.exit_code == 143 ? CaseState::interrupted : CaseState::failed;
    o.message = failure_line(layout.log(name));
  }
  return o;
}

}  // namespace fowtsim::driver::sweep
