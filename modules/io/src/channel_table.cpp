#include "fowtsim/io/channel_table.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::io {

std::size_t ChannelTable::rows() const { return columns.empty() ? 0 : columns.front().size(); }

std::optional<std::size_t> ChannelTable::find(std::string_view name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return std::nullopt;
  return static_cast<std::size_t>(it - names.begin());
}

const std::vector<double>& ChannelTable::time() const {
  if (columns.empty()) {
    throw Error(ErrorContext{"io", std::nullopt, "Time", ""},
                "channel table has no columns, hence no time channel");
  }
  return columns.front();
}

std::vector<std::string> reading_warnings(const ChannelTable& table, const std::string& source) {
  std::vector<std::string> warnings = table.warnings;
  const double last = table.rows() ? table.time().back() : 0.0;
  if (table.status == "running")
    warnings.push_back(fmt::format("{}: status 'running': the run that writes it is still going, or it died without closing "
                                   "the file (SIGKILL, power loss); its rows up to t = {:.6g} s are read",
                                   source, last));
  else if (!table.status.empty() && table.status != "completed")
    warnings.push_back(fmt::format("{}: the run did not complete (status '{}'); its rows up to t = {:.6g} s are read", source,
                                   table.status, last));
  return warnings;
}

void normalise_time_channel(ChannelTable& table, const std::string& source) {
  const auto fail = [&](const std::string& message, const std::string& hint) {
    throw InputError(ErrorContext{"io", std::nullopt, source, hint}, message);
  };
  if (table.names.empty()) fail(fmt::format("{}: no channels found", source), "");
  if (table.units.size() != table.names.size() || table.columns.size() != table.names.size()) {
    fail(fmt::format("{}: {} channel names but {} units and {} columns", source, table.names.size(),
                     table.units.size(), table.columns.size()),
         "");
  }
  const std::size_t rows = table.columns.front().size();
  for (std::size_t c = 1; c < table.columns.size(); ++c) {
    if (table.columns[c].size() != rows) {
      fail(fmt::format("{}: channel '{}' has {} rows, time has {}", source, table.names[c],
                       table.columns[c].size(), rows),
           "");
    }
  }
  std::string first = table.names.front();
  std::transform(first.begin(), first.end(), first.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (first != "time") {
    fail(fmt::format("{}: the first channel is '{}', expected the time channel 'Time'", source,
                     table.names.front()),
         "only time-series outputs with a leading Time column can be read");
  }
  // OpenFAST writes "Time" with unit "(s)"; normalising here spares every caller the variants.
  // (Move-assigned std::strings: assigning the literals trips GCC 12's false -Wrestrict, PR 105329.)
  table.names.front() = std::string("Time");
  table.units.front() = std::string("s");
}

}  // namespace fowtsim::io
