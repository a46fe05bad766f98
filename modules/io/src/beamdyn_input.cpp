// Reader of BeamDyn stand-alone driver cases (see beamdyn_input.hpp). Layout of the three files,
// as BeamDyn reads them (Driver_Beam_Subs.f90, BeamDyn_IO.f90):
//   line 1 a banner, line 2 a title, then lines "value(s)  Name  - description", section lines
//   "---…"/"===…", and tables without names after some named lines (GlbDCM after GlbPos(3), point
//   loads after NumPointLoads, member and key-point rows after kp_total, mu after damp_type,
//   stations after mu or zeta, channel names after OutList).
// Values follow Fortran list-directed input: fields separated by blanks, tabs or commas, strings
// possibly quoted, logicals T/F/True/False in any case, reals with E or D exponents.
#include "fowtsim/io/beamdyn_input.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "file_bytes.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::io {
namespace {

constexpr const char* kModule = "io.beamdyn";
constexpr std::size_t kFirstBodyLine = 2;  // lines 1 and 2 (banner, title) are never data

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

bool iequals(std::string_view a, std::string_view b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) ==
           std::tolower(static_cast<unsigned char>(y));
  });
}

// Fields of a line as Fortran list-directed input sees them: separated by blanks and commas; a
// field that starts with a quote runs to the closing quote (or the end of the line) and may hold
// blanks and commas. Quotes are removed.
std::vector<std::string> split_fields(std::string_view text) {
  std::vector<std::string> fields;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const char c = text[pos];
    if (is_blank(c) || c == ',') {
      ++pos;
    } else if (c == '"' || c == '\'') {
      const std::size_t close = text.find(c, pos + 1);
      const std::size_t end = close == std::string_view::npos ? text.size() : close;
      fields.emplace_back(text.substr(pos + 1, end - pos - 1));
      pos = end + 1;
    } else {
      std::size_t end = pos;
      while (end < text.size() && !is_blank(text[end]) && text[end] != ',') ++end;
      fields.emplace_back(text.substr(pos, end - pos));
      pos = end;
    }
  }
  return fields;
}

// Fortran reals: also "1.0D+00" (D exponent) and a leading '+'. Only finite values are accepted.
std::optional<double> parse_real(std::string_view field) {
  std::string text(field);
  if (!text.empty() && text.front() == '+') text.erase(0, 1);  // from_chars rejects a leading '+'
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == 'd' || c == 'D'; }, 'E');
  double value = 0.0;
  const char* const end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<long long> parse_integer(std::string_view field) {
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  long long value = 0;
  const char* const end = field.data() + field.size();
  const auto [ptr, ec] = std::from_chars(field.data(), end, value);
  if (field.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

// Fortran logicals as written in OpenFAST inputs: T, F, True, False, .TRUE., .FALSE. (any case).
std::optional<bool> parse_logical(std::string_view field) {
  if (field.size() > 2 && field.front() == '.' && field.back() == '.') {
    field = field.substr(1, field.size() - 2);
  }
  if (iequals(field, "t") || iequals(field, "true")) return true;
  if (iequals(field, "f") || iequals(field, "false")) return false;
  return std::nullopt;
}

struct Line {
  int number = 0;                   // 1-based line number in the file
  std::vector<std::string> fields;  // list-directed fields (split_fields)
  bool comment = false;             // a section or comment line: "---…" or "===…"
  bool unterminated = false;        // the file's last line, without a line end: cut short

  bool blank() const { return fields.empty(); }
  bool starts_with_number() const {
    return !fields.empty() && parse_real(fields.front()).has_value();
  }
};

class InputFile;

// A named line "value(s)  Name  - description" of an input file.
class Entry {
 public:
  Entry(const InputFile& file, std::size_t index, std::string key)
      : file_(&file), index_(index), key_(std::move(key)) {}

  std::size_t index() const { return index_; }  // index of the line in the file
  const Line& line() const;

  double real(std::size_t field = 0) const;
  int integer(int min, int max = INT_MAX, std::size_t field = 0) const;
  bool logical() const;
  std::string text() const { return line().fields[0]; }
  // OpenFAST's DEFAULT test: the value, upper-cased, starts with "DEFAULT" (quoted or not).
  bool is_default() const { return iequals(text().substr(0, 7), "default"); }

  [[noreturn]] void fail(const std::string& message) const;

 private:
  const InputFile* file_;
  std::size_t index_;
  std::string key_;
};

class InputFile {
 public:
  explicit InputFile(const std::filesystem::path& path) : path_(path) {
    const std::string bytes = detail::read_file_bytes(path, kModule);
    std::string_view rest(bytes);
    while (!rest.empty()) {
      const std::size_t end = std::min(rest.find('\n'), rest.size());
      std::string_view text = rest.substr(0, end);
      if (!text.empty() && text.back() == '\r') text.remove_suffix(1);  // CRLF files
      const bool unterminated = end == rest.size();
      rest.remove_prefix(std::min(end + 1, rest.size()));
      lines_.push_back(make_line(text, static_cast<int>(lines_.size()) + 1));
      lines_.back().unterminated = unterminated;
      if (lines_.size() == 2) title_ = trim(text);
    }
  }

  const std::filesystem::path& path() const { return path_; }
  const std::string& title() const { return title_; }
  std::size_t size() const { return lines_.size(); }
  const Line& line(std::size_t index) const { return lines_[index]; }

  // "file:line: key: message" (or "file: key: message" without a line).
  [[noreturn]] void fail(const Line* line, std::string_view key, const std::string& message) const {
    const std::string where =
        line ? fmt::format("{}:{}", path_.string(), line->number) : path_.string();
    throw InputError(ErrorContext{kModule, std::nullopt, std::string(key), ""},
                     fmt::format("{}: {}: {}", where, key, message));
  }

  // The first line naming `key` (any letter case) before its description, with `values` fields
  // in front of the name; a name found with fewer values in front is an error.
  std::optional<Entry> find(std::string_view key, std::size_t values = 1) const {
    for (std::size_t i = kFirstBodyLine; i < lines_.size(); ++i) {
      const Line& line = lines_[i];
      if (line.comment) continue;
      for (std::size_t f = 0; f < line.fields.size() && line.fields[f] != "-"; ++f) {
        if (!iequals(line.fields[f], key)) continue;
        if (f < values) {
          fail(&line, key,
               fmt::format("expected {} value{} before the name, found {}", values,
                           values == 1 ? "" : "s", f));
        }
        return Entry(*this, i, std::string(key));
      }
    }
    return std::nullopt;
  }

  Entry entry(std::string_view key, std::size_t values = 1) const {
    if (auto found = find(key, values)) return *found;
    fail(nullptr, key,
         fmt::format("expected a line \"<value>  {}  - description\", found none", key));
  }

 private:
  static Line make_line(std::string_view text, int number) {
    const std::string_view trimmed = trim(text);
    const bool comment = trimmed.starts_with("---") || trimmed.starts_with("===");
    return Line{number, comment ? std::vector<std::string>{} : split_fields(text), comment};
  }

  std::filesystem::path path_;
  std::string title_;
  std::vector<Line> lines_;
};

const Line& Entry::line() const { return file_->line(index_); }

void Entry::fail(const std::string& message) const { file_->fail(&line(), key_, message); }

// A number read from a last line without a line end may be cut ("7.0" of "7.000000E-01"): every
// tool that writes these files ends each line, so such a file was cut short and is refused.
void check_terminated(const InputFile& file, const Line& line, std::string_view what) {
  if (line.unterminated)
    file.fail(&line, what, "the file ends inside this line, without a line end: cut short? (its last number may be incomplete)");
}

// Value checks shared by named lines and table rows: `what` names the value in messages.
double to_real(const InputFile& file, const Line& line, std::string_view what,
               const std::string& field) {
  check_terminated(file, line, what);
  const auto value = parse_real(field);
  if (!value) file.fail(&line, what, fmt::format("expected a number, got \"{}\"", field));
  return *value;
}

int to_integer(const InputFile& file, const Line& line, std::string_view what,
               const std::string& field, int min, int max) {
  check_terminated(file, line, what);
  const auto value = parse_integer(field);
  if (!value || *value < min || *value > max) {
    const std::string range =
        max == INT_MAX ? fmt::format("≥ {}", min) : fmt::format("in [{}, {}]", min, max);
    file.fail(&line, what, fmt::format("expected an integer {}, got \"{}\"", range, field));
  }
  return static_cast<int>(*value);
}

double Entry::real(std::size_t field) const {
  return to_real(*file_, line(), key_, line().fields[field]);
}

int Entry::integer(int min, int max, std::size_t field) const {
  return to_integer(*file_, line(), key_, line().fields[field], min, max);
}

bool Entry::logical() const {
  const auto value = parse_logical(text());
  if (!value) fail(fmt::format("expected True or False (T/F), got \"{}\"", text()));
  return *value;
}

std::optional<int> defaultable_integer(const InputFile& file, std::string_view key, int min) {
  const auto entry = file.find(key);
  if (!entry || entry->is_default()) return std::nullopt;
  return entry->integer(min);
}

std::optional<double> defaultable_real(const InputFile& file, std::string_view key) {
  const auto entry = file.find(key);
  if (!entry || entry->is_default()) return std::nullopt;
  return entry->real();
}

std::optional<bool> defaultable_logical(const InputFile& file, std::string_view key) {
  const auto entry = file.find(key);
  if (!entry || entry->is_default()) return std::nullopt;
  return entry->logical();
}

// Name(1) … Name(6) on six lines, e.g. DistrLoad(1..6).
template <int N>
Eigen::Matrix<double, N, 1> indexed_reals(const InputFile& file, std::string_view name, int first) {
  Eigen::Matrix<double, N, 1> values;
  for (int i = 0; i < N; ++i) values(i) = file.entry(fmt::format("{}({})", name, first + i)).real();
  return values;
}

// A file named by `entry`, relative to the directory of the file holding it; it must exist and be a
// file, not a directory.
std::filesystem::path referenced_file(const InputFile& file, const Entry& entry) {
  std::filesystem::path path = entry.text();
  if (path.is_relative()) path = file.path().parent_path() / path;
  if (const std::string reason = detail::not_a_file_reason(path); !reason.empty()) {
    entry.fail(fmt::format("file \"{}\" {} (looked for {})", entry.text(), reason == "no such file" ? "not found" : reason,
                           path.string()));
  }
  return path;
}

// Rows of an unnamed table after a given line. Blank and comment lines are skipped anywhere; up to
// a given number of column-heading lines (text not starting with a number) before the first row,
// matching the comment lines BeamDyn skips there.
class TableCursor {
 public:
  TableCursor(const InputFile& file, std::size_t after) : file_(file), index_(after) {}

  TableCursor& skip_headings(int max) {
    for (std::size_t i = index_ + 1; i < file_.size(); ++i) {
      const Line& line = file_.line(i);
      if (line.starts_with_number()) break;
      const bool heading = !line.comment && !line.blank();
      if (heading && max-- == 0) break;
      index_ = i;
    }
    return *this;
  }

  // The next row, which must hold at least `count` numbers (more fields are ignored, as Fortran
  // does); `what` names the row in messages.
  std::vector<double> row(std::size_t count, const std::string& what) {
    const Line& line = next_line(count, what);
    std::vector<double> values;
    for (std::size_t c = 0; c < count; ++c) {
      values.push_back(to_real(file_, line, what, line.fields[c]));
    }
    return values;
  }

  const Line& next_line(std::size_t count, const std::string& what) {
    do {
      if (++index_ >= file_.size()) {
        file_.fail(&file_.line(file_.size() - 1), what,
                   fmt::format("expected {} number{}, reached the end of the file", count, count == 1 ? "" : "s"));
      }
    } while (file_.line(index_).comment || file_.line(index_).blank());
    const Line& line = file_.line(index_);
    if (line.fields.size() < count) {
      file_.fail(&line, what,
                 fmt::format("expected {} number{}, found {} field{}", count, count == 1 ? "" : "s", line.fields.size(),
                             line.fields.size() == 1 ? "" : "s"));
    }
    return line;
  }

  std::size_t index() const { return index_; }

 private:
  const InputFile& file_;
  std::size_t index_;
};

template <int Rows, int Cols>
Eigen::Matrix<double, Rows, Cols> read_matrix(TableCursor& table, const std::string& what) {
  Eigen::Matrix<double, Rows, Cols> matrix;
  for (int r = 0; r < Rows; ++r) {
    const auto values = table.row(Cols, fmt::format("{} row {}", what, r + 1));
    for (int c = 0; c < Cols; ++c) matrix(r, c) = values[static_cast<std::size_t>(c)];
  }
  return matrix;
}

// ---------------------------------------------------------------------------------------------
// Driver file

std::vector<BeamDynPointLoad> read_point_loads(const InputFile& file) {
  // Older drivers have no NumPointLoads line: the primary-file section follows TipLoad(6).
  const auto count_entry = file.find("NumPointLoads");
  if (!count_entry) return {};
  const int count = count_entry->integer(0);
  TableCursor table(file, count_entry->index());
  table.skip_headings(2);  // "Non-dim blade-span eta  Fx …" and its units line
  std::vector<BeamDynPointLoad> loads;
  for (int i = 1; i <= count; ++i) {
    const auto values = table.row(7, fmt::format("point load {} (eta Fx Fy Fz Mx My Mz)", i));
    BeamDynPointLoad load;
    load.eta = values[0];
    for (int c = 0; c < 6; ++c) load.load(c) = values[static_cast<std::size_t>(c) + 1];
    loads.push_back(load);
  }
  return loads;
}

BeamDynDriver parse_driver(const InputFile& file) {
  BeamDynDriver driver;
  driver.file = file.path();
  driver.title = file.title();
  driver.dynamic_solve = file.entry("DynamicSolve").logical();
  driver.t_initial_s = file.entry("t_initial").real();
  driver.t_final_s = file.entry("t_final").real();
  driver.dt_s = file.entry("dt").real();
  driver.gravity_m_s2 = {file.entry("Gx").real(), file.entry("Gy").real(), file.entry("Gz").real()};
  driver.glb_pos_m = indexed_reals<3>(file, "GlbPos", 1);
  // GlbDCM has no name: three rows after GlbPos(3) and two comment lines.
  TableCursor dcm(file, file.entry("GlbPos(3)").index());
  driver.glb_dcm = read_matrix<3, 3>(dcm.skip_headings(2), "GlbDCM");
  driver.glb_rot_blade_t0 = file.entry("GlbRotBladeT0").logical();
  // The driver file numbers the root angular velocity as components 4..6 of RootVel.
  driver.root_angular_velocity_rad_s = indexed_reals<3>(file, "RootVel", 4);
  driver.distributed_load = indexed_reals<6>(file, "DistrLoad", 1);
  driver.tip_load = indexed_reals<6>(file, "TipLoad", 1);
  driver.point_loads = read_point_loads(file);
  driver.primary_file = referenced_file(file, file.entry("InputFile"));
  return driver;
}

// ---------------------------------------------------------------------------------------------
// Primary file

// Member rows "member number, key points" after kp_total, then the key-point table.
void read_geometry(const InputFile& file, BeamDynPrimary& primary) {
  const Entry kp_total = file.entry("kp_total");
  primary.member_total = file.entry("member_total").integer(1);
  primary.kp_total = kp_total.integer(3);
  TableCursor table(file, kp_total.index());
  int kp_sum = 0;
  for (int m = 1; m <= primary.member_total; ++m) {
    const std::string what = fmt::format("member {} (member number, key points)", m);
    const Line& line = table.next_line(2, what);
    // BeamDyn wants the members numbered 1, 2, … in order.
    if (parse_integer(line.fields[0]) != m) {
      file.fail(&line, what,
                fmt::format("expected member number {}, got \"{}\"", m, line.fields[0]));
    }
    primary.member_kp_counts.push_back(to_integer(file, line, what, line.fields[1], 2, INT_MAX));
    kp_sum += primary.member_kp_counts.back();
  }
  if (kp_sum != primary.kp_total + primary.member_total - 1) {
    file.fail(&file.line(table.index()), "member key points",
              fmt::format("expected key-point counts adding up to kp_total + member_total − 1 = {} "
                          "(members share their end points), got {}",
                          primary.kp_total + primary.member_total - 1, kp_sum));
  }
  table.skip_headings(2);  // "kp_xr kp_yr kp_zr initial_twist" and its units line
  for (int k = 1; k <= primary.kp_total; ++k) {
    const auto values =
        table.row(4, fmt::format("key point {} (kp_xr kp_yr kp_zr initial_twist)", k));
    primary.key_points.push_back({Vec3(values[0], values[1], values[2]), values[3]});
  }
}

std::optional<BeamDynPitchActuator> read_pitch_actuator(const InputFile& file) {
  const auto use = file.find("UsePitchAct");
  if (!use) return std::nullopt;
  return BeamDynPitchActuator{use->logical(), file.entry("PitchJ").real(),
                              file.entry("PitchK").real(), file.entry("PitchC").real()};
}

// The channel list after the line named OutList, ended by a line starting with END. As in
// OpenFAST's ReadOutputList only the first field of each line counts: a quoted list such as
// "RootFxr, RootFyr" or a single bare name; names are separated by blanks, commas or semicolons.
std::vector<std::string> read_out_list(const InputFile& file) {
  const Entry heading = file.entry("OutList", 0);
  std::vector<std::string> names;
  for (std::size_t i = heading.index() + 1; i < file.size(); ++i) {
    const Line& line = file.line(i);
    if (line.comment || line.blank()) continue;
    const std::string& first = line.fields.front();
    if (iequals(first.substr(0, 3), "END")) return names;
    std::string list = first;
    std::replace(list.begin(), list.end(), ';', ',');
    for (auto& name : split_fields(list)) names.push_back(std::move(name));
  }
  heading.fail("expected a line starting with END after the channel names, reached the end of "
               "the file");
}

void read_outputs(const InputFile& file, BeamDynPrimary& primary) {
  if (const auto out_fmt = file.find("OutFmt")) primary.out_fmt = out_fmt->text();
  if (const auto n_node_outs = file.find("NNodeOuts")) {
    primary.n_node_outs = n_node_outs->integer(0, 9);
    const auto count = static_cast<std::size_t>(*primary.n_node_outs);
    const Entry out_nd = file.entry("OutNd", count);
    for (std::size_t i = 0; i < count; ++i) primary.out_nd.push_back(out_nd.integer(1, INT_MAX, i));
  }
  primary.out_list = read_out_list(file);
}

BeamDynPrimary parse_primary(const InputFile& file) {
  BeamDynPrimary primary;
  primary.file = file.path();
  primary.title = file.title();
  if (const auto quasi_static = file.find("QuasiStaticInit")) {
    primary.quasi_static_init = quasi_static->logical();
  }
  primary.rhoinf = file.entry("rhoinf").real();
  primary.quadrature = file.entry("quadrature").integer(1, 2);
  primary.refine = defaultable_integer(file, "refine", 1);
  primary.n_fact = defaultable_integer(file, "n_fact", 1);
  primary.dt_beam_s = defaultable_real(file, "DTBeam");
  primary.load_retries = defaultable_integer(file, "load_retries", 0);
  primary.nr_max = defaultable_integer(file, "NRMax", 1);
  primary.stop_tol = defaultable_real(file, "stop_tol");
  primary.tngt_stf_fd = defaultable_logical(file, "tngt_stf_fd");
  primary.tngt_stf_comp = defaultable_logical(file, "tngt_stf_comp");
  primary.tngt_stf_pert = defaultable_real(file, "tngt_stf_pert");
  primary.tngt_stf_difftol = defaultable_real(file, "tngt_stf_difftol");
  read_geometry(file, primary);
  primary.order_elem = file.entry("order_elem").integer(1);
  primary.blade_file = referenced_file(file, file.entry("BldFile"));
  primary.pitch_actuator = read_pitch_actuator(file);
  read_outputs(file, primary);
  return primary;
}

// ---------------------------------------------------------------------------------------------
// Blade file

// One station: eta, then the 6×6 stiffness and mass matrices row by row. `previous` is the
// preceding station (nullptr for the first).
BeamDynStation read_station(const InputFile& file, TableCursor& table, int number,
                            const BeamDynStation* previous) {
  BeamDynStation station;
  const std::string what = fmt::format("station {} eta", number);
  const Line& line = table.next_line(1, what);
  station.eta = to_real(file, line, what, line.fields[0]);
  if (station.eta < 0.0 || station.eta > 1.0) {
    file.fail(&line, what, fmt::format("expected a number in [0, 1], got \"{}\"", line.fields[0]));
  }
  if (previous && station.eta <= previous->eta) {
    file.fail(&line, what,
              fmt::format("expected more than station {}'s eta {}, got \"{}\"", number - 1,
                          previous->eta, line.fields[0]));
  }
  station.stiffness = read_matrix<6, 6>(table, fmt::format("station {} stiffness", number));
  station.mass = read_matrix<6, 6>(table, fmt::format("station {} mass", number));
  return station;
}

BeamDynBlade parse_blade(const InputFile& file) {
  BeamDynBlade blade;
  blade.file = file.path();
  blade.title = file.title();
  blade.station_total = file.entry("station_total").integer(1);
  const Entry damp_type = file.entry("damp_type");
  blade.damp_type = damp_type.integer(0, 2);
  // mu1..mu6 have no name: one row after the "mu1 … mu6" and "(-) …" heading lines.
  TableCursor damping(file, damp_type.index());
  const auto mu = damping.skip_headings(3).row(6, "mu1..mu6");
  for (int c = 0; c < 6; ++c) blade.mu(c) = mu[static_cast<std::size_t>(c)];
  std::size_t last_damping_line = damping.index();
  // Newer files add a modal-damping section (n_modes, zeta) before the stations.
  if (const auto n_modes = file.find("n_modes")) {
    const auto count = static_cast<std::size_t>(n_modes->integer(0));
    const Entry zeta = file.entry("zeta", count);
    for (std::size_t i = 0; i < count; ++i) blade.zeta.push_back(zeta.real(i));
    last_damping_line = zeta.index();
  }
  TableCursor stations(file, last_damping_line);
  stations.skip_headings(1);  // "Distributed Properties", should it be written without dashes
  for (int s = 1; s <= blade.station_total; ++s) {
    const BeamDynStation* previous = blade.stations.empty() ? nullptr : &blade.stations.back();
    blade.stations.push_back(read_station(file, stations, s, previous));
  }
  // The stations end the file: more rows mean station_total and the table disagree.
  for (std::size_t i = stations.index() + 1; i < file.size(); ++i)
    if (!file.line(i).comment && !file.line(i).blank())
      file.fail(&file.line(i), "station_total",
                fmt::format("expected the end of the file after station {} (station_total), found more rows", blade.station_total));
  return blade;
}

}  // namespace

BeamDynPrimary read_beamdyn_primary(const std::filesystem::path& bd_primary_inp) {
  return parse_primary(InputFile(bd_primary_inp));
}

BeamDynBlade read_beamdyn_blade(const std::filesystem::path& blade_props_inp) {
  return parse_blade(InputFile(blade_props_inp));
}

BeamDynCase read_beamdyn_driver(const std::filesystem::path& bd_driver_inp) {
  BeamDynCase result;
  result.driver = parse_driver(InputFile(bd_driver_inp));
  result.primary = read_beamdyn_primary(result.driver.primary_file);
  result.blade = read_beamdyn_blade(result.primary.blade_file);
  return result;
}

}  // namespace fowtsim::io
