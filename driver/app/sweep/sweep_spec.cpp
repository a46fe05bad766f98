#include "sweep/sweep_spec.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include <fmt/format.h>

#include "sweep/iec_presets.hpp"

namespace fowtsim::driver::sweep {

using io::Schema;

Schema sweep_spec_schema() {
  const Schema numbers = Schema::sequence(Schema::number()).min_items(1);
  const Schema sweep = Schema::map({
      {"name", Schema::string().doc("sweep name: case seeds and the default output folder derive from it")},
      {"base_deck", Schema::string().doc("scene deck every case includes, relative to this spec")},
      {"output_dir", Schema::string().optional().doc("decks, outputs, logs and the load table, relative to the working folder; absent = runs/sweeps/<name>")},
      {"transient_s", Schema::number().unit("s").at_least(0.0).default_value(120.0).doc("start discarded from the statistics")},
      {"analysis_s", Schema::number().unit("s").greater_than(0.0).default_value(600.0).doc("analysed length after the transient")},
      {"trim", Schema::map({
                   {"duration_s", Schema::number().unit("s").greater_than(0.0).at_most(3600.0).default_value(400.0)
                                      .doc("length of the steady run per wind speed")},
                   {"average_s", Schema::number().unit("s").greater_than(0.0).default_value(150.0)
                                     .doc("its averaged end: at least one surge period of a floating platform")},
               }).optional().doc("start each operating case at the steady operating point of its wind speed (a steady run per speed)")},
  });
  const Schema turbine = Schema::map({
      {"wind_class", Schema::integer().at_least(1).at_most(3).default_value(1).doc("IEC 61400-1 class I/II/III: V_ref 50/42.5/37.5 m/s")},
      {"turbulence_class", Schema::choice({"A", "B", "C"}).default_value("B").doc("IEC turbulence category: I_ref 0.16/0.14/0.12")},
      {"hub_height_m", Schema::number().unit("m").greater_than(0.0).default_value(90.0).doc("hub height above the still-water level")},
      {"rotor_diameter_m", Schema::number().unit("m").greater_than(0.0).optional().doc("rotor diameter D of the gust and shear events")},
      {"cut_in_m_s", Schema::number().unit("m_s").greater_than(0.0).optional().doc("V_in at hub height: the presets' default speeds")},
      {"rated_m_s", Schema::number().unit("m_s").greater_than(0.0).optional().doc("V_r at hub height: the presets' default speeds")},
      {"cut_out_m_s", Schema::number().unit("m_s").greater_than(0.0).optional().doc("V_out at hub height: the presets' default speeds")},
  });
  const Schema table_row = Schema::map({
      {"wind_speed_m_s", Schema::number().unit("m_s").at_least(0.0).doc("hub-height mean wind speed")},
      {"hs_m", Schema::number().unit("m").at_least(0.0).doc("significant wave height")},
      {"tp_s", Schema::number().unit("s").greater_than(0.0).doc("peak period")},
  });
  const Schema relation = Schema::map({
      {"hs_coefficients", numbers.doc("Hs = c0 + c1 V + c2 V² + … [m], V the hub-height mean wind speed in m/s")},
      {"tp_factor", Schema::number().greater_than(0.0).doc("Tp = tp_factor √(Hs/g); IEC 61400-3 bounds it by 11.1 … 14.3")},
  });
  const Schema sea_state = Schema::map({
      {"hs_m", Schema::number().unit("m").at_least(0.0).optional().doc("one Hs for every case (with tp_s)")},
      {"tp_s", Schema::number().unit("s").greater_than(0.0).optional().doc("one Tp for every case (with hs_m)")},
      {"table", Schema::sequence(table_row).min_items(2).optional().doc("Hs, Tp by wind speed, interpolated linearly")},
      {"relation", relation.optional().doc("the normal-sea relation Hs(V), Tp(Hs) of the site")},
  });
  const Schema group = Schema::map({
      {"name", Schema::string().doc("case-name prefix, e.g. dlc12")},
      {"preset", Schema::choice(preset_names()).optional()
                     .doc("IEC 61400-1/-3 design load case: wind, events, parked rotor, factors, γ_f (driver/app/sweep/README.md)")},
      {"wind_speeds_m_s", numbers.optional().doc("hub-height mean wind speeds; absent = the preset's (from the turbine's speeds) or the base deck's")},
      {"seeds", Schema::integer().at_least(1).optional().doc("realisations per factor combination (presets: 6, else 1)")},
      {"sea_state", sea_state.optional().doc("waves per case; absent = the base deck's")},
      {"yaw_misalignment_deg", numbers.optional().doc("wind direction relative to the rotor axis (wind.direction_deg)")},
      {"wave_heading_deg", numbers.optional().doc("wave propagation direction (waves.heading_deg)")},
      {"set", Schema::map_of(Schema::sequence(Schema::string()).min_items(1)).optional()
                  .doc("any deck key by its path, one value per case: {controller.min_pitch_rad: [0, 0.05]}")},
      {"combine", Schema::choice({"cross", "zip"}).default_value("cross")
                      .doc("cross: every combination; zip: the i-th values together (single values shared)")},
      {"fatigue", Schema::boolean().optional().doc("enters the lifetime DEL (default: the preset's analysis F; false without a preset)")},
      {"ultimate", Schema::boolean().optional().doc("enters the ultimate-load table (default: the preset's analysis U; true without a preset)")},
      {"partial_safety_factor", Schema::number().at_least(1.0).at_most(3.0).optional()
                                    .doc("γ_f of the group's ultimate loads (default: the preset's, N 1.35 / A 1.1; 1.35 without a preset)")},
      {"fatigue_time_fraction", Schema::number().greater_than(0.0).at_most(1.0).default_value(1.0)
                                    .doc("share of the design life the group's conditions hold (e.g. availability 0.95 for dlc1.2, 0.05 for dlc6.4)")},
      {"events_per_year", numbers.optional()
                              .doc("event-weighted fatigue (start-ups, shutdowns, faults): occurrences a year, one value or one per wind speed")},
  });
  const Schema fatigue_channel = Schema::map({
      {"channel", Schema::string().doc("output channel")},
      {"wohler_exponent", Schema::number().greater_than(0.0).doc("S-N slope m (3-5 steel, ~10 composite)")},
  });
  const Schema load_table = Schema::map({
      {"channels", Schema::sequence(Schema::string()).min_items(1).optional()
                       .doc("channels with min, max, mean, std; absent = GenPwr, RotSpeed, BldPitch1, PtfmPitch, TwrBsMyt")},
      {"fatigue", Schema::sequence(fatigue_channel).min_items(1).optional().doc("channels with short-term and lifetime DELs")},
      {"equivalent_frequency_hz", Schema::number().unit("hz").greater_than(0.0).default_value(1.0).doc("f_eq of the DELs")},
      {"design_life_years", Schema::number().greater_than(0.0).default_value(20.0).doc("design life of the lifetime damage")},
      {"weibull_shape", Schema::number().greater_than(0.0).default_value(2.0).doc("k of the wind-speed distribution (2 = Rayleigh)")},
      {"mean_wind_speed_m_s", Schema::number().unit("m_s").greater_than(0.0).optional()
                                  .doc("V_ave at hub height; absent = 0.2 V_ref of turbine.wind_class (IEC 61400-1)")},
      {"bin_width_m_s", Schema::number().unit("m_s").greater_than(0.0).optional()
                            .doc("wind-speed bin of each fatigue speed; absent = their smallest spacing (2 with one speed)")},
  });
  const Schema slurm = Schema::map({
      {"partition", Schema::string().optional().doc("--partition (the command line's --partition wins)")},
      {"time", Schema::string().optional().doc("--time per array task, Slurm's format, e.g. 02:00:00 (--time wins)")},
      {"account", Schema::string().optional().doc("--account charged for the job (--account wins)")},
      {"qos", Schema::string().optional().doc("--qos (--qos wins)")},
      {"mem", Schema::string().optional().doc("--mem per array task, e.g. 2G (--mem wins)")},
      {"sbatch_lines", Schema::sequence(Schema::string()).optional()
                           .doc("more sbatch options, each written as '#SBATCH <line>', e.g. --constraint=avx2")},
      {"setup_lines", Schema::sequence(Schema::string()).optional()
                          .doc("shell lines each array task runs before its cases: module load …, export …")},
  });
  return Schema::map({
      {"sweep", sweep.doc("what is swept and where it goes")},
      {"slurm", slurm.optional().doc("how --slurm submits the job array (cluster account, QOS, memory, set-up)")},
      {"turbine", turbine.optional().doc("IEC classes of the turbine (presets, wind distribution); absent = I B, 90 m")},
      {"load_cases", Schema::sequence(group).min_items(1).doc("load-case groups, expanded in order")},
      {"load_table", load_table.optional().doc("statistics and DELs of the load table")},
  });
}

namespace {

// Case and sweep names become file names and Slurm job names.
bool is_file_name_safe(const std::string& text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '-' || c == '.';
  }) && text.front() != '.';
}

class Issues {
 public:
  void add(const io::ValidatedDeck& deck, const std::string& path, std::string found, std::string expected,
           std::string hint = "") {
    issues_.push_back({io::DeckIssueKind::out_of_range, deck.location(path), join(deck.path(), path), std::move(found),
                       std::move(expected), std::move(hint)});
  }
  void missing(const io::ValidatedDeck& deck, const std::string& key, std::string expected) {
    issues_.push_back({io::DeckIssueKind::missing_key, deck.location(""), join(deck.path(), key), "", std::move(expected), ""});
  }
  void throw_if_any() {
    if (!issues_.empty()) throw io::DeckError(std::move(issues_));
  }

 private:
  static std::string join(const std::string& a, const std::string& b) {
    return a.empty() ? b : b.empty() ? a : b.front() == '[' ? a + b : a + "." + b;
  }
  std::vector<io::DeckIssue> issues_;
};

std::vector<double> optional_numbers(const io::ValidatedDeck& d, const char* key) {
  return d.has(key) ? d.numbers(key) : std::vector<double>{};
}

SeaStateSpec read_sea_state(const io::ValidatedDeck& group, const std::vector<double>& speeds, Issues& issues) {
  SeaStateSpec sea;
  if (!group.has("sea_state")) return sea;
  const io::ValidatedDeck s = group.section("sea_state");
  sea.location = s.location("");
  const bool fixed = s.has("hs_m") || s.has("tp_s");
  const int kinds = int(fixed) + int(s.has("table")) + int(s.has("relation"));
  if (kinds != 1) {
    issues.add(s, "", fmt::format("{} ways of giving the sea state", kinds), "exactly one of hs_m + tp_s, table, relation");
    return sea;
  }
  if (fixed) {
    if (!s.has("hs_m") || !s.has("tp_s")) {
      issues.missing(s, s.has("hs_m") ? "tp_s" : "hs_m", "hs_m and tp_s together");
      return sea;
    }
    sea.kind = SeaStateSpec::Kind::fixed;
    sea.hs_m = s.number("hs_m");
    sea.tp_s = s.number("tp_s");
  } else if (s.has("table")) {
    sea.kind = SeaStateSpec::Kind::table;
    for (std::size_t i = 0; i < s.size("table"); ++i) {
      const io::ValidatedDeck row = s.section(fmt::format("table[{}]", i));
      sea.table.push_back({row.number("wind_speed_m_s"), row.number("hs_m"), row.number("tp_s")});
      if (i > 0 && sea.table[i].wind_speed_m_s <= sea.table[i - 1].wind_speed_m_s)
        issues.add(row, "wind_speed_m_s", fmt::format("{}", sea.table[i].wind_speed_m_s),
                   fmt::format("a wind speed above the previous row's {} m/s", sea.table[i - 1].wind_speed_m_s));
    }
    // Interpolated, never extrapolated: a sea state outside the table is the site data's to give.
    for (std::size_t i = 0; i < speeds.size(); ++i) {
      if (speeds[i] < sea.table.front().wind_speed_m_s || speeds[i] > sea.table.back().wind_speed_m_s)
        issues.add(group, fmt::format("wind_speeds_m_s[{}]", i), fmt::format("{} m/s", speeds[i]),
                   fmt::format("a speed inside the sea-state table ({} … {} m/s)", sea.table.front().wind_speed_m_s,
                               sea.table.back().wind_speed_m_s),
                   "add table rows that cover it");
    }
  } else {
    sea.kind = SeaStateSpec::Kind::relation;
    sea.hs_coefficients = s.numbers("relation.hs_coefficients");
    sea.tp_factor = s.number("relation.tp_factor");
  }
  return sea;
}

LoadCaseGroup read_group(const io::ValidatedDeck& g, const io::DeckNode& raw, const TurbineClass& turbine, Issues& issues) {
  LoadCaseGroup group;
  group.location = g.location("");
  group.name = g.string("name");
  if (!is_file_name_safe(group.name))
    issues.add(g, "name", group.name, "a name of letters, digits, _ - . (it starts every case file name)");
  group.preset = g.has("preset") ? g.string("preset") : "";
  group.wind_speeds_m_s = optional_numbers(g, "wind_speeds_m_s");
  group.yaw_misalignment_deg = optional_numbers(g, "yaw_misalignment_deg");
  group.wave_heading_deg = optional_numbers(g, "wave_heading_deg");
  group.combine = g.string("combine") == "zip" ? Combination::zip : Combination::cross;
  const PresetInfo* preset = group.preset.empty() ? nullptr : &preset_info(group.preset);
  group.seeds = static_cast<int>(g.has("seeds") ? g.integer("seeds") : preset != nullptr ? preset->seeds : 1);
  group.fatigue = g.has("fatigue") ? g.boolean("fatigue") : preset != nullptr && preset->fatigue;
  group.ultimate = g.has("ultimate") ? g.boolean("ultimate") : preset == nullptr || preset->ultimate;
  group.partial_safety_factor = g.has("partial_safety_factor") ? g.number("partial_safety_factor")
                                : preset != nullptr && preset->ultimate ? preset->partial_safety_factor
                                                                        : 1.35;
  group.fatigue_time_fraction = g.number("fatigue_time_fraction");
  group.events_per_year = optional_numbers(g, "events_per_year");
  if (!group.events_per_year.empty() && group.events_per_year.size() != 1 && group.events_per_year.size() != group.wind_speeds_m_s.size())
    issues.add(g, "events_per_year", fmt::format("{} values", group.events_per_year.size()),
               fmt::format("one value, or one per listed wind speed ({})", group.wind_speeds_m_s.size()));
  for (std::size_t i = 0; i < group.events_per_year.size(); ++i)
    if (!(group.events_per_year[i] >= 0.0))
      issues.add(g, fmt::format("events_per_year[{}]", i), fmt::format("{}", group.events_per_year[i]), "occurrences a year, ≥ 0");
  group.sea_state = read_sea_state(g, group.wind_speeds_m_s, issues);

  // `set` keys are deck paths with dots, which ValidatedDeck paths cannot name: read the node.
  if (const io::DeckNode* set = raw.find("set")) {
    for (const io::DeckEntry& entry : set->entries) {
      KeyFactor factor{entry.key, {}, entry.key_location};
      for (const io::DeckNode& item : entry.value.items) factor.values.push_back(item.scalar);
      group.set.push_back(std::move(factor));
    }
  }

  // Parked in the extreme wind: the preset sets the speed (V_50 or V_1) and the sea is one extreme sea state.
  const bool extreme_wind = preset != nullptr && preset->wind.starts_with("turbulent EWM");
  if (extreme_wind && !group.wind_speeds_m_s.empty())
    issues.add(g, "wind_speeds_m_s", "wind speeds", fmt::format("none: {} blows the extreme wind model's speed ({})", group.preset, preset->wind));
  // A preset's default speeds derive from the turbine's V_in, V_r, V_out; its gusts and shears from D.
  const bool turbine_speeds = turbine.cut_in_m_s && turbine.rated_m_s && turbine.cut_out_m_s;
  if (preset != nullptr && !extreme_wind && group.preset != "dlc6.4" && group.wind_speeds_m_s.empty() && !turbine_speeds)
    issues.missing(g, "wind_speeds_m_s",
                   fmt::format("the wind speeds of {}, or turbine.cut_in_m_s, rated_m_s and cut_out_m_s for its default ones", group.preset));
  const bool wind_event = preset != nullptr && (preset->wind.find("EOG") != std::string_view::npos ||
                                                preset->wind.find("EDC") != std::string_view::npos ||
                                                preset->wind.find("ECD") != std::string_view::npos ||
                                                preset->wind.find("EWS") != std::string_view::npos);
  if (wind_event && !turbine.rotor_diameter_m)
    issues.add(g, "preset", group.preset, "a spec whose turbine section gives rotor_diameter_m (the size of its gust or shear)");
  if (group.preset == "dlc6.4" && group.wind_speeds_m_s.empty())
    issues.missing(g, "wind_speeds_m_s", "the idling wind speeds of dlc6.4 (below 0.7 V_ref)");
  if (preset != nullptr && preset->events_per_year_needed() && group.events_per_year.empty())
    issues.missing(g, "events_per_year", fmt::format("how often a year {} happens ({}): it weights the event's damage", group.preset, preset->other));
  if (preset != nullptr && group.sea_state.kind == SeaStateSpec::Kind::from_base_deck && !g.has("sea_state"))
    issues.missing(g, "sea_state", std::string(preset_sea_state_kind(group.preset)) + " (hs_m + tp_s, table or relation)");
  if (extreme_wind && group.sea_state.kind != SeaStateSpec::Kind::from_base_deck && group.sea_state.kind != SeaStateSpec::Kind::fixed)
    issues.add(g, "sea_state", "a sea state by wind speed", std::string("hs_m + tp_s of ") + std::string(preset_sea_state_kind(group.preset)));

  if (group.combine == Combination::zip) {
    std::size_t length = 1;
    std::string first;
    auto check = [&](std::size_t n, const std::string& path) {
      if (n <= 1) return;
      if (length == 1) {
        length = n;
        first = path;
      } else if (n != length) {
        issues.add(g, path, fmt::format("{} values", n),
                   fmt::format("{} values (as {}) or one, to zip", length, first));
      }
    };
    check(group.wind_speeds_m_s.size(), "wind_speeds_m_s");
    check(group.yaw_misalignment_deg.size(), "yaw_misalignment_deg");
    check(group.wave_heading_deg.size(), "wave_heading_deg");
    for (const KeyFactor& f : group.set) check(f.values.size(), "set");
  }
  return group;
}

LoadTableSpec read_load_table(const io::ValidatedDeck& root) {
  LoadTableSpec t;
  t.channels = {"GenPwr", "RotSpeed", "BldPitch1", "PtfmPitch", "TwrBsMyt"};
  if (!root.has("load_table")) return t;
  const io::ValidatedDeck d = root.section("load_table");
  if (d.has("channels")) t.channels = d.strings("channels");
  if (d.has("fatigue")) {
    for (std::size_t i = 0; i < d.size("fatigue"); ++i) {
      const io::ValidatedDeck f = d.section(fmt::format("fatigue[{}]", i));
      t.fatigue.push_back({f.string("channel"), f.number("wohler_exponent")});
    }
  }
  t.equivalent_frequency_hz = d.number("equivalent_frequency_hz");
  t.design_life_years = d.number("design_life_years");
  t.weibull_shape = d.number("weibull_shape");
  if (d.has("mean_wind_speed_m_s")) t.mean_wind_speed_m_s = d.number("mean_wind_speed_m_s");
  if (d.has("bin_width_m_s")) t.bin_width_m_s = d.number("bin_width_m_s");
  return t;
}

SlurmOptions read_slurm_options(const io::ValidatedDeck& root, Issues& issues) {
  SlurmOptions o;
  if (!root.has("slurm")) return o;
  const io::ValidatedDeck d = root.section("slurm");
  auto text = [&](const char* key) { return d.has(key) ? d.string(key) : std::string(); };
  o.partition = text("partition");
  o.time_limit = text("time");
  o.account = text("account");
  o.qos = text("qos");
  o.memory = text("mem");
  if (d.has("sbatch_lines")) o.sbatch_lines = d.strings("sbatch_lines");
  if (d.has("setup_lines")) o.setup_lines = d.strings("setup_lines");
  // One line each: a line break would end the #SBATCH block or split a shell command unseen.
  for (const char* key : {"partition", "time", "account", "qos", "mem"})
    if (text(key).find_first_of("\n\r") != std::string::npos) issues.add(d, key, "a line break", "a value on one line");
  for (std::size_t i = 0; i < o.sbatch_lines.size(); ++i) {
    const std::string& line = o.sbatch_lines[i];
    if (line.empty() || line.front() != '-' || line.find_first_of("\n\r") != std::string::npos)
      issues.add(d, fmt::format("sbatch_lines[{}]", i), line, "one sbatch option on one line, starting with - (e.g. --constraint=avx2)");
  }
  for (std::size_t i = 0; i < o.setup_lines.size(); ++i)
    if (o.setup_lines[i].find_first_of("\n\r") != std::string::npos)
      issues.add(d, fmt::format("setup_lines[{}]", i), "a line break", "one shell line per item");
  return o;
}

}  // namespace

SweepSpec read_sweep_spec(const std::filesystem::path& spec_path) {
  io::LoadedDeck loaded = io::load_deck(spec_path);
  const io::DeckNode raw_root = loaded.root;
  const io::ValidatedDeck deck = io::validate(sweep_spec_schema(), std::move(loaded));
  Issues issues;

  SweepSpec spec;
  spec.spec_path = spec_path;
  spec.hash = deck.hash();
  const io::ValidatedDeck s = deck.section("sweep");
  spec.name = s.string("name");
  if (!is_file_name_safe(spec.name))
    issues.add(s, "name", spec.name, "a name of letters, digits, _ - . (it names the output folder and the Slurm job)");
  const std::filesystem::path base = s.string("base_deck");
  spec.base_deck = base.is_absolute() ? base : std::filesystem::path(s.location("base_deck").file).parent_path() / base;
  if (!std::filesystem::is_regular_file(spec.base_deck))
    issues.add(s, "base_deck", spec.base_deck.string(), "a readable scene deck", "the path is relative to the spec file");
  spec.output_dir = s.has("output_dir") ? std::filesystem::path(s.string("output_dir"))
                                        : std::filesystem::path("runs") / "sweeps" / spec.name;
  spec.transient_s = s.number("transient_s");
  spec.analysis_s = s.number("analysis_s");
  if (s.has("trim")) {
    spec.trim = TrimSpec{s.number("trim.duration_s"), s.number("trim.average_s")};
    if (spec.trim->average_s > spec.trim->duration_s)
      issues.add(s, "trim.average_s", fmt::format("{} s", spec.trim->average_s),
                 fmt::format("at most trim.duration_s ({} s)", spec.trim->duration_s));
  }
  if (deck.has("turbine")) {
    const io::ValidatedDeck t = deck.section("turbine");
    spec.turbine.wind_class = static_cast<int>(t.integer("wind_class"));
    spec.turbine.turbulence_class = t.string("turbulence_class");
    spec.turbine.hub_height_m = t.number("hub_height_m");
    auto optional = [&](const char* key) { return t.has(key) ? std::optional(t.number(key)) : std::nullopt; };
    spec.turbine.rotor_diameter_m = optional("rotor_diameter_m");
    spec.turbine.cut_in_m_s = optional("cut_in_m_s");
    spec.turbine.rated_m_s = optional("rated_m_s");
    spec.turbine.cut_out_m_s = optional("cut_out_m_s");
  } else {
    spec.turbine.turbulence_class = "B";
  }

  std::set<std::string> names;
  const io::DeckNode& raw_groups = *raw_root.find("load_cases");
  for (std::size_t i = 0; i < deck.size("load_cases"); ++i) {
    const io::ValidatedDeck g = deck.section(fmt::format("load_cases[{}]", i));
    spec.groups.push_back(read_group(g, raw_groups.items[i], spec.turbine, issues));
    if (!names.insert(spec.groups.back().name).second)
      issues.add(g, "name", spec.groups.back().name, "a name no other load-case group has");
  }
  spec.load_table = read_load_table(deck);
  spec.slurm = read_slurm_options(deck, issues);
  issues.throw_if_any();
  return spec;
}

}  // namespace fowtsim::driver::sweep
