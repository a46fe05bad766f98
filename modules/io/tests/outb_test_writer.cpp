#include "outb_test_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

namespace fowtsim::io::testing {
namespace {

class Output {
 public:
  explicit Output(const std::filesystem::path& path) : file_(std::fopen(path.string().c_str(), "wb")) {
    if (file_ == nullptr) throw std::runtime_error("cannot create " + path.string());
  }
  ~Output() { std::fclose(file_); }
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  template <class T>
  void put(T value) { put_bytes(&value, sizeof value); }
  template <class T>
  void put_all(const std::vector<T>& values) { put_bytes(values.data(), values.size() * sizeof(T)); }
  // A Fortran CHARACTER(len) value: blank-padded or cut to `length`.
  void put_text(const std::string& text, std::size_t length) {
    std::string padded = text.substr(0, length);
    padded.resize(length, ' ');
    put_bytes(padded.data(), length);
  }

 private:
  void put_bytes(const void* data, std::size_t size) {
    if (size > 0 && std::fwrite(data, 1, size, file_) != size) throw std::runtime_error("write failed");
  }
  std::FILE* file_;
};

// Fortran NINT: nearest integer, halves away from zero.
long nint(double value) { return std::lround(value); }

}  // namespace

void write_openfast_binary(const std::filesystem::path& path, const ChannelTable& table,
                           OutbFormat format, const std::string& description) {
  const std::size_t channels = table.columns.size() - 1;
  const std::size_t steps = table.rows();
  const std::vector<double>& time = table.columns[0];
  const auto id = static_cast<std::int16_t>(format);

  std::size_t name_length = 10;
  std::vector<std::string> units;
  for (const std::string& unit : table.units) units.push_back("(" + unit + ")");
  if (format == OutbFormat::chan_len_in) {  // WrBinFAST: the longest trimmed name or unit, at least 1
    name_length = 1;
    for (std::size_t c = 0; c <= channels; ++c) {
      name_length = std::max({name_length, table.names[c].size(), units[c].size()});
    }
  }

  Output out(path);
  out.put<std::int16_t>(id);
  if (format == OutbFormat::chan_len_in) out.put<std::int16_t>(static_cast<std::int16_t>(name_length));
  out.put<std::int32_t>(static_cast<std::int32_t>(channels));
  out.put<std::int32_t>(static_cast<std::int32_t>(steps));

  std::vector<std::int32_t> packed_time;
  if (format == OutbFormat::with_time) {
    // WrBinFAST's "Int32" range is [-65536, 65535] (sic), kept here to match its files.
    constexpr double kInt32Max = 65535.0;
    constexpr double kInt32Min = -65536.0;
    const auto [low, high] = std::minmax_element(time.begin(), time.end());
    const double scale = *high == *low ? 1.0 : (kInt32Max - kInt32Min) / (*high - *low);
    const double offset = kInt32Min - scale * *low;
    for (const double t : time) {
      packed_time.push_back(static_cast<std::int32_t>(nint(std::clamp(scale * t + offset, kInt32Min, kInt32Max))));
    }
    out.put(scale);
    out.put(offset);
  } else {
    out.put(time.at(0));
    out.put(steps > 1 ? time[1] - time[0] : 0.0);
  }

  std::vector<float> scales(channels);
  std::vector<float> offsets(channels);
  if (format != OutbFormat::no_compress_without_time) {
    constexpr float kIntMax = 32767.0F;
    constexpr float kIntMin = -32768.0F;
    constexpr float kIntRange = kIntMax - kIntMin;
    for (std::size_t c = 0; c < channels; ++c) {
      const auto [low, high] = std::minmax_element(table.columns[c + 1].begin(), table.columns[c + 1].end());
      // Single precision throughout, as the REAL(SiKi) factors of WrBinFAST.
      scales[c] = *high == *low ? kIntRange / std::sqrt(std::numeric_limits<float>::epsilon())
                                : kIntRange / static_cast<float>(*high - *low);
      offsets[c] = kIntMin - scales[c] * static_cast<float>(*low);
    }
    out.put_all(scales);
    out.put_all(offsets);
  }

  out.put<std::int32_t>(static_cast<std::int32_t>(description.size()));
  out.put_text(description, description.size());
  for (std::size_t c = 0; c <= channels; ++c) out.put_text(table.names[c], name_length);
  for (std::size_t c = 0; c <= channels; ++c) out.put_text(units[c], name_length);

  if (format == OutbFormat::with_time) out.put_all(packed_time);
  if (format == OutbFormat::no_compress_without_time) {
    std::vector<double> values;
    for (std::size_t i = 0; i < steps; ++i) {
      for (std::size_t c = 0; c < channels; ++c) values.push_back(table.columns[c + 1][i]);
    }
    out.put_all(values);
  } else {
    std::vector<std::int16_t> values;
    for (std::size_t i = 0; i < steps; ++i) {
      for (std::size_t c = 0; c < channels; ++c) {
        // ColScl*x + ColOff in the data's precision, rounded to single, clamped, then NINT.
        const auto scaled = static_cast<float>(static_cast<double>(scales[c]) * table.columns[c + 1][i] +
                                               static_cast<double>(offsets[c]));
        values.push_back(static_cast<std::int16_t>(nint(std::clamp(scaled, -32768.0F, 32767.0F))));
      }
    }
    out.put_all(values);
  }
}

}  // namespace fowtsim::io::testing
