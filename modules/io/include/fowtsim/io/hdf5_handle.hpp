#pragma once
// An owning wrapper for HDF5 identifiers (hid_t): io's HDF5 reader and writers and the driver's
// HDF5 files (post results, sweep load tables and case outcomes) share it.
#include <hdf5.h>

#include <utility>

namespace fowtsim::io::hdf5 {

// Owns one HDF5 identifier and closes it with the matching H5?close function. An invalid
// identifier (< 0, what a failed H5 call returns) is held but never closed.
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

// HDF5 prints its error stack to stderr by default; our callers report failures themselves with
// their context, so the automatic printing is switched off (process-wide).
inline void silence_error_printing() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

}  // namespace fowtsim::io::hdf5
