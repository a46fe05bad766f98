#include "verify/verify_turbine.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "verify/verify_cases.hpp"
#include "compare/window_statistics.hpp"
#include "fowtsim/io/readers.hpp"
#include "run/run_scene.hpp"

namespace fowtsim::driver {

std::filesystem::path source_input(const std::string& relative);  // verify_cases.cpp

namespace {

std::filesystem::path input(const std::string& relative) { return std::filesystem::absolute(source_input(relative)); }

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "fowtsim-verify" / name;
  std::filesystem::create_directories(dir);
  return dir;
}

io::ChannelTable run_deck(const std::filesystem::path& deck, const std::filesystem::path& base) {
  RunRequest r;
  r.deck_path = deck;
  r.output_base = base;
  r.output_format = "out";
  run_scene(r, nullptr);
  return io::read_channels(base.string() + ".out");
}

// |ours/ref − 1| of the means, or |ours − ref| for means near zero (`absolute`).
VerificationRow mean_row(const std::string& case_name, const PairedSeries& p, const std::string& what, double limit,
                         bool absolute, const std::string& source) {
  const double diff = absolute ? std::abs(mean(p.test) - mean(p.ref)) : std::abs(mean(p.test) / mean(p.ref) - 1.0);
  return {case_name, fmt::format("{} mean: {} {:.4g} vs {:.4g}", what, absolute ? "|diff|" : "rel. diff", mean(p.test), mean(p.ref)),
          diff, fmt::format("< {:.3g}", limit), source, diff < limit};
}
VerificationRow std_row(const std::string& case_name, const PairedSeries& p, const std::string& what, double limit,
                        const std::string& source) {
  const double diff = std::abs(standard_deviation(p.test) / standard_deviation(p.ref) - 1.0);
  return {case_name, fmt::format("{} std rel. diff", what), diff, fmt::format("< {:.3g}", limit), source, diff < limit};
}
VerificationRow correlation_row(const std::string& case_name, const PairedSeries& p, const std::string& what, double limit,
                                const std::string& source) {
  const double c = correlation(p);
  return {case_name, fmt::format("{} correlation", what), c, fmt::format("> {:.5g}", limit), source, c > limit};
}

// Mean period between up-crossings of the signal about its mean over the second half (the level
// it decays to), as the OpenFAST runs' README measures it; NaN with fewer than two crossings.
double mean_period(const std::vector<double>& t, const std::vector<double>& x) {
  const std::size_t half = x.size() / 2;
  double level = 0.0;
  for (std::size_t i = half; i < x.size(); ++i) level += x[i];
  level /= static_cast<double>(x.size() - half);
  std::vector<double> up;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (x[i - 1] - level < 0.0 && x[i] - level >= 0.0)
      up.push_back(t[i - 1] + (t[i] - t[i - 1]) * (level - x[i - 1]) / (x[i] - x[i - 1]));
  if (up.size() < 2) return std::nan("");
  return (up.back() - up.front()) / static_cast<double>(up.size() - 1);
}

VerificationRow below(const std::string& case_name, const std::string& metric, double value, double limit,
                      const std::string& source) {
  return {case_name, metric, value, fmt::format("< {:.3g}", limit), source, value < limit};
}

}  // namespace

std::vector<VerificationRow> verify_free_decay(std::FILE* out) {
  fmt::print(out, "OC3-Hywind free decay: rigid multibody, Morison hydro, nonlinear hydrostatics, catenary mooring\n");
  const struct {
    const char *name, *channel;
    double published_hz;  // PUBLISHED.md, OC3-Hywind platform natural frequencies (TP-47266)
  } cases[] = {{"surge", "PtfmSurge", 0.0080}, {"heave", "PtfmHeave", 0.0324}, {"pitch", "PtfmPitch", 0.0343}, {"yaw", "PtfmYaw", 0.1210}};
  const auto runs = shared_dir() / "reference/openfast-runs/oc3_free_decay";
  const std::string c = "free-decay";
  std::vector<VerificationRow> rows;
  for (const auto& d : cases) {
    const io::ChannelTable ours =
        run_deck(input(std::string("oc3_hywind/free_decay_") + d.name + ".yaml"), scratch("free-decay") / d.name);
    const auto& x = ours.columns[ours.find(d.channel).value()];
    const double period = mean_period(ours.time(), x);
    // Issue 6: within 5 % of the published natural frequency. Measured: surge +1.1 %, heave
    // −1.8 %, pitch +2.9 %, yaw −0.3 % (the published values are rounded to 2–3 digits).
    rows.push_back(below(c, fmt::format("{} period {:.4g} s vs published {:.4g} s: rel. diff", d.name, period, 1.0 / d.published_hz),
                         std::abs(period * d.published_hz - 1.0), 0.05, "PUBLISHED.md (TP-47266)"));
    // A free decay: nothing grows beyond the initial displacement (5 % for the offset of the
    // static equilibrium, e.g. the heave sink under the turbine weight).
    double largest = 0.0;
    for (double v : x) largest = std::max(largest, std::abs(v));
    rows.push_back(below(c, fmt::format("{}: largest |x| / |x(0)|", d.name), largest / std::abs(x.front()), 1.05, "decay"));
    const auto reference = runs / d.name / (std::string("oc3_decay_") + d.name + ".out");
    if (!std::filesystem::exists(reference)) continue;
    const io::ChannelTable theirs = io::read_channels(reference);
    const double p_theirs = mean_period(theirs.time(), theirs.columns[theirs.find(d.channel).value()]);
    // OpenFAST takes added mass and radiation damping from WAMIT potential flow, we from Morison
    // strips with Ca = 1 (the runs' README: "compare periods to a few percent"): 3 %. Measured:
    // surge +0.7 %, heave −1.7 %, pitch +1.8 %, yaw −0.03 %.
    rows.push_back(below(c, fmt::format("{} period vs OpenFAST {:.4g} s: rel. diff", d.name, p_theirs),
                         std::abs(period / p_theirs - 1.0), 0.03, "openfast-runs/oc3_free_decay"));
  }
  // The same decays with OpenFAST's hydrodynamic model (issue 15): WAMIT added mass, radiation
  // convolution and linear .hst hydrostatics, drag-only members (inputs/oc3_hywind/
  // hydro_potential_flow.yaml, which reads the WAMIT files beside the OpenFAST runs).
  if (!std::filesystem::exists(runs)) return rows;
  fmt::print(out, "OC3-Hywind free decay with WAMIT potential flow (hydro_potential_flow.yaml) against OpenFAST v5\n");
  const std::string cw = "free-decay-wamit";
  for (const auto& d : cases) {
    const io::ChannelTable ours =
        run_deck(input(std::string("oc3_hywind/free_decay_") + d.name + "_wamit.yaml"), scratch("free-decay") / (std::string(d.name) + "_wamit"));
    const io::ChannelTable theirs = io::read_channels(runs / d.name / (std::string("oc3_decay_") + d.name + ".out"));
    const double period = mean_period(ours.time(), ours.columns[ours.find(d.channel).value()]);
    const double p_theirs = mean_period(theirs.time(), theirs.columns[theirs.find(d.channel).value()]);
    const PairedSeries p = paired_series(theirs, d.channel, ours, d.channel, 0.0, theirs.time().back());
    double error = 0.0;
    for (std::size_t k = 0; k < p.ref.size(); ++k) error += (p.test[k] - p.ref[k]) * (p.test[k] - p.ref[k]);
    const double relative_rms = std::sqrt(error / static_cast<double>(p.ref.size())) / standard_deviation(p.ref);
    // Issue 15: periods within 1 %. Measured: surge +0.09 %, heave +0.01 %, pitch −0.01 %, yaw
    // −0.02 % (Morison: +0.75, −1.65, +1.79, −0.03 %).
    rows.push_back(below(cw, fmt::format("{} period {:.4g} s vs OpenFAST {:.4g} s: rel. diff", d.name, period, p_theirs),
                         std::abs(period / p_theirs - 1.0), 0.01, "issue 15; openfast-runs/oc3_free_decay"));
    // The whole decay: measured correlation ≥ 0.99997 and RMS error / RMS ≤ 0.0097 (heave: it
    // settles 1.8 cm deeper, −0.100 m against −0.082 m); bounds 0.999 and 0.05 (Morison: 0.972–1.0
    // and up to 0.24).
    rows.push_back(correlation_row(cw, p, d.channel, 0.999, "openfast-runs/oc3_free_decay"));
    rows.push_back(below(cw, fmt::format("{} RMS error / RMS", d.channel), relative_rms, 0.05, "openfast-runs/oc3_free_decay"));
  }
  // The state-space radiation against the convolution, pitch decay: measured correlation
  // 0.999996, RMS difference / RMS 3.3e-3 (the 0.2 % fit tolerance); bounds 0.9999 and 2e-2.
  const io::ChannelTable convolution = io::read_channels((scratch("free-decay") / "pitch_wamit").string() + ".out");
  const io::ChannelTable state_space =
      run_deck(input("oc3_hywind/free_decay_pitch_wamit_state_space.yaml"), scratch("free-decay") / "pitch_wamit_state_space");
  const PairedSeries p = paired_series(convolution, "PtfmPitch", state_space, "PtfmPitch", 0.0, convolution.time().back());
  double difference = 0.0;
  for (std::size_t k = 0; k < p.ref.size(); ++k) difference += (p.test[k] - p.ref[k]) * (p.test[k] - p.ref[k]);
  rows.push_back(correlation_row(cw, p, "PtfmPitch state space vs convolution", 0.9999, "radiation methods"));
  rows.push_back(below(cw, "PtfmPitch state space vs convolution: RMS difference / RMS",
                       std::sqrt(difference / static_cast<double>(p.ref.size())) / standard_deviation(p.ref), 2e-2, "radiation methods"));
  return rows;
}

std::vector<VerificationRow> verify_turbine_validation(std::FILE* out) {
  const auto reference = shared_dir() / "reference/openfast-runs/seed_validation_surge1000/v1_surge1000_BD/v1_surge1000_BD.out";
  if (!std::filesystem::exists(reference)) return {};
  fmt::print(out, "Seed §4.5.3: OC3 from rest, rotor held at 12.1 rpm, 1000 kN surge force; OpenFAST v5 + BeamDyn, 50–100 s\n");
  const io::ChannelTable ours = run_deck(input("oc3_hywind/seed_validation_surge1000.yaml"), scratch("turbine-validation") / "run");
  const io::ChannelTable ref = io::read_channels(reference);
  auto at = [&](const char* name) { return paired_series(ref, name, ours, name, 50.0, 100.0); };
  const std::string c = "turbine-validation";
  const std::string src = "openfast-runs/seed_validation_surge1000";
  // Platform: Morison (ours) against WAMIT (theirs) changes the periods by ≈ 1.5–2 % (free-decay
  // checks), not the static balance of the force. Measured: surge mean +0.51 %, pitch mean
  // +0.06 %, stds within 2.3 %, heave −0.045 m (the set-down of the surged spar; the hydrostatic
  // models differ at the waterline).
  std::vector<VerificationRow> rows = {
      mean_row(c, at("PtfmSurge"), "PtfmSurge", 0.02, false, src),
      mean_row(c, at("PtfmPitch"), "PtfmPitch", 0.01, false, src),
      std_row(c, at("PtfmSurge"), "PtfmSurge", 0.1, src),
      std_row(c, at("PtfmPitch"), "PtfmPitch", 0.1, src),
      mean_row(c, at("PtfmHeave"), "PtfmHeave [m]", 0.1, true, src),
      // Blade root (BeamDyn root frame): centrifugal axial force and flap moment means 0.034 % and
      // 0.064 %; the once-per-revolution gravity cycle of the edge moment: amplitude 0.1 %, phase
      // through the correlation 0.9986 (0.99: a phase error below 8°).
      mean_row(c, at("B1RootFzr"), "B1RootFzr", 5e-3, false, src),
      mean_row(c, at("B1RootMyr"), "B1RootMyr", 5e-3, false, src),
      std_row(c, at("B1RootMxr"), "B1RootMxr (gravity cycle)", 1e-2, src),
      correlation_row(c, at("B1RootMxr"), "B1RootMxr (gravity cycle)", 0.99, src),
      // Tip: flap mean +1.3 % (BeamDyn's single 5th-order element is 1.2 % stiffer in flap than the
      // converged blade); edge cycle std +1.5 %, correlation 0.997.
      mean_row(c, at("B1TipTDxr"), "B1TipTDxr", 0.05, false, src),
      std_row(c, at("B1TipTDyr"), "B1TipTDyr", 0.05, src),
      correlation_row(c, at("B1TipTDyr"), "B1TipTDyr", 0.99, src),
      // The flap oscillation rings 18 % larger, correlation 0.88: set off by the start and the
      // platform pitch, its decay depends on structural damping and frequency, which differ
      // between 23 finite volumes and one 5th-order element.
      std_row(c, at("B1RootMyr"), "B1RootMyr", 0.5, src),
      correlation_row(c, at("B1RootMyr"), "B1RootMyr", 0.8, src),
  };
  return rows;
}

std::vector<VerificationRow> verify_turbine_oc3(std::FILE* out) {
  const auto runs = shared_dir() / "reference/openfast-runs/oc3_spar_wturb_wavesirr/glue-codes/openfast";
  const auto reference = runs / "5MW_OC3Spar_DLL_WTurb_WavesIrr/5MW_OC3Spar_DLL_WTurb_WavesIrr_BD.out";
  if (!std::filesystem::exists(reference)) return {};
  fmt::print(out, "OC3 load case, 60 s: OpenFAST's TurbSim file and replayed sea; OpenFAST v5 + BeamDyn, 10–60 s\n");
  // OpenFAST's own inputs: its TurbSim file, its sea through Wave1Elev (waves.model
  // elevation_series), its initial state (platform at rest at the origin, 12.1 rpm, blades
  // spun but unloaded: BeamDyn's QuasiStaticInit).
  const auto dir = scratch("turbine-oc3");
  std::ofstream(dir / "case.yaml") << "include: [" << input("oc3_hywind/structure.yaml").string() << ", "
                                   << input("oc3_hywind/hydro.yaml").string() << ", " << input("oc3_hywind/mooring.yaml").string()
                                   << ", " << input("oc3_hywind/controller.yaml").string() << ", "
                                   << input("nrel5mw/aero.yaml").string() << ", " << input("nrel5mw/blade_structure.yaml").string()
                                   << "]\nsimulation: {t_max_s: 60.0, dt_s: 0.02}\noutput: {format: out, decimation: 5}\n"
                                   << "structure: {initial_conditions: {rotor_speed_rpm: 12.1}}\n"
                                   << "wind: {model: bts, file: " << (runs / "5MW_Baseline/Wind/90m_12mps_twr.bts").string()
                                   << ", speed_m_s: 12.0, reference_height_m: 90.0}\n"
                                   << "waves: {model: elevation_series, file: " << reference.string()
                                   << ", depth_m: 320.0, stretching: none}\n"
                                   << "blades: {segments: 23, substeps: 4, start: centrifugal}\n";
  const io::ChannelTable ours = run_deck(dir / "case.yaml", dir / "run");
  const io::ChannelTable ref = io::read_channels(reference);
  auto at = [&](const char* ref_name, const char* our_name, double scale = 1.0) {
    return paired_series(ref, ref_name, ours, our_name, 10.0, 60.0, scale);
  };
  const std::string c = "turbine-oc3";
  const std::string src = "openfast-runs/oc3_spar_wturb_wavesirr (_BD)";
  std::vector<VerificationRow> rows;
  // Issue 12 verification 4: means within 5 %. Measured: RotSpeed +0.4 %, GenPwr +0.6 %, PtfmSurge
  // −3.6 %, PtfmPitch −4.5 %, root flap moment −1.2 %, edge moment −4.9 %, tip flap −1.7 %, tip
  // edge −2.8 %, TwrBsMyt −4.8 % (Morison against WAMIT, rigid tower, no unsteady airfoil
  // aerodynamics: README). Same wind and sea, so the histories follow each other: measured
  // correlations 0.89–0.999, bound 0.85.
  const struct {
    const char *ref_name, *our_name;
    double scale;  // ours → reference units
  } channels[] = {{"RotSpeed", "RotSpeed", 1.0},   {"GenPwr", "GenPwr", 1.0},     {"PtfmSurge", "PtfmSurge", 1.0},
                  {"PtfmPitch", "PtfmPitch", 1.0}, {"B1RootMyr", "RootMyb1", 1e3}, {"B1RootMxr", "RootMxb1", 1e3},
                  {"B1TipTDxr", "TipDxb1", 1.0},   {"B1TipTDyr", "TipDyb1", 1.0},  {"TwrBsMyt", "TwrBsMyt", 1.0}};
  for (const auto& ch : channels) {
    const PairedSeries p = at(ch.ref_name, ch.our_name, ch.scale);
    rows.push_back(mean_row(c, p, ch.ref_name, 0.05, false, src));
    rows.push_back(correlation_row(c, p, ch.ref_name, 0.85, src));
  }
  // Means near zero, in their own units: blade pitch 2.80° vs 2.35° (the detuned OC3 pitch loop
  // answers the 4 % smaller platform pitch), platform yaw −0.42° vs −0.33°.
  rows.push_back(mean_row(c, at("BldPitch1", "BldPitch1"), "BldPitch1 [deg]", 1.0, true, src));
  rows.push_back(mean_row(c, at("PtfmYaw", "PtfmYaw"), "PtfmYaw [deg]", 0.5, true, src));
  // The replayed sea is OpenFAST's: Wave1Elev correlation 1.0000.
  rows.push_back(correlation_row(c, at("Wave1Elev", "Wave1Elev"), "Wave1Elev (replayed)", 0.9999, src));
  return rows;
}

}  // namespace fowtsim::driver
