#include "fowtsim/io/wamit_input.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "file_bytes.hpp"
#include "wamit_blocks.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::io {
namespace {

constexpr const char* kModule = "io.wamit";

// The numeric lines of a WAMIT output file (blank lines skipped), each with its line number.
struct NumericLine {
  int number = 0;
  std::vector<double> values;
};

[[noreturn]] void fail(const std::filesystem::path& path, int line, const std::string& message) {
  throw InputError(ErrorContext{kModule, std::nullopt, path.filename().string(), ""},
                   line > 0 ? fmt::format("{}:{}: {}", path.string(), line, message) : fmt::format("{}: {}", path.string(), message));
}

// The numeric lines of a WAMIT output file (blank lines skipped). A file whose last data line has
// no line end was cut short, perhaps inside its last number ("2.78" of "2.784415E-02" still reads
// as a number), so it is refused: every tool that writes these files ends each line.
std::vector<NumericLine> numeric_lines(const std::filesystem::path& path, std::size_t min_fields, std::size_t max_fields) {
  const std::string bytes = detail::read_file_bytes(path, kModule);
  std::vector<NumericLine> lines;
  std::size_t start = 0;
  for (int number = 1; start < bytes.size(); ++number) {
    const std::size_t end = std::min(bytes.find('\n', start), bytes.size());
    std::istringstream fields(bytes.substr(start, end - start));
    start = end + 1;
    NumericLine line{number, {}};
    std::string field;
    while (fields >> field) {
      // std::stod also accepts Fortran's "1.0D+03" once D is an E.
      std::replace(field.begin(), field.end(), 'D', 'E');
      std::replace(field.begin(), field.end(), 'd', 'e');
      std::size_t used = 0;
      double value = 0.0;
      try {
        value = std::stod(field, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != field.size() || !std::isfinite(value)) fail(path, number, fmt::format("`{}` is not a number", field));
      line.values.push_back(value);
    }
    if (line.values.empty()) continue;
    if (end == bytes.size())
      fail(path, number, "the file ends inside this line, without a line end: cut short? (its last number may be incomplete)");
    if (line.values.size() < min_fields || line.values.size() > max_fields)
      fail(path, number, fmt::format("{} fields (expected {}{})", line.values.size(), min_fields,
                                     max_fields > min_fields ? fmt::format(" to {}", max_fields) : std::string()));
    lines.push_back(std::move(line));
  }
  if (lines.empty()) fail(path, 0, "no data lines");
  return lines;
}

int mode(const std::filesystem::path& path, const NumericLine& line, double value) {
  const int m = static_cast<int>(value);
  if (m != value || m < 1 || m > 6) fail(path, line.number, fmt::format("mode {} (expected 1 to 6)", value));
  return m - 1;
}

// L^k with k = 3, 4, 5 as both, one or none of the modes is a translation.
double radiation_scale(const WamitScales& s, int i, int j) {
  return std::pow(s.length_m, 3 + (i >= 3 ? 1 : 0) + (j >= 3 ? 1 : 0));
}

void check_scales(const std::filesystem::path& path, const WamitScales& s) {
  if (!(s.water_density_kg_m3 > 0.0) || !(s.gravity_m_s2 > 0.0) || !(s.length_m > 0.0))
    fail(path, 0, fmt::format("scales ρ = {}, g = {}, L = {} must be positive", s.water_density_kg_m3, s.gravity_m_s2, s.length_m));
}

std::string pair_name(std::size_t entry) { return fmt::format("({}, {})", entry / 6 + 1, entry % 6 + 1); }

double frequency_of(const std::filesystem::path& path, const NumericLine& line) {
  const double period = line.values[0];
  if (!(period > 0.0)) fail(path, line.number, fmt::format("period {} s (expected > 0 here)", period));
  return 2.0 * std::numbers::pi / period;
}

}  // namespace

WamitRadiation read_wamit_radiation(const std::filesystem::path& wamit_1, const WamitScales& scales) {
  check_scales(wamit_1, scales);
  std::map<double, std::pair<Mat6, Mat6>> by_frequency;  // ω → (A, B), ascending
  WamitRadiation r;
  detail::WamitBlocks blocks(wamit_1, pair_name);
  for (const NumericLine& line : numeric_lines(wamit_1, 4, 5)) {
    const double period = line.values[0];
    const int i = mode(wamit_1, line, line.values[1]), j = mode(wamit_1, line, line.values[2]);
    blocks.add(fmt::format("period {} s", period), static_cast<std::size_t>(6 * i + j), line.number);
    const double a = line.values[3] * scales.water_density_kg_m3 * radiation_scale(scales, i, j);
    if (period == -1.0 || period == 0.0) {  // the limits, A only: PER = −1 an infinite period (ω = 0),
                                            // PER = 0 a zero period (ω = ∞)
      std::optional<Mat6>& limit = period < 0.0 ? r.added_mass_zero_frequency : r.added_mass_infinite_frequency;
      if (!limit) limit = Mat6::Zero();
      (*limit)(i, j) = a;
      continue;
    }
    if (line.values.size() != 5) fail(wamit_1, line.number, "a finite period needs added mass and damping (5 fields)");
    const double omega = frequency_of(wamit_1, line);
    auto [entry, fresh] = by_frequency.try_emplace(omega, Mat6::Zero(), Mat6::Zero());
    entry->second.first(i, j) = a;
    entry->second.second(i, j) = line.values[4] * scales.water_density_kg_m3 * omega * radiation_scale(scales, i, j);
  }
  if (by_frequency.empty()) fail(wamit_1, 0, "no finite frequency");
  blocks.check_complete();
  for (const auto& [omega, ab] : by_frequency) {
    r.frequencies_rad_s.push_back(omega);
    r.added_mass.push_back(ab.first);
    r.damping.push_back(ab.second);
  }
  return r;
}

WamitExcitation read_wamit_excitation(const std::filesystem::path& wamit_3, const WamitScales& scales) {
  check_scales(wamit_3, scales);
  std::map<double, std::map<double, Vec6c>> by_heading;  // β → ω → X
  detail::WamitBlocks blocks(wamit_3, [](std::size_t i) { return fmt::format("mode {}", i + 1); });
  for (const NumericLine& line : numeric_lines(wamit_3, 7, 7)) {
    const double omega = frequency_of(wamit_3, line);
    const int i = mode(wamit_3, line, line.values[2]);
    blocks.add(fmt::format("period {} s, heading {}°", line.values[0], line.values[1]), static_cast<std::size_t>(i), line.number);
    const double scale = scales.water_density_kg_m3 * scales.gravity_m_s2 * std::pow(scales.length_m, i >= 3 ? 3 : 2);
    auto [entry, fresh] = by_heading[line.values[1]].try_emplace(omega, Vec6c::Zero());
    entry->second[i] = scale * std::complex<double>(line.values[5], line.values[6]);
  }
  blocks.check_complete();
  WamitExcitation x;
  for (const auto& [heading, by_frequency] : by_heading) {
    x.headings_deg.push_back(heading);
    std::vector<double> frequencies;
    std::vector<Vec6c> force;
    for (const auto& [omega, f] : by_frequency) {
      frequencies.push_back(omega);
      force.push_back(f);
    }
    if (x.frequencies_rad_s.empty()) x.frequencies_rad_s = frequencies;
    if (frequencies != x.frequencies_rad_s)
      fail(wamit_3, 0, fmt::format("heading {}° has other frequencies than heading {}°", heading, x.headings_deg.front()));
    x.force.push_back(std::move(force));
  }
  return x;
}

Mat6 read_wamit_hydrostatics(const std::filesystem::path& wamit_hst, const WamitScales& scales) {
  check_scales(wamit_hst, scales);
  Mat6 c = Mat6::Zero();
  // WAMIT writes all 36 entries, zeros included: one block, each entry once, all of them.
  detail::WamitBlocks blocks(wamit_hst, pair_name);
  int count = 0, last_line = 0;
  for (const NumericLine& line : numeric_lines(wamit_hst, 3, 3)) {
    const int i = mode(wamit_hst, line, line.values[0]), j = mode(wamit_hst, line, line.values[1]);
    blocks.add("the matrix", static_cast<std::size_t>(6 * i + j), line.number);
    last_line = line.number;
    c(i, j) = line.values[2] * scales.water_density_kg_m3 * scales.gravity_m_s2 * radiation_scale(scales, i, j) / scales.length_m;
    ++count;
  }
  if (count != 36)
    fail(wamit_hst, last_line, fmt::format("{} of the 36 entries (I, J) of the 6×6 matrix (WAMIT writes them all, zeros "
                                           "included: cut short?)", count));
  return c;
}

void check_same_frequencies(const WamitRadiation& radiation, const std::filesystem::path& wamit_1,
                            const WamitExcitation& excitation, const std::filesystem::path& wamit_3) {
  // Both files print the periods to 7 significant digits: the same period reads within 1e-6.
  constexpr double kRelativeTolerance = 1e-6;
  const std::vector<double>& a = radiation.frequencies_rad_s;
  const std::vector<double>& b = excitation.frequencies_rad_s;
  const bool same = a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [&](double x, double y) {
                      return std::abs(x - y) <= kRelativeTolerance * std::max(std::abs(x), std::abs(y));
                    });
  if (same) return;
  const auto span = [](const std::vector<double>& w) {
    return w.empty() ? std::string("none") : fmt::format("{} from {:.6g} to {:.6g} rad/s", w.size(), w.front(), w.back());
  };
  throw InputError(ErrorContext{kModule, std::nullopt, wamit_1.filename().string(), ""},
                   fmt::format("{} and {}: the finite frequencies differ ({}: {}; {}: {}); the two files of one WAMIT run "
                               "hold the same periods: is one of them cut short?",
                               wamit_1.string(), wamit_3.string(), wamit_1.filename().string(), span(a),
                               wamit_3.filename().string(), span(b)));
}

}  // namespace fowtsim::io
