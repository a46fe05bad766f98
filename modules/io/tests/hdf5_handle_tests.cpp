// The owning HDF5 identifier: closes exactly once, hands ownership on when moved, never closes
// an invalid identifier.
#include <hdf5.h>

#include <utility>

#include <catch2/catch.hpp>

#include "fowtsim/io/hdf5_handle.hpp"

using fowtsim::io::hdf5::Handle;

TEST_CASE("HDF5 handle closes its identifier when it goes out of scope", "[unit]") {
  hid_t id = H5I_INVALID_HID;
  {
    const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    id = space.get();
    REQUIRE(space.valid());
    CHECK(H5Iis_valid(id) > 0);
  }
  CHECK(H5Iis_valid(id) <= 0);  // closed by the destructor
}

TEST_CASE("HDF5 handle moves ownership and closes once", "[unit]") {
  Handle first(H5Screate(H5S_SCALAR), H5Sclose);
  const hid_t id = first.get();
  Handle second(std::move(first));
  CHECK(!first.valid());  // NOLINT(bugprone-use-after-move): the moved-from state is the point
  CHECK(second.get() == id);
  Handle third;
  third = std::move(second);
  CHECK(H5Iis_valid(id) > 0);  // still open: ownership moved twice, nothing closed
  CHECK(third.reset());        // one close, reported successful
  CHECK(H5Iis_valid(id) <= 0);
  CHECK(!third.valid());
}

TEST_CASE("HDF5 handle holds a failed call's identifier without closing it", "[unit]") {
  fowtsim::io::hdf5::silence_error_printing();
  const Handle missing(H5Fopen("/nonexistent/fowtsim.h5", H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  CHECK(!missing.valid());
}
