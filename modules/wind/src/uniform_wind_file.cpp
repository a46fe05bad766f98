#include "fowtsim/wind/uniform_wind_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/text_fields.hpp"

namespace fowtsim::wind {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr const char* kLayout =
    "8 or 9 numbers per row: Time s, speed m/s, direction deg, vertical speed m/s, horizontal linear shear, "
    "power-law exponent, vertical linear shear, gust speed m/s[, upflow deg]; '!' starts a comment line";

[[noreturn]] void bad(const std::string& where, const std::string& message) {
  throw InputError({"wind", std::nullopt, "wind.file", kLayout}, where + ": " + message);
}

bool comment(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t\v\f");
  return first != std::string_view::npos && (line[first] == '!' || line[first] == '#' || line[first] == '%');
}

double number(std::string_view field, const std::string& where, const char* what) {
  const char* first = field.data();
  const char* last = first + field.size();
  if (first != last && *first == '+') ++first;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || end != last) bad(where, "cannot read '" + std::string(field) + "' as " + what);
  if (!std::isfinite(value)) bad(where, std::string(what) + " is not finite ('" + std::string(field) + "')");
  return value;
}

}  // namespace

UniformWindHistory parse_uniform_wind(std::string_view text, const std::string& source) {
  static const char* const kColumns[9] = {"a time [s]",
                                          "a horizontal speed [m/s]",
                                          "a direction [deg]",
                                          "a vertical speed [m/s]",
                                          "a horizontal linear shear [-]",
                                          "a power-law exponent [-]",
                                          "a vertical linear shear [-]",
                                          "a gust speed [m/s]",
                                          "an upflow angle [deg]"};
  UniformWindHistory h;
  h.source = source;
  std::size_t columns = 0, number_of_line = 0, pos = 0;
  double previous_direction_deg = 0.0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++number_of_line;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (comment(line)) continue;
    const std::vector<std::string_view> fields = split_fields(line);
    if (fields.empty()) continue;
    const std::string where = source + ":" + std::to_string(number_of_line);
    if (columns == 0) {
      if (fields.size() != 8 && fields.size() != 9)
        bad(where, "expected 8 or 9 numbers in the first data row, found " + std::to_string(fields.size()) + " fields");
      columns = fields.size();
    } else if (fields.size() != columns) {
      bad(where, "expected " + std::to_string(columns) + " numbers as in the first data row (line " +
                     std::to_string(h.lines.front()) + "), found " + std::to_string(fields.size()) + " fields");
    }
    double v[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (std::size_t k = 0; k < columns; ++k) v[k] = number(fields[k], where, kColumns[k]);
    if (!h.rows.empty() && !(v[0] > h.rows.back().time_s))
      bad(where, "time " + std::string(fields[0]) + " s is not after the previous row's (times must increase)");
    // InflowWind unwraps each direction to within 180° of the previous one (interpolation takes the
    // short way round); a jump of exactly 180° has no short way and is refused, as there.
    double direction_deg = v[2];
    if (!h.rows.empty()) {
      const double jump = std::remainder(direction_deg - previous_direction_deg, 360.0);
      if (std::abs(jump) == 180.0) bad(where, "the direction jumps by 180° from the previous row: ambiguous sense of turn");
      direction_deg = previous_direction_deg + jump;
    }
    previous_direction_deg = direction_deg;
    h.rows.push_back({v[0], v[1], direction_deg * kDegree, v[3], v[4], v[5], v[6], v[7], v[8] * kDegree});
    h.lines.push_back(number_of_line);
  }
  if (h.rows.empty()) bad(source, "no data rows (only comments or blank lines)");
  return h;
}

UniformWindHistory read_uniform_wind_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) bad(path.string(), "cannot open the uniform wind file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_uniform_wind(text.str(), path.string());
}

UniformWindRow uniform_wind_at(const UniformWindHistory& h, double t) {
  const std::vector<UniformWindRow>& r = h.rows;
  if (t <= r.front().time_s) return r.front();
  if (t >= r.back().time_s) return r.back();
  const auto upper = std::upper_bound(r.begin(), r.end(), t, [](double x, const UniformWindRow& row) { return x < row.time_s; });
  const UniformWindRow& b = *upper;
  const UniformWindRow& a = *(upper - 1);
  const double w = (t - a.time_s) / (b.time_s - a.time_s);
  auto lerp = [w](double x, double y) { return x + (y - x) * w; };
  return {t,
          lerp(a.speed_m_s, b.speed_m_s),
          lerp(a.direction_rad, b.direction_rad),
          lerp(a.vertical_m_s, b.vertical_m_s),
          lerp(a.horizontal_shear, b.horizontal_shear),
          lerp(a.power_law_exponent, b.power_law_exponent),
          lerp(a.vertical_linear_shear, b.vertical_linear_shear),
          lerp(a.gust_m_s, b.gust_m_s),
          lerp(a.upflow_rad, b.upflow_rad)};
}

Vec3 uniform_wind_velocity(const UniformWindRow& row, const Vec3& p, double ref_height_m, double ref_length_m) {
  if (p.z() <= 0.0) return Vec3::Zero();
  const double cd = std::cos(row.direction_rad), sd = std::sin(row.direction_rad);
  const double v1 = row.speed_m_s * (std::pow(p.z() / ref_height_m, row.power_law_exponent) +
                                     (row.horizontal_shear * (p.y() * cd + p.x() * sd) +
                                      row.vertical_linear_shear * (p.z() - ref_height_m)) /
                                         ref_length_m) +
                    row.gust_m_s;
  const double cu = std::cos(row.upflow_rad), su = std::sin(row.upflow_rad);
  const double along = cu * v1 - su * row.vertical_m_s;
  return Vec3(along * cd, -along * sd, su * v1 + cu * row.vertical_m_s);
}

}  // namespace fowtsim::wind
