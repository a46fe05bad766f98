// Reader of OpenFAST text outputs (.out). Layout, as written by OpenFAST's WrOutputLine /
// FAST_Output and the module drivers (BeamDyn, AeroDyn): free header lines, one names line
// starting with "Time", one units line "(s) (m) ...", then one numeric row per output time.
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "file_bytes.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"

namespace fowtsim::io {
namespace {

constexpr const char* kModule = "io.openfast_text";

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

// Header fields are tab-separated when the line has a tab (OpenFAST's default; a field could then
// hold a space), else whitespace-separated (older space-delimited outputs). Empty fields are dropped.
std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  const bool tabbed = line.find('\t') != std::string_view::npos;
  std::size_t pos = 0;
  while (pos <= line.size()) {
    std::size_t end = pos;
    if (tabbed) {
      end = line.find('\t', pos);
      if (end == std::string_view::npos) end = line.size();
    } else {
      while (pos < line.size() && is_blank(line[pos])) ++pos;
      end = pos;
      while (end < line.size() && !is_blank(line[end])) ++end;
    }
    const std::string_view field = trim(line.substr(pos, end - pos));
    if (!field.empty()) fields.push_back(field);
    pos = end + 1;
  }
  return fields;
}

bool starts_with_time(std::string_view line) {
  const std::string_view text = trim(line);
  if (text.size() < 4) return false;
  for (std::size_t i = 0; i < 4; ++i) {
    if ((text[i] | 0x20) != "time"[i]) return false;  // ASCII case-insensitive
  }
  return text.size() == 4 || is_blank(text[4]);
}

bool is_units_line(std::string_view line) {
  const std::string_view text = trim(line);
  return !text.empty() && text.front() == '(';
}

// Value of a number from_chars found out of double range: its exponent sign says which end.
double out_of_range_value(std::string_view token) {
  const bool negative = !token.empty() && token.front() == '-';
  const std::size_t e = token.find_first_of("eE");
  const bool underflow = e != std::string_view::npos && e + 1 < token.size() && token[e + 1] == '-';
  const double magnitude = underflow ? 0.0 : std::numeric_limits<double>::infinity();
  return negative ? -magnitude : magnitude;
}

bool parse_plain(std::string_view token, double& value) {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') ++first;  // from_chars rejects a leading '+'
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ptr != last) return false;
  if (ec == std::errc::result_out_of_range) {
    value = out_of_range_value(token);
    return true;
  }
  return ec == std::errc();
}

// Fortran spellings from_chars does not take: "D" exponents (1.0D+03) and, for 3-digit exponents
// with an Ew.d edit descriptor, no exponent letter at all (1.234-100 means 1.234E-100).
bool parse_fortran_fallback(std::string_view token, double& value) {
  char buffer[96];
  if (token.size() + 2 > sizeof buffer) return false;
  std::size_t n = 0;
  bool has_exponent_letter = false;
  for (std::size_t i = 0; i < token.size(); ++i) {
    char c = token[i];
    if (c == 'D' || c == 'd') c = 'E';
    if (c == 'E' || c == 'e') has_exponent_letter = true;
    const bool sign_after_mantissa =
        (c == '+' || c == '-') && i > 0 && (std::isdigit(static_cast<unsigned char>(token[i - 1])) ||
                                            token[i - 1] == '.');
    if (!has_exponent_letter && sign_after_mantissa) {
      buffer[n++] = 'E';
      has_exponent_letter = true;
    }
    buffer[n++] = c;
  }
  return parse_plain(std::string_view(buffer, n), value);
}

bool parse_number(std::string_view token, double& value) {
  return parse_plain(token, value) || parse_fortran_fallback(token, value);
}

class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}

  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(pos_, end - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = end + 1;
    ++number_;
    return true;
  }
  std::size_t number() const { return number_; }      // 1-based number of the last line returned
  std::size_t remaining_bytes() const { return pos_ < text_.size() ? text_.size() - pos_ : 0; }
  // The line last read was the file's last and had no line end.
  bool unterminated() const { return pos_ > text_.size(); }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

}  // namespace

ChannelTable read_openfast_text(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::string text = detail::read_file_bytes(path, kModule);
  const auto fail = [&](std::size_t line, const std::string& message) {
    throw InputError(ErrorContext{kModule, std::nullopt, name, ""},
                     fmt::format("{}:{}: {}", name, line, message));
  };

  ChannelTable table;
  Lines lines(text);
  std::string_view line;
  std::string_view names_line;
  std::size_t names_line_number = 0;
  std::vector<std::string_view> header;
  bool found = false;
  while (lines.next(line)) {
    if (names_line_number != 0) {
      if (is_units_line(line)) {
        found = true;
        break;
      }
      header.push_back(names_line);  // a header line that merely starts with the word "Time"
      names_line_number = 0;
    }
    if (starts_with_time(line)) {
      names_line = line;
      names_line_number = lines.number();
    } else {
      header.push_back(line);
    }
  }
  if (!found) {
    fail(lines.number(), "no channel-names line starting with 'Time' followed by a units line");
  }
  for (const std::string_view header_line : header) {
    const std::string_view trimmed = trim(header_line);
    if (trimmed.empty()) continue;
    if (trimmed.starts_with("Status: ")) table.status = trim(trimmed.substr(8));  // ours: line 5
    if (!table.description.empty()) table.description += '\n';
    table.description += trimmed;
  }
  for (const std::string_view field : split_fields(names_line)) table.names.emplace_back(field);
  for (std::string_view field : split_fields(line)) {
    if (field.front() == '(') field.remove_prefix(1);
    if (!field.empty() && field.back() == ')') field.remove_suffix(1);
    table.units.emplace_back(field);
  }
  if (table.units.size() != table.names.size()) {
    fail(lines.number(), fmt::format("{} units for {} channel names on line {}", table.units.size(),
                                     table.names.size(), names_line_number));
  }

  const std::size_t channel_count = table.names.size();
  table.columns.resize(channel_count);
  bool reserved = false;
  while (lines.next(line)) {
    // OpenFAST and our writer end every row: a last row without a line end was cut by a writer that
    // died mid-row, perhaps inside its last number (which would still read: "0.12" of
    // "0.1234E+01"). It is dropped with a warning; every whole row before it is read.
    if (lines.unterminated() && !trim(line).empty()) {
      table.warnings.push_back(
          fmt::format("{}:{}: the last row is cut short (no line end; the writer stopped mid-row): dropped", name, lines.number()));
      break;
    }
    const char* p = line.data();
    const char* const end = p + line.size();
    std::size_t column = 0;
    while (true) {
      while (p != end && is_blank(*p)) ++p;
      if (p == end) break;
      const char* token_end = p;
      while (token_end != end && !is_blank(*token_end)) ++token_end;
      const std::string_view token(p, static_cast<std::size_t>(token_end - p));
      if (column == channel_count) {
        fail(lines.number(), fmt::format("more than {} values on the row", channel_count));
      }
      double value = 0.0;
      if (!parse_number(token, value)) {
        fail(lines.number(), fmt::format("cannot read '{}' as a number (channel {})", token,
                                         table.names[column]));
      }
      table.columns[column].push_back(value);
      ++column;
      p = token_end;
    }
    if (column == 0) continue;  // blank line (trailing blank lines are common)
    if (column != channel_count) {
      fail(lines.number(), fmt::format("{} values on the row, expected {}", column, channel_count));
    }
    if (!reserved) {
      // Rows have nearly equal length: one reservation from the first avoids regrowth.
      const std::size_t estimate = lines.remaining_bytes() / (line.size() + 1) + 2;
      for (auto& values : table.columns) values.reserve(estimate);
      reserved = true;
    }
  }
  normalise_time_channel(table, name);
  return table;
}

}  // namespace fowtsim::io
