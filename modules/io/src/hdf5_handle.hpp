#pragma once
// Private helpers shared by the HDF5 writer and reader: an owning wrapper for hid_t handles and
// the error conversion (HDF5 failures become fowtsim::Error with module "io.hdf5" and the path).
#include <hdf5.h>

#include <string>
#include <utility>

#include "fowtsim/core/error.hpp"

namespace fowtsim::io::hdf5 {

// Owns one HDF5 identifier and closes it with the matching H5?close function.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);

  Handle() = default;
  Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)), closer_(other.closer_) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
      closer_ = other.closer_;
    }
    return *this;
  }
  ~Handle() { reset(); }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Closes now; returns false if HDF5 reported a failure (never throws: used in destructors).
  bool reset() noexcept {
    bool ok = true;
    if (id_ >= 0 && closer_ != nullptr) ok = closer_(id_) >= 0;
    id_ = H5I_INVALID_HID;
    return ok;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

// HDF5 prints its error stack to stderr by default; library code must not print, and our own
// exceptions carry the context, so the automatic printing is switched off (process-wide).
inline void silence_error_printing() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

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
