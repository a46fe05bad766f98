#pragma once
// Small helpers the driver tests share: the message of the exception a call must throw, a channel's
// column, and the mean of a channel after a start-up transient.
#include <functional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/io/channel_table.hpp"
#include "fowtsim/testing/exception_message.hpp"

namespace fowtsim::driver {

using testing::message_of;  // fowtsim/testing/exception_message.hpp

// The column of channel `name` (the test fails if the table has none).
inline const std::vector<double>& column(const io::ChannelTable& t, const char* name) {
  const auto i = t.find(name);
  REQUIRE(i.has_value());
  return t.columns[*i];
}

// Mean of channel `name` over the rows at t ≥ t0 [s].
inline double mean_after(const io::ChannelTable& t, const char* name, double t0) {
  const auto c = t.find(name);
  REQUIRE(c);
  const auto& time = t.time();
  const auto& v = t.columns[*c];
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (time[i] >= t0) {
      sum += v[i];
      ++n;
    }
  REQUIRE(n > 0);
  return sum / n;
}

}  // namespace fowtsim::driver
