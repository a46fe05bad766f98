#include "decks/waves_deck.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/core/text_fields.hpp"
#include "fowtsim/io/readers.hpp"

namespace fowtsim::driver {

using io::Schema;

namespace {

constexpr const char* kRecordModule = "waves.file";
constexpr const char* kRecordChannel = "Wave1Elev";  // OpenFAST's first wave-elevation probe

[[noreturn]] void bad_record(const std::string& file, const std::string& message) {
  throw InputError({kRecordModule, std::nullopt, "waves.file",
                    "two columns (time s, elevation m; '#' starts a comment), or an OpenFAST .out/.outb or our "
                    ".h5 output with a Wave1Elev channel"},
                   fmt::format("{}: {}", file, message));
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) bad_record(path.string(), "cannot open the elevation record (check the path; relative paths are taken "
                                     "from the directory of the deck file that names it)");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Lines of `text` (1-based numbers), '\r' stripped.
template <class Visit>
void for_each_line(std::string_view text, Visit&& visit) {
  std::size_t pos = 0, number = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!visit(line, ++number)) return;
    pos = end + 1;
  }
}

// Two columns, time [s] and elevation [m], separated by blanks or a comma; '#' starts a comment;
// blank lines are skipped. "nan"/"inf" are read as such so that the waves module's check names them.
waves::ElevationRecord read_two_columns(const std::filesystem::path& path) {
  waves::ElevationRecord r;
  r.source = path.string();
  const std::string text = read_text(path);
  // A last line without a line end was cut, perhaps inside its last number: refused there.
  const std::size_t unterminated_line =
      text.empty() || text.back() == '\n' ? 0 : static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
  for_each_line(text, [&](std::string_view line, std::size_t number) {
    line = line.substr(0, line.find('#'));
    const std::vector<std::string_view> fields = split_fields(line);
    if (fields.empty()) return true;
    if (number == unterminated_line)
      bad_record(fmt::format("{}:{}", r.source, number),
                 "the file ends inside this line, without a line end: cut short? (its last number may be incomplete)");
    if (fields.size() != 2)
      bad_record(fmt::format("{}:{}", r.source, number),
                 fmt::format("expected two numbers (time s, elevation m), found {} fields", fields.size()));
    double values[2];
    for (int k = 0; k < 2; ++k) {
      const char* first = fields[k].data();
      const char* last = first + fields[k].size();
      if (*first == '+') ++first;
      const auto [end, ec] = std::from_chars(first, last, values[k]);
      if (ec != std::errc() || end != last)
        bad_record(fmt::format("{}:{}", r.source, number),
                   fmt::format("cannot read '{}' as {}", fields[k], k == 0 ? "a time [s]" : "an elevation [m]"));
    }
    r.time_s.push_back(values[0]);
    r.elevation_m.push_back(values[1]);
    r.lines.push_back(number);
    return true;
  });
  return r;
}

// Line numbers of the data rows of an OpenFAST text output: the non-blank lines after the units line
// that follows the "Time …" names line (the layout io::read_openfast_text reads). Empty if not found.
std::vector<std::size_t> openfast_row_lines(const std::filesystem::path& path) {
  const std::string text = read_text(path);
  std::vector<std::size_t> lines;
  bool after_names = false, in_data = false;
  for_each_line(text, [&](std::string_view line, std::size_t number) {
    const std::vector<std::string_view> fields = split_fields(line);
    if (in_data) {
      if (!fields.empty()) lines.push_back(number);
      return true;
    }
    if (after_names && !fields.empty() && fields.front().front() == '(') {
      in_data = true;
      return true;
    }
    std::string first = fields.empty() ? std::string() : std::string(fields.front());
    std::transform(first.begin(), first.end(), first.begin(), [](unsigned char c) { return std::tolower(c); });
    after_names = first == "time";
    return true;
  });
  return lines;
}

// OpenFAST .out / .outb or our HDF5 output (dispatch by extension, as `fowtsim compare`): the Time
// column and Wave1Elev.
waves::ElevationRecord read_output_channel(const std::filesystem::path& path, bool text) {
  const io::ChannelTable table = io::read_channels(path);
  const auto column = table.find(kRecordChannel);
  if (!column) {
    std::string names;
    for (std::size_t c = 0; c < table.names.size() && c < 12; ++c) names += (c ? ", " : "") + table.names[c];
    bad_record(path.string(), fmt::format("no channel {} (the elevation at the platform); the file has {}{}",
                                          kRecordChannel, names, table.names.size() > 12 ? ", …" : ""));
  }
  if (table.units[*column] != "m")
    bad_record(path.string(), fmt::format("channel {} is in '{}', expected m", kRecordChannel, table.units[*column]));
  waves::ElevationRecord r;
  r.source = path.string();
  r.time_s = table.time();
  r.elevation_m = table.columns[*column];
  if (text) {
    r.lines = openfast_row_lines(path);
    if (r.lines.size() != r.time_s.size()) r.lines.clear();  // unexpected layout: name samples by index
  }
  return r;
}

waves::ElevationRecord read_elevation_record(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".out") return read_output_channel(path, true);
  if (ext == ".outb" || ext == ".h5" || ext == ".hdf5") return read_output_channel(path, false);
  return read_two_columns(path);
}

// Each key once: name, schema and the WaveParams field it fills (decks/deck_section.hpp).
const DeckSection<waves::WaveParams>& waves_section() {
  using waves::WaveParams;
  static const DeckSection<WaveParams> section = [] {
    DeckSection<WaveParams> w;
    w.key("model", Schema::choice({"still", "regular", "jonswap", "pm", "elevation_series"}).default_value("still")
                       .doc("still water, one Airy wave, an irregular sea (JONSWAP / Pierson–Moskowitz), or the "
                            "sea rebuilt from a recorded elevation (elevation_series, OpenFAST WaveMod 5)"),
          &WaveParams::model, waves::parse_wave_model)
        // Read only for model elevation_series: `model` is declared above, so read_into has set it.
        .custom("file", Schema::string().optional()
                            .doc("elevation_series: η(t) at x = y = 0, relative to this deck — two columns (time s, "
                                 "elevation m; '#' comments) or the Wave1Elev channel of an OpenFAST .out/.outb or our .h5; "
                                 "uniform steps; its mean is removed, times are simulation times and the sea repeats "
                                 "with the record length N·dt (duration_s and dt_s are not used)"),
                [](const io::ValidatedDeck& d, const std::string& key, WaveParams& p) {
                  if (p.model != waves::WaveModel::elevation_series) return;
                  const std::filesystem::path file = file_beside_deck(d, key);
                  p.elevation_record =
                      located(d, [&] { return std::make_shared<const waves::ElevationRecord>(read_elevation_record(file)); });
                })
        .key("hs_m", Schema::number().at_least(0.0).default_value(0.0).doc("significant wave height Hs = 4√m0 (irregular)"),
             &WaveParams::hs_m)
        .key("tp_s", Schema::number().greater_than(0.0).optional().doc("spectral peak period (irregular)"), &WaveParams::tp_s)
        .key("gamma", Schema::number().at_least(1.0).optional().doc("JONSWAP peak shape; absent = IEC 61400-3 default"),
             &WaveParams::gamma)
        .key("rayleigh_amplitudes", Schema::boolean().default_value(false).doc("Rayleigh-random amplitudes (HydroDyn WaveNDAmp)"),
             &WaveParams::rayleigh_amplitudes)
        .key("seed", Schema::integer().at_least(0).default_value(1).doc("random seed of the phases"), &WaveParams::seed)
        .key("duration_s", Schema::number().greater_than(0.0).default_value(3600.0).doc("record length; the sea repeats with it"),
             &WaveParams::duration_s)
        .key("dt_s", Schema::number().greater_than(0.0).default_value(0.25).doc("record time step (Nyquist bounds the spectrum)"),
             &WaveParams::dt_s)
        .key("cutoff_low_hz", Schema::number().at_least(0.0).default_value(0.0)
                                  .doc("components below are dropped (irregular, elevation_series)"),
             &WaveParams::cutoff_low_hz)
        .key("cutoff_high_hz", Schema::number().greater_than(0.0).optional()
                                   .doc("components above are dropped; absent = Nyquist (of the record for elevation_series)"),
             &WaveParams::cutoff_high_hz)
        .key("height_m", Schema::number().at_least(0.0).default_value(0.0).doc("regular wave height, crest to trough"),
             &WaveParams::height_m)
        .key("period_s", Schema::number().greater_than(0.0).optional().doc("regular wave period"), &WaveParams::period_s)
        .key("phase_deg", Schema::number().default_value(0.0).doc("regular wave phase at the origin"), &WaveParams::phase_deg)
        .key("heading_deg", Schema::number().default_value(0.0).doc("propagation direction, from +x towards +y"),
             &WaveParams::heading_deg)
        .key("depth_m", Schema::number().greater_than(0.0).optional().doc("water depth; absent = deep water"), &WaveParams::depth_m)
        .key("stretching", Schema::choice({"none", "wheeler"}).default_value("none").doc("kinematics near the surface"),
             &WaveParams::stretching, waves::parse_stretching)
        .key("water_density_kg_m3", Schema::number().greater_than(0.0).default_value(1025.0).doc("water density"),
             &WaveParams::water_density_kg_m3)
        .key("gravity_m_s2", Schema::number().greater_than(0.0).default_value(9.80665).doc("gravity"), &WaveParams::gravity_m_s2)
        .key("elevation_probes_m", Schema::sequence(number_vector(2, "x, y")).min_items(1).max_items(9).optional()
                                       .doc("(x, y) of Wave1Elev … Wave9Elev; absent = the origin"),
             &WaveParams::elevation_probes_m);
    return w;
  }();
  return section;
}

}  // namespace

Schema waves_schema() { return waves_section().schema(); }

waves::WaveParams wave_params(const io::ValidatedDeck& d) {
  waves::WaveParams p = waves_section().read(d);
  located(d, [&] { waves::validate(p); });
  return p;
}

}  // namespace fowtsim::driver
