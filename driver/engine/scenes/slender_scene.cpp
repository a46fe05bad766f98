#include "scenes/slender_scene.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "decks/slender_deck.hpp"
#include "run/channel_selection.hpp"
#include "run/output_set.hpp"
#include "scenes/scene_runner.hpp"
#include "scenes/slender_analysis.hpp"
#include "scenes/slender_time_domain.hpp"

namespace fowtsim::driver {
namespace {

// The CSV's columns after x and D, per domain: name and the profile it holds.
struct ProfileColumn {
  const char* name;
  const VecX SlenderProfiles::*values;
};
constexpr ProfileColumn kColumns[] = {
    {"displacement_m", &SlenderProfiles::displacement_m},
    {"moment_ei_N_m", &SlenderProfiles::moment_elastic_N_m},
    {"moment_ir_N_m", &SlenderProfiles::moment_inertia_relief_N_m},
    {"stress_ei_Pa", &SlenderProfiles::stress_elastic_Pa},
    {"stress_ir_Pa", &SlenderProfiles::stress_inertia_relief_Pa},
};

// The profile table: <output>.amplitude.csv (regular wave) or <output>.rms.csv (JONSWAP).
std::string profiles_suffix(bool regular) { return regular ? ".amplitude.csv" : ".rms.csv"; }

// Its bytes: x, D, then the FD and the TD profiles that were solved.
std::string profiles_csv(const SlenderResults& r) {
  const std::vector<std::pair<const char*, const SlenderProfiles*>> domains = {
      {"fd", r.frequency_domain ? &*r.frequency_domain : nullptr}, {"td", r.time_domain ? &*r.time_domain : nullptr}};
  std::string csv = "x_m,outer_diameter_m";
  for (const auto& [prefix, p] : domains)
    if (p)
      for (const ProfileColumn& c : kColumns) csv += fmt::format(",{}_{}", prefix, c.name);
  csv += '\n';
  const slender::StripTable& s = r.model.strips;
  for (Eigen::Index i = 0; i < s.x_m.size(); ++i) {
    csv += fmt::format("{:.10g},{:.10g}", s.x_m(i), s.diameter_m(i));
    for (const auto& [prefix, p] : domains)
      if (p)
        for (const ProfileColumn& c : kColumns) csv += fmt::format(",{:.10g}", (p->*c.values)(i));
    csv += '\n';
  }
  return csv;
}

// What was solved: the model, its modes and the frequency domain's drag linearisation.
std::string solution(const SlenderResults& r) {
  const slender::Modes& m = r.modes;
  std::string periods;
  for (Eigen::Index k = 0; k < std::min<Eigen::Index>(m.omega_rad_s.size(), 6); ++k)
    periods += fmt::format(" {:.4g}", 2 * std::numbers::pi / m.omega_rad_s(k));
  std::string line = fmt::format("{} strips, {} shapes, {} modes; periods [s]:{}", r.model.strips.x_m.size(), r.model.phi.cols(),
                                 m.omega_rad_s.size(), periods);
  if (r.frequency_domain) line += fmt::format("; drag linearised in {} iterations", r.drag_iterations);
  return line;
}

// Largest value along the body, FD and TD, per profile: the summary's table.
std::vector<std::string> peaks(const SlenderResults& r, bool regular) {
  std::vector<std::string> lines;
  lines.push_back(fmt::format("largest {} along the body:  {:>12} {:>12}", regular ? "amplitude" : "RMS", "FD", "TD"));
  for (const ProfileColumn& c : kColumns) {
    const auto peak = [&](const std::optional<SlenderProfiles>& p) {
      return p ? fmt::format("{:>12.5g}", ((*p).*c.values).maxCoeff()) : fmt::format("{:>12}", "-");
    };
    lines.push_back(fmt::format("  {:<16} {} {}", c.name, peak(r.frequency_domain), peak(r.time_domain)));
  }
  return lines;
}

// Time-series channels: the wave elevation, then per station the displacement, both moments and
// both stresses at the strip holding it.
struct Station {
  Eigen::Index strip;
};
// The frequency domain's response spectra at the stations, <output>.spectra.csv (JONSWAP sea):
// ω [rad/s], then per station S of the displacement [m²·s/rad] and of the inertia-relief moment
// [kN²·m²·s/rad], one-sided in ω (the time-series channels' units squared per rad/s).
WholeFile spectra_csv(const SlenderSpectra& s, const std::vector<Station>& stations) {
  std::string csv = "omega_rad_s";
  for (std::size_t k = 0; k < stations.size(); ++k) csv += fmt::format(",Stn{0}Disp,Stn{0}MomIR", k + 1);
  csv += '\n';
  for (Eigen::Index j = 0; j < s.omega_rad_s.size(); ++j) {
    csv += fmt::format("{:.10g}", s.omega_rad_s(j));
    for (const Station& st : stations)
      csv += fmt::format(",{:.10g},{:.10g}", s.displacement_m2_s(st.strip, j), s.moment_inertia_relief_N2m2_s(st.strip, j) / 1e6);
    csv += '\n';
  }
  return {".spectra.csv", std::move(csv)};
}

std::vector<ChannelInfo> channels(const SlenderResults& r, const std::vector<Station>& stations) {
  std::vector<ChannelInfo> all = {{"WaveElev", "m", "wave elevation at the body", "slender"}};
  for (std::size_t k = 0; k < stations.size(); ++k) {
    const std::string n = fmt::format("Stn{}", k + 1);
    const std::string at = fmt::format("at station {} (strip midpoint x = {:.6g} m from the bottom end)", k + 1,
                                       r.model.strips.x_m(stations[k].strip));
    all.push_back({n + "Disp", "m", "transverse displacement " + at, "slender"});
    all.push_back({n + "MomEI", "kN-m", "bending moment EI v'' " + at, "slender"});
    all.push_back({n + "MomIR", "kN-m", "bending moment by inertia relief " + at, "slender"});
    all.push_back({n + "StrEI", "MPa", "bending stress EI v''/Z " + at, "slender"});
    all.push_back({n + "StrIR", "MPa", "bending stress (inertia relief)/Z " + at, "slender"});
  }
  return all;
}

std::vector<Station> stations_of(const slender::Model& model, const std::vector<double>& x_m) {
  std::vector<Station> out;
  const VecX& x = model.strips.x_m;
  const VecX& dx = model.strips.dx_m;
  for (double xs : x_m) {
    Eigen::Index i = 0;
    while (i + 1 < x.size() && xs > x(i) + 0.5 * dx(i)) ++i;
    out.push_back({i});
  }
  return out;
}

}  // namespace

io::Schema slender_scene_schema() {
  std::vector<io::SchemaField> fields = {
      {"simulation", simulation_schema("time step of the time domain (RK4)").doc("time span and step of the time domain")},
      {"output", output_schema().optional().doc("time-series format, decimation and channels (WaveElev, Stn1Disp, Stn1MomEI, …)")},
  };
  for (io::SchemaField& f : slender_deck_fields()) fields.push_back(std::move(f));
  return io::Schema::map(std::move(fields));
}

SlenderCase read_slender_case(const io::ValidatedDeck& deck, std::optional<double> t_max_override) {
  const SimulationKeys simulation = simulation_keys(deck);
  const double t_max = t_max_override.value_or(simulation.t_max_s);
  return {read_slender_deck(deck, simulation.dt_s, t_max), simulation.dt_s, t_max};
}

SlenderCase read_slender_case(const std::filesystem::path& path, const std::vector<std::string>& settings) {
  return read_slender_case(io::read_deck(slender_scene_schema(), path, settings));
}

RunReport run_slender_scene(const RunRequest& request, const ProgressCallback& progress) {
  const io::ValidatedDeck deck = io::read_deck(slender_scene_schema(), request.deck_path, request.deck_settings);
  const SlenderCase c = read_slender_case(deck, request.t_max_s);
  const SlenderDeck& d = c.deck;
  const io::ValidatedDeck section = deck.section("slender");
  SlenderResults r = located(section, [&] { return solve_frequency_domain(d); });
  const std::vector<Station> stations = stations_of(r.model, d.analysis.stations_m);
  std::vector<WholeFile> tables;
  if (r.spectra) tables.push_back(spectra_csv(*r.spectra, stations));

  RunReport report;
  if (d.analysis.time_domain) {
    // The module stepped by the run loop (scenes/slender_time_domain.hpp): its state is all the
    // scene changes, so a checkpoint writes it and a restart continues bit-identically.
    const auto time_domain = located(section, [&] {
      return std::make_unique<SlenderTimeDomain>(d, r.model, r.modes, c.dt_s, std::lround(c.t_max_s / c.dt_s));
    });
    SlenderTimeState state = time_domain->make_state();
    const std::vector<ChannelInfo> all = channels(r, stations);
    const std::vector<std::size_t> picked = select_channels(deck, all, "slender");
    FixedStepScene scene;
    for (std::size_t i : picked) scene.written.push_back(all[i]);
    scene.metadata.extra = {{"scene", "slender"}};
    if (!d.sea.regular) scene.metadata.seeds = {d.sea.seed};
    for (WholeFile& t : tables) scene.whole_files.push_back(std::move(t));
    std::vector<double> values(all.size());
    scene.step = [&](double, double) { time_domain->step(state); };
    scene.row = [&](double, std::span<double> row) {
      const slender::SlenderBody::Output& out = time_domain->outputs(state);
      values[0] = time_domain->wave_elevation_m(state);
      for (std::size_t k = 0; k < stations.size(); ++k) {
        const Eigen::Index i = stations[k].strip;
        const double Z = r.model.strips.section_modulus_m3(i);
        const double ei = out.moment_elastic_N_m(i), ir = out.moment_inertia_relief_N_m(i);
        const double station[5] = {out.displacement_m(i), ei / 1e3, ir / 1e3, ei / Z / 1e6, ir / Z / 1e6};
        std::copy(station, station + 5, values.begin() + 1 + 5 * static_cast<std::ptrdiff_t>(k));
      }
      for (std::size_t k = 0; k < picked.size(); ++k) row[k] = values[picked[k]];
    };
    scene.save = [&](CheckpointWriter& w) { w.io(state); };
    scene.load = [&](CheckpointReader& reader) { reader.io(state); };
    // The profiles hold the TD statistics over the whole window: written once the last step is
    // taken, never from part of the run.
    scene.end_file_suffixes = {profiles_suffix(d.sea.regular)};
    scene.end_files = [&] {
      r.time_domain = time_domain->profiles(state);
      return std::vector<std::string>{profiles_csv(r)};
    };
    report = run_fixed_steps(request, deck, std::move(scene), progress);
    report.coupling = "none (one body)";
    report.results.push_back(solution(r));
  } else {
    // No time series: the tables alone, still under the run's lock and written whole.
    tables.insert(tables.begin(), WholeFile{profiles_suffix(d.sea.regular), profiles_csv(r)});
    OutputSet outputs(output_plan(request, deck).base, "none", std::move(tables));
    outputs.begin({}, {});
    outputs.finish({0.0, "completed", 0.0, {}});
    report.outputs = outputs.paths();
    report.warnings = outputs.notes();
    report.time_loop = false;
    report.coupling = "frequency domain: " + solution(r);
  }
  for (std::string& line : peaks(r, d.sea.regular)) report.results.push_back(std::move(line));
  return report;
}

}  // namespace fowtsim::driver
