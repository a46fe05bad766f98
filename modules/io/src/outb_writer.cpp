#include "fowtsim/io/outb_writer.hpp"

#include <sys/types.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>

#include <fmt/format.h>

#include "row_file.hpp"
#include "status_field.hpp"

namespace fowtsim::io {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the .outb writer writes the host's byte order, which OpenFAST's readers take as little-endian");

constexpr std::int16_t kFileFmtIdNoCompressWithoutTime = 3;
constexpr off_t kRowCountOffset = 6;  // NT, then TimeOut1 and TimeIncr: 20 contiguous bytes
constexpr double kUniformTolerance = 1e-6;  // of the row interval

// A Fortran CHARACTER(10) value: cut or blank-padded.
std::string fixed_text(const std::string& text) {
  std::string field = text.substr(0, kOutbNameLength);
  field.resize(kOutbNameLength, ' ');
  return field;
}

template <class T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace

std::string outb_name_note(const std::vector<ChannelInfo>& channels) {
  constexpr std::size_t kListed = 8;  // names shown; a turbine's hundreds would swamp the summary
  std::vector<std::string> cut;
  std::map<std::string, std::vector<std::string>> by_cut_name;
  for (const ChannelInfo& c : channels) {
    if (c.name.size() <= kOutbNameLength) continue;
    const std::string short_name = c.name.substr(0, kOutbNameLength);
    cut.push_back(c.name + " → " + short_name);
    by_cut_name[short_name].push_back(c.name);
  }
  for (const ChannelInfo& c : channels)  // an uncut name equal to a cut one clashes too
    if (auto it = by_cut_name.find(c.name); it != by_cut_name.end()) it->second.push_back(c.name);
  if (cut.empty()) return "";
  auto listed = [&](const std::vector<std::string>& items) {
    std::string text;
    for (std::size_t i = 0; i < std::min(items.size(), kListed); ++i) text += (i ? ", " : " ") + items[i];
    if (items.size() > kListed) text += fmt::format(", … ({} more)", items.size() - kListed);
    return text;
  };
  std::string text = fmt::format("the .outb holds {} characters per channel name (FileFmtID 3): {} name{} cut:{}", kOutbNameLength,
                                 cut.size(), cut.size() == 1 ? "" : "s", listed(cut));
  std::vector<std::string> clashes;
  for (const auto& [short_name, names] : by_cut_name)
    if (names.size() > 1) clashes.push_back(fmt::format("{} ({} columns)", short_name, names.size()));
  if (!clashes.empty()) text += "; the same name then stands for several channels, in the .h5/.out order:" + listed(clashes);
  return text;
}

struct OutbWriter::Impl {
  enum class Phase { created, open, finished };

  detail::RowFile file;
  FlushPolicy policy;
  Phase phase = Phase::created;
  std::size_t channel_count = 0;  // declared channels, without Time
  std::vector<double> pending;    // rows not yet in the file, channels only; reserved once, at begin
  std::size_t pending_rows = 0;
  std::size_t rows_written = 0;   // rows in the file
  std::size_t rows_appended = 0;
  double first_time_s = 0.0;      // of row 0
  double interval_s = 0.0;        // t₁ − t₀, the grid appended rows are checked against
  double last_time_s = 0.0;       // of the last row appended
  double written_last_time_s = 0.0;  // of the last row in the file

  Impl(const std::filesystem::path& path, std::size_t rows_per_flush)
      : file("io.outb", path.string()), policy(rows_per_flush) {}

  // The rows after the last whole row, then the header's row count and interval, which only ever
  // describe rows already in the file.
  void write_pending() {
    if (pending_rows > 0) {
      file.append(pending.data(), pending.size() * sizeof(double), fmt::format("{} rows", pending_rows));
      rows_written += pending_rows;
      written_last_time_s = last_time_s;
      pending.clear();
      pending_rows = 0;
      write_row_count();
    }
    policy.flushed();
  }

  // NT, TimeOut1 and TimeIncr in place. The interval over the whole span written, (t_last − t₀) /
  // (n − 1), rebuilds every row's time to within rounding.
  void write_row_count() {
    if (rows_written > static_cast<std::size_t>(INT32_MAX)) file.fail("more than 2^31 − 1 rows: beyond the .outb format's row count");
    // NT (int32) then TimeOut1, TimeIncr (float64), packed as in the header; no allocation per flush.
    const auto rows = static_cast<std::int32_t>(rows_written);
    const double interval = rows_written > 1 ? (written_last_time_s - first_time_s) / static_cast<double>(rows_written - 1) : 0.0;
    std::array<char, sizeof rows + 2 * sizeof(double)> fields{};
    std::memcpy(fields.data(), &rows, sizeof rows);
    std::memcpy(fields.data() + sizeof rows, &first_time_s, sizeof(double));
    std::memcpy(fields.data() + sizeof rows + sizeof(double), &interval, sizeof(double));
    file.write_at(fields.data(), fields.size(), kRowCountOffset, "the header's row count");
  }

  // A row off the evenly spaced grid would be read back at the wrong time: refused.
  void check_uniform(double time_s) {
    if (rows_appended == 0) {
      first_time_s = time_s;
    } else if (rows_appended == 1) {
      interval_s = time_s - first_time_s;
      if (!(interval_s > 0.0))
        file.fail(fmt::format("row times {:.17g} s then {:.17g} s do not increase: the .outb format keeps evenly spaced rows only",
                              first_time_s, time_s));
    } else {
      const double expected = last_time_s + interval_s;
      if (!(std::abs(time_s - expected) <= kUniformTolerance * interval_s))
        file.fail(fmt::format("row {} at t = {:.17g} s is not one interval {:.17g} s after the last one ({:.17g} s): the .outb "
                              "format keeps evenly spaced rows only (first time and interval)",
                              rows_appended, time_s, interval_s, last_time_s));
    }
    last_time_s = time_s;
  }
};

OutbWriter::OutbWriter(std::filesystem::path path, std::size_t rows_per_flush)
    : impl_(std::make_unique<Impl>(path, rows_per_flush)) {}

OutbWriter::~OutbWriter() {
  impl_->file.mark_unfinished([this] { impl_->write_pending(); });
}

void OutbWriter::begin(const std::vector<ChannelInfo>& channels, const RunMetadata& metadata) {
  Impl& w = *impl_;
  if (w.phase != Impl::Phase::created) w.file.fail("begin() called twice");
  if (channels.size() > static_cast<std::size_t>(INT32_MAX)) w.file.fail("too many channels for the .outb format");
  w.file.create();
  w.phase = Impl::Phase::open;
  w.channel_count = channels.size();

  const std::string lead = fmt::format("Predictions were generated by fowtsim {}; deck {} (hash {}); Status: ", metadata.version,
                                       metadata.deck_path, metadata.deck_hash);
  const std::string description = lead + detail::status_field("running");
  std::string header;
  put<std::int16_t>(header, kFileFmtIdNoCompressWithoutTime);
  put<std::int32_t>(header, static_cast<std::int32_t>(channels.size()));
  put<std::int32_t>(header, 0);    // NT: no row yet
  put<double>(header, 0.0);        // TimeOut1, TimeIncr: set with the first rows
  put<double>(header, 0.0);
  put<std::int32_t>(header, static_cast<std::int32_t>(description.size()));
  w.file.set_status_offset(static_cast<off_t>(header.size() + lead.size()));
  header += description;
  header += fixed_text("Time");
  for (const ChannelInfo& c : channels) header += fixed_text(c.name);
  header += fixed_text("(s)");
  for (const ChannelInfo& c : channels) header += fixed_text("(" + c.unit + ")");
  w.file.append(header.data(), header.size(), "the header");
  w.pending.reserve(w.channel_count * w.policy.rows_per_block());
  w.policy.flushed();
}

void OutbWriter::append(double time_s, std::span<const double> values) {
  Impl& w = *impl_;
  if (w.phase != Impl::Phase::open) w.file.fail("append() before begin() or after finish()");
  if (values.size() != w.channel_count)
    w.file.fail(fmt::format("append() got {} values for {} declared channels", values.size(), w.channel_count));
  w.check_uniform(time_s);
  ++w.rows_appended;
  w.pending.insert(w.pending.end(), values.begin(), values.end());
  if (w.policy.due(++w.pending_rows)) w.write_pending();
}

void OutbWriter::flush() {
  if (impl_->phase == Impl::Phase::open) impl_->write_pending();
}

void OutbWriter::finish(const RunEnd& end) {
  Impl& w = *impl_;
  if (w.phase != Impl::Phase::open) w.file.fail("finish() before begin() or called twice");
  w.write_pending();
  w.write_row_count();  // again: an earlier rewrite of it may have failed after its rows went in
  w.file.write_status(end.status);
  w.phase = Impl::Phase::finished;
  w.file.close();
}

}  // namespace fowtsim::io
