// Reader of OpenFAST binary outputs (.outb).
//
// Layout followed: OpenFAST's writer, SUBROUTINE WrBinFAST in modules/nwtc-library/src/NWTC_IO.f90
// (OpenFAST/openfast on GitHub), cross-checked with the toolbox readers ReadFASTbinary.m
// (OpenFAST/matlab-toolbox) and openfast_toolbox's load_binary_output. Fortran stream access, so no
// record markers; little-endian; every FileFmtID has the same header shape:
//
//   int16   FileID                1 WithTime, 2 WithoutTime, 3 NoCompressWithoutTime, 4 ChanLen_In
//   int16   LenName               only if FileID == 4; else names and units are 10 characters
//   int32   NumOutChans           channels, without time
//   int32   NT                    time steps
//   float64 TimeScl, TimeOff      if FileID == 1: time = (packed_time - TimeOff) / TimeScl
//   float64 TimeOut1, TimeIncr    otherwise:      time = TimeOut1 + i * TimeIncr
//   float32 ColScl[NumOutChans]   unless FileID == 3
//   float32 ColOff[NumOutChans]   unless FileID == 3: value = (packed - ColOff) / ColScl
//   int32   LenDesc, then LenDesc bytes of description text
//   (NumOutChans + 1) names of LenName bytes each, blank-padded, Time first
//   (NumOutChans + 1) units of LenName bytes each, e.g. "(m/s)"
//   int32   packed_time[NT]       only if FileID == 1
//   data, time-major (all channels of step 1, then step 2, ...):
//           float64[NT * NumOutChans] if FileID == 3, else int16[NT * NumOutChans]
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "file_bytes.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"

namespace fowtsim::io {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the .outb reader assumes a little-endian host, like the files OpenFAST writes");

constexpr const char* kModule = "io.openfast_binary";
constexpr const char* kStatusMark = "; Status: ";

enum FileFormat : std::int16_t {
  kWithTime = 1,
  kWithoutTime = 2,
  kNoCompressWithoutTime = 3,
  kChanLenIn = 4,
};

// Sequential reads with bounds checks, so a truncated file gives an error, never garbage.
class ByteCursor {
 public:
  ByteCursor(const std::string& bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  template <class T>
  T read(const char* what) {
    T value;
    std::memcpy(&value, take(sizeof(T), what), sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> read_array(std::size_t count, const char* what) {
    std::vector<T> values(count);
    if (count > 0) std::memcpy(values.data(), take(count * sizeof(T), what), count * sizeof(T));
    return values;
  }
  std::string read_text(std::size_t count, const char* what) {
    return std::string(take(count, what), count);
  }
  std::size_t remaining() const { return bytes_.size() - pos_; }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(ErrorContext{kModule, std::nullopt, name_, "is the file complete?"},
                     fmt::format("{}: {}", name_, message));
  }

 private:
  const char* take(std::size_t count, const char* what) {
    if (count > remaining()) {
      fail(fmt::format("file ends at byte {} while reading {} ({} bytes needed)", bytes_.size(),
                       what, count));
    }
    const char* start = bytes_.data() + pos_;
    pos_ += count;
    return start;
  }

  const std::string& bytes_;
  const std::string& name_;
  std::size_t pos_ = 0;
};

std::string trim_blanks(std::string text) {
  const auto first = text.find_first_not_of(" \0", 0, 2);
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(" \0", std::string::npos, 2);
  return text.substr(first, last - first + 1);
}

std::string strip_parentheses(std::string unit) {
  if (!unit.empty() && unit.front() == '(') unit.erase(0, 1);
  if (!unit.empty() && unit.back() == ')') unit.pop_back();
  return unit;
}

}  // namespace

ChannelTable read_openfast_binary(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::string bytes = detail::read_file_bytes(path, kModule);
  ByteCursor in(bytes, name);

  const auto format = in.read<std::int16_t>("FileID");
  if (format < kWithTime || format > kChanLenIn) {
    in.fail(fmt::format("unknown FileID {} (expected 1 to 4); not an OpenFAST binary output?", format));
  }
  const std::int16_t name_length = format == kChanLenIn ? in.read<std::int16_t>("LenName") : 10;
  const auto channel_count = in.read<std::int32_t>("NumOutChans");
  const auto step_count = in.read<std::int32_t>("NT");
  if (name_length <= 0 || channel_count < 0 || step_count < 0) {
    in.fail(fmt::format("invalid header: LenName {}, NumOutChans {}, NT {}", name_length,
                        channel_count, step_count));
  }
  const auto channels = static_cast<std::size_t>(channel_count);
  auto steps = static_cast<std::size_t>(step_count);
  const auto time_a = in.read<double>(format == kWithTime ? "TimeScl" : "TimeOut1");
  const auto time_b = in.read<double>(format == kWithTime ? "TimeOff" : "TimeIncr");
  std::vector<float> scale;
  std::vector<float> offset;
  if (format != kNoCompressWithoutTime) {
    scale = in.read_array<float>(channels, "ColScl");
    offset = in.read_array<float>(channels, "ColOff");
  }
  const auto description_length = in.read<std::int32_t>("LenDesc");
  if (description_length < 0) in.fail(fmt::format("negative LenDesc {}", description_length));

  ChannelTable table;
  table.description = trim_blanks(in.read_text(static_cast<std::size_t>(description_length), "DescStr"));
  // Ours (OutbWriter) end the description with "Status: <how the run ended>".
  if (const auto at = table.description.rfind(kStatusMark); at != std::string::npos)
    table.status = trim_blanks(table.description.substr(at + std::strlen(kStatusMark)));
  for (std::size_t c = 0; c <= channels; ++c) {
    table.names.push_back(trim_blanks(in.read_text(static_cast<std::size_t>(name_length), "ChanName")));
  }
  for (std::size_t c = 0; c <= channels; ++c) {
    table.units.push_back(
        strip_parentheses(trim_blanks(in.read_text(static_cast<std::size_t>(name_length), "ChanUnit"))));
  }

  // The rest of the file is the data; check its size before the (possibly large) allocations.
  if (steps > 0 && channels > in.remaining() / steps) {  // also guards the products below
    in.fail(fmt::format("header claims {} channels x {} steps, more than the file holds", channels, steps));
  }
  const std::size_t time_bytes = format == kWithTime ? steps * sizeof(std::int32_t) : 0;
  const std::size_t value_bytes = format == kNoCompressWithoutTime ? sizeof(double) : sizeof(std::int16_t);
  const std::size_t expected_bytes = time_bytes + steps * channels * value_bytes;
  if (in.remaining() < expected_bytes) {
    in.fail(fmt::format("{} data bytes after the header, expected {} for {} channels x {} steps",
                        in.remaining(), expected_bytes, channels, steps));
  }
  if (in.remaining() > expected_bytes) {
    // A writer that appends rows and then updates NT (ours, OutbWriter) leaves more rows than NT
    // says when it is killed between the two writes: with uniform time the rows after NT are read
    // as well (their times follow from TimeOut1 and TimeIncr); a last row cut short is dropped.
    // With packed time (FileID 1) the time array sits before the data, sized by NT: nothing to add.
    const std::size_t row_bytes = channels * value_bytes;
    if (format == kWithTime || row_bytes == 0) {
      in.fail(fmt::format("{} data bytes after the header, expected {} for {} channels x {} steps",
                          in.remaining(), expected_bytes, channels, steps));
    }
    const std::size_t whole_rows = in.remaining() / row_bytes;
    const std::string rows_found = fmt::format("the header says {} rows but the file holds {} whole rows{}", steps, whole_rows,
                                               in.remaining() % row_bytes ? " and part of one" : "");
    if (time_b > 0.0) {
      table.warnings.push_back(
          fmt::format("{}: {} (a writer stopped before updating its header?): all {} read", name, rows_found, whole_rows));
      steps = whole_rows;
    } else {  // no interval in the header yet (it had at most one row): the rows after it have no time
      table.warnings.push_back(
          fmt::format("{}: {}, without a time interval in the header: the {} rows it counts are read", name, rows_found, steps));
    }
  }

  table.columns.assign(channels + 1, std::vector<double>(steps));
  std::vector<double>& time = table.columns[0];
  if (format == kWithTime) {
    const auto packed = in.read_array<std::int32_t>(steps, "packed time");
    for (std::size_t i = 0; i < steps; ++i) time[i] = (packed[i] - time_b) / time_a;
  } else {
    for (std::size_t i = 0; i < steps; ++i) time[i] = time_a + static_cast<double>(i) * time_b;
  }
  if (format == kNoCompressWithoutTime) {
    const auto values = in.read_array<double>(steps * channels, "channel data");
    for (std::size_t i = 0; i < steps; ++i) {
      for (std::size_t c = 0; c < channels; ++c) table.columns[c + 1][i] = values[i * channels + c];
    }
  } else {
    const auto packed = in.read_array<std::int16_t>(steps * channels, "channel data");
    for (std::size_t i = 0; i < steps; ++i) {
      for (std::size_t c = 0; c < channels; ++c) {
        // Unpacked in double from the stored float32 factors, the inverse of WrBinFAST's packing.
        table.columns[c + 1][i] = (packed[i * channels + c] - static_cast<double>(offset[c])) /
                                  static_cast<double>(scale[c]);
      }
    }
  }
  normalise_time_channel(table, name);
  return table;
}

}  // namespace fowtsim::io
