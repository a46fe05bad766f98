// `fowtsim verify aero` and `fowtsim verify wind` (issue 16): the headline checks of the aero and
// wind module tests, through fowtsim/aero/verification.hpp and fowtsim/wind/verification.hpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "verify/verify_cases.hpp"
#include "verify/verify_modules.hpp"
#include "decks/aero_deck.hpp"
#include "fowtsim/aero/verification.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/io/turbsim_bts.hpp"
#include "fowtsim/wind/iec_turbulence.hpp"
#include "fowtsim/wind/turbulence_generator.hpp"
#include "fowtsim/wind/verification.hpp"

namespace fowtsim::driver {

std::filesystem::path source_input(const std::string& relative);  // verify_cases.cpp

namespace {

VerificationRow below(const std::string& case_name, const std::string& metric, double value, double limit, const std::string& source) {
  return {case_name, metric, value, fmt::format("< {:.3g}", limit), source, value < limit};
}

// One operating point of openfast-runs/aero_steady/summary.csv (RtAero* averaged over 15–20 s).
struct AeroDynPoint {
  double wind, rpm, pitch, tsr, cp, ct, power_kW, thrust_kN, torque_kNm;
};

std::vector<AeroDynPoint> read_aerodyn_summary(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);  // header
  std::vector<AeroDynPoint> points;
  while (std::getline(file, line)) {
    AeroDynPoint p;
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &p.wind, &p.rpm, &p.pitch, &p.tsr, &p.cp, &p.ct,
                    &p.power_kW, &p.thrust_kN, &p.torque_kNm) == 9)
      points.push_back(p);
  }
  return points;
}

// The rigid rotor at the azimuths of each OpenFAST output row 15–20 s against AeroDyn's averages
// (the module test "rigid NREL 5MW rotor matches OpenFAST AeroDyn at seven steady operating
// points"); no row when the reference runs are absent.
void aerodyn_rows(const aero::Params& params, std::FILE* out, std::vector<VerificationRow>& rows) {
  const auto runs = shared_dir() / "reference/openfast-runs/aero_steady";
  const std::vector<AeroDynPoint> points = read_aerodyn_summary(runs / "summary.csv");
  if (points.empty()) {
    fmt::print(out, "(OpenFAST AeroDyn operating points skipped: {} not found)\n", (runs / "summary.csv").string());
    return;
  }
  fmt::print(out, "\nRigid NREL 5MW rotor against OpenFAST v5 AeroDyn (openfast-runs/aero_steady, means over 15–20 s)\n");
  fmt::print(out, "{:>5} {:>19} {:>19} {:>17} {:>17}\n", "U m/s", "power kW (AeroDyn)", "thrust kN (AeroDyn)", "Cp (AeroDyn)", "Ct (AeroDyn)");
  double worst[5] = {0, 0, 0, 0, 0}, worst_alpha = 0.0, worst_induction = 0.0;
  int unconverged = 0;
  // The other AeroDyn channels as the module writes them (channel_values), against the same rows:
  // relative differences, RtSkew's in degrees, the node loads relative to the largest |F| among the
  // point's compared node loads (the module test's metrics; bounds and reasons below).
  const char* other[5] = {"RtSpeed", "RtVAvgxh", "RtTSR", "RtAeroCq", "RtSkew"};
  double worst_other[5] = {0, 0, 0, 0, 0}, worst_node_load = 0.0;
  for (const AeroDynPoint& c : points) {
    const std::string name = fmt::format("U{:02d}", static_cast<int>(c.wind));
    const io::ChannelTable of = io::read_channels(runs / name / ("aero_steady_" + name + ".out"));
    const std::vector<double>& azimuth = of.columns[of.find("Azimuth").value()];
    std::vector<double> azimuths;
    std::vector<double> ref_alpha(params.output_nodes.size(), 0.0), ref_induction(ref_alpha.size(), 0.0);
    std::vector<std::string> compared(other, other + 5);
    for (std::size_t j = 1; j <= params.output_nodes.size(); ++j)  // AeroDyn's run writes B1N2, B1N3 only
      for (const char* f : {"Fx", "Fy"})
        if (of.find(fmt::format("B1N{}{}", j, f))) compared.push_back(fmt::format("B1N{}{}", j, f));
    std::vector<double> ref_channel(compared.size(), 0.0);
    for (std::size_t row = 0; row < of.rows(); ++row) {
      if (of.time()[row] < 15.0 - 1e-9) continue;
      azimuths.push_back(azimuth[row]);
      for (std::size_t k = 0; k < compared.size(); ++k) ref_channel[k] += of.columns[of.find(compared[k]).value()][row];
      for (std::size_t j = 0; j < ref_alpha.size(); ++j) {
        ref_alpha[j] += of.columns[of.find(fmt::format("B1N{}Alpha", j + 1)).value()][row];
        ref_induction[j] += of.columns[of.find(fmt::format("B1N{}AxInd", j + 1)).value()][row];
      }
    }
    const aero::verification::RotorMean m = aero::verification::rotor_mean(params, aero::verification::nrel5mw_rigid_rotor(), c.wind,
                                                                           c.rpm, c.pitch, azimuths);
    unconverged += m.unconverged_evaluations;
    const double ours[5] = {m.power_W, m.thrust_N, m.torque_N_m, m.cp, m.ct};
    const double theirs[5] = {c.power_kW * 1e3, c.thrust_kN * 1e3, c.torque_kNm * 1e3, c.cp, c.ct};
    for (int k = 0; k < 5; ++k) worst[k] = std::max(worst[k], std::abs(ours[k] / theirs[k] - 1.0));
    const double n = static_cast<double>(azimuths.size());
    for (std::size_t j = 0; j < ref_alpha.size(); ++j) {
      worst_alpha = std::max(worst_alpha, std::abs(m.alpha_deg[j] - ref_alpha[j] / n));
      worst_induction = std::max(worst_induction, std::abs(m.axial_induction[j] - ref_induction[j] / n));
    }
    double node_scale = 0.0;
    for (std::size_t k = 5; k < compared.size(); ++k) node_scale = std::max(node_scale, std::abs(ref_channel[k] / n));
    for (std::size_t k = 0; k < compared.size(); ++k) {
      const double ours = m.channel(compared[k]), theirs = ref_channel[k] / n;
      if (k >= 5)
        worst_node_load = std::max(worst_node_load, std::abs(ours - theirs) / node_scale);
      else
        worst_other[k] = std::max(worst_other[k], k == 4 ? std::abs(ours - theirs) : std::abs(ours / theirs - 1.0));
    }
    fmt::print(out, "{:>5.0f} {:>8.1f} ({:>8.1f}) {:>8.2f} ({:>8.2f}) {:.4f} ({:.4f}) {:.4f} ({:.4f})\n", c.wind, m.power_W / 1e3,
               c.power_kW, m.thrust_N / 1e3, c.thrust_kN, m.cp, c.cp, m.ct, c.ct);
  }
  const std::string source = "openfast-runs/aero_steady (AeroDyn v5)";
  // Issue 4 acceptance bounds against AeroDyn (same theory, same data; what differs are
  // implementation details such as the skew-angle definition): 1 % on rotor loads, 0.3° and 0.01 on
  // the section states. Measured worst 0.109 %, 0.0031°, 8e-5 (README).
  const char* names[5] = {"power", "thrust", "torque", "Cp", "Ct"};
  for (int k = 0; k < 5; ++k)
    rows.push_back(below("aero", fmt::format("{} operating points: worst {} rel. diff", points.size(), names[k]), worst[k], 0.01, source));
  rows.push_back(below("aero", fmt::format("{} operating points: worst α |diff| [deg]", points.size()), worst_alpha, 0.3, source));
  rows.push_back(below("aero", fmt::format("{} operating points: worst induction |diff|", points.size()), worst_induction, 0.01, source));
  // About ten times the measured worst (the module test states each): RtSpeed, RtVAvgxh 1e-6 (the
  // same input; AeroDyn writes single precision; measured 3.3e-8, 4.7e-8); RtTSR 5e-4 (measured
  // 4.9e-5: AeroDyn's largest node radius shrinks with pitch, 3 mm at 23°); RtAeroCq the torque's
  // 1 % (measured 0.109 %); RtSkew 1e-5° (both the 5° tilt; measured 8e-15°); node loads 3 %
  // (measured 0.26 %, B1N3Fx at 15 m/s).
  const double other_bound[5] = {1e-6, 1e-6, 5e-4, 0.01, 1e-5};
  for (int k = 0; k < 5; ++k)
    rows.push_back(below("aero", fmt::format("{} operating points: worst {} {}", points.size(), other[k], k == 4 ? "|diff| [deg]" : "rel. diff"),
                         worst_other[k], other_bound[k], source));
  rows.push_back(below("aero", fmt::format("{} operating points: worst B1N2-3 Fx/Fy |diff|/max|F|", points.size()), worst_node_load, 0.03, source));
  // Every node converged (the module test requires it).
  rows.push_back(below("aero", fmt::format("{} operating points: unconverged evaluations", points.size()), unconverged, 0.5, "induction solver"));
}

// σ of u, v, w over all points and seeds of generated small fields, against the record's target.
struct GeneratedSigma {
  std::array<double, 3> measured{}, target{}, iec{};
};
GeneratedSigma generated_sigma(int seeds) {
  GeneratedSigma g;
  std::array<double, 3> variance{};
  int series = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    const wind::GeneratedTurbulence t = wind::generate_turbulence(wind::verification::small_turbulent_field(static_cast<std::uint64_t>(seed)));
    for (int c = 0; c < 3; ++c) g.target[c] = t.stats.expected_sigma_m_s[c], g.iec[c] = t.stats.iec_sigma_m_s[c];
    for (int iz = 0; iz < t.field.nz; ++iz)
      for (int iy = 0; iy < t.field.ny; ++iy) {
        const wind::verification::PointStatistics s = wind::verification::grid_point_statistics(t.field, iy, iz);
        for (int c = 0; c < 3; ++c) variance[c] += s.sigma_m_s[c] * s.sigma_m_s[c];
        ++series;
      }
  }
  for (int c = 0; c < 3; ++c) g.measured[c] = std::sqrt(variance[c] / series);
  return g;
}

}  // namespace

std::vector<VerificationRow> verify_aero(std::FILE* out) {
  const io::ValidatedDeck deck =
      io::read_deck(io::Schema::map({{"aero", aero_schema()}, {"airfoils", airfoils_schema()}}), source_input("nrel5mw/aero.yaml"));
  const aero::Params params = aero_params(deck);
  std::vector<VerificationRow> rows;

  const aero::verification::CpPeak peak = aero::verification::peak_power_coefficient(params, aero::verification::nrel5mw_rigid_rotor(), 8.0);
  fmt::print(out, "NREL 5MW rigid rotor, 8 m/s, 0° pitch: Cp–λ peak Cp = {:.4f} at λ = {:.3f} (38060: 0.482 at 7.55)\n", peak.cp, peak.tsr);
  // Issue 4 bound for the published peak: 2 % (older AeroDyn, different BEM options). Measured
  // +1.2 % and +0.9 %.
  const std::string published = "38060 Ch. 7 (PUBLISHED.md)";
  rows.push_back(below("aero", fmt::format("Cp peak {:.4f} vs 0.482: rel. diff", peak.cp), std::abs(peak.cp / 0.482 - 1.0), 0.02, published));
  rows.push_back(below("aero", fmt::format("λ at Cp peak {:.3f} vs 7.55: rel. diff", peak.tsr), std::abs(peak.tsr / 7.55 - 1.0), 0.02, published));

  aerodyn_rows(params, out, rows);

  const aero::verification::MomentumBalance b = aero::verification::momentum_balance(params);
  fmt::print(out, "\nMomentum balance of {} converged sections (λ 4–10, a ≤ 0.4): worst thrust {:.1e}, torque {:.1e}; {} failed\n",
             b.sections, b.worst_thrust, b.worst_torque, b.failed);
  // Blade-element loads equal the annulus momentum fluxes at the root of R(φ); Brent stops at
  // 1e-12 rad in φ: 1e-8 relative (the module test's bound). A failed solve counts as a failure.
  const std::string glauert = "Glauert momentum, closed form";
  rows.push_back(below("aero", "BEM section thrust vs momentum: worst rel. diff", b.failed == 0 ? b.worst_thrust : INFINITY, 1e-8, glauert));
  rows.push_back(below("aero", "BEM section torque vs momentum: worst rel. diff", b.failed == 0 ? b.worst_torque : INFINITY, 1e-8, glauert));

  const aero::verification::PotentialFlowCheck tower = aero::verification::tower_potential_flow();
  fmt::print(out, "Tower potential flow at {} points around a 6 m cylinder: worst |Δv| {:.1e} m/s\n\n", tower.points, tower.worst_m_s);
  // Two forms of the same exact flow: round-off only, 1e-12 m/s at 10 m/s.
  rows.push_back(below("aero", "tower potential vs cylinder complex potential [m/s]", tower.worst_m_s, 1e-12, "2-D potential flow, closed form"));
  return rows;
}

std::vector<VerificationRow> verify_wind(std::FILE* out) {
  std::vector<VerificationRow> rows;
  wind::TurbulenceParams ntm;
  ntm.category = wind::TurbulenceCategory::B;
  const double sigma_ntm = wind::longitudinal_sigma(ntm, 12.0);
  wind::TurbulenceParams etm = ntm;
  etm.model = wind::TurbulenceModel::ETM;
  etm.iec_wind_class = 1;
  const double sigma_etm = wind::longitudinal_sigma(etm, 12.0);
  fmt::print(out, "IEC σ1 at 12 m/s, class B: NTM {:.5f} m/s, ETM (class I) {:.5f} m/s\n", sigma_ntm, sigma_etm);
  // NTM: 0.14 (0.75·12 + 5.6) = 2.044 m/s as TurbSim's summary prints it (4 digits: half a unit
  // of the last digit). ETM: 2·0.14·(0.072·(10/2 + 3)(12/2 − 4) + 10) = 3.12256 m/s, the same
  // closed form: round-off.
  rows.push_back(below("wind", "NTM class B σ1 at 12 m/s: |σ − 2.044| [m/s]", std::abs(sigma_ntm - 2.044), 5e-4,
                       "IEC 61400-1 ed. 3 eq. 11; TurbSim .sum"));
  rows.push_back(below("wind", "ETM class I B σ1 at 12 m/s vs 3.12256: rel. diff", std::abs(sigma_etm / 3.12256 - 1.0), 1e-12,
                       "IEC 61400-1 ed. 3 eq. 19"));

  // The IEC 61400-1 events (EOG, EDC, ECD, EWS) of the wind field against the standard's formulas at
  // the hub and the rotor disk's edges (the module test "the verify command's event check"): the
  // same closed forms in another order, round-off only; measured ≤ 2e-15, limit 10×.
  const struct {
    wind::WindEventType type;
    const char* name;
  } events[] = {{wind::WindEventType::EOG, "EOG"}, {wind::WindEventType::EDC, "EDC"}, {wind::WindEventType::ECD, "ECD"},
                {wind::WindEventType::EWS_vertical, "EWS vertical"}, {wind::WindEventType::EWS_horizontal, "EWS horizontal"}};
  for (const auto& e : events) {
    double worst = 0.0;
    for (int sign : {1, -1})
      for (double direction : {0.0, 20.0}) worst = std::max(worst, wind::verification::iec_event_worst_deviation(e.type, sign, direction));
    rows.push_back(below("wind", fmt::format("{} vs IEC formula at hub and disk edges: worst |Δv|/V_hub", e.name), worst, 2e-14,
                         "IEC 61400-1 ed. 3 §6.3.2 / ed. 4 §6.3.3"));
  }
  // The turbulent EWM: the generator's σ1 is 0.11 V_hub, and the hub u variance over 200 seeds
  // matches the record's target within 4 standard errors (the module test of the same name).
  const wind::verification::EwmHubSigma ewm = wind::verification::ewm_hub_sigma(200);
  fmt::print(out, "Turbulent EWM at 40 m/s, 200 seeds: hub σ u = {:.4f} m/s, record target {:.4f}, 0.11 V_hub = {:.4f}\n",
             std::sqrt(ewm.mean_variance_m2_s2), ewm.record_sigma_m_s, ewm.iec_sigma_m_s);
  rows.push_back(below("wind", "EWM σ1 vs 0.11 V_hub at 40 m/s: rel. diff", std::abs(ewm.iec_sigma_m_s / 4.4 - 1.0), 1e-15,
                       "IEC 61400-1 ed. 3 §6.3.2.1"));
  rows.push_back(below("wind", "EWM hub σ² (200 seeds) vs record target [m²/s²]",
                       std::abs(ewm.mean_variance_m2_s2 - ewm.record_sigma_m_s * ewm.record_sigma_m_s), 4.0 * ewm.standard_error_m2_s2,
                       "4 standard errors of the seeds' mean"));

  constexpr int kSeeds = 240;
  const GeneratedSigma g = generated_sigma(kSeeds);
  fmt::print(out, "Generated 4×3 fields (class A, 10 m/s, 600 s at 4 Hz), {} seeds: σ u, v, w = {:.4f}, {:.4f}, {:.4f} m/s; "
             "record targets {:.4f}, {:.4f}, {:.4f}; IEC {:.4f}, {:.4f}, {:.4f}\n",
             kSeeds, g.measured[0], g.measured[1], g.measured[2], g.target[0], g.target[1], g.target[2], g.iec[0], g.iec[1], g.iec[2]);
  // Issue 4: within 3 % of the record's target σ = √(Σ S(f_m) Δf) of the IEC Kaimal spectrum (the
  // IEC σ itself is larger: a record carries no variance below 1/T or above Nyquist, as TurbSim
  // without ScaleIEC). Measured u +0.74 % over these 240 seeds (README).
  const char* names[3] = {"u", "v", "w"};
  for (int c = 0; c < 3; ++c)
    rows.push_back(below("wind", fmt::format("generated σ_{} vs IEC Kaimal record target: rel. diff", names[c]),
                         std::abs(g.measured[c] / g.target[c] - 1.0), 0.03, "IEC 61400-1 ed. 3 Annex C; issue 4"));

  // The sampler's covariance against the IEC coherence exp(−a r) on a 6 × 5 grid (4 m × 5 m):
  // embedding and dense are exact (round-off, 1e-12); the independent switch drops only
  // coherences below its threshold 1e-4.
  const int ny = 6, nz = 5;
  const double dy = 4.0, dz = 5.0;
  wind::CoherentSampler sampler(ny, nz, dy, dz);
  const struct {
    double decay_per_m;
    wind::CoherentSampler::Method method;
    const char* name;
    double limit;
  } ways[] = {{0.5, wind::CoherentSampler::Method::embedding, "embedding", 1e-12},
              {0.002, wind::CoherentSampler::Method::dense, "dense Cholesky", 1e-12},
              {2.5, wind::CoherentSampler::Method::independent, "independent", wind::CoherentSampler::independence_threshold}};
  for (const auto& w : ways) {
    const bool chosen = sampler.prepare(w.decay_per_m) == w.method;
    const double error = wind::verification::sampler_coherence_error(sampler, ny, dy, dz, w.decay_per_m);
    rows.push_back(below("wind", fmt::format("sampler coherence, {} (a = {}/m): worst |diff|", w.name, w.decay_per_m),
                         chosen ? error : INFINITY, w.limit, "IEC 61400-1 ed. 3 eq. B.2"));
  }

  const auto wind_dir = shared_dir() / "reference/openfast-runs/oc3_spar_wturb_wavesirr/glue-codes/openfast";
  const auto run_out = wind_dir / "5MW_OC3Spar_DLL_WTurb_WavesIrr/5MW_OC3Spar_DLL_WTurb_WavesIrr.out";
  if (!std::filesystem::exists(run_out)) {
    fmt::print(out, "(TurbSim files and OpenFAST run skipped: {} not found)\n\n", run_out.string());
    return rows;
  }
  // TurbSim's 60 s OC3 file at the InflowWind probe (0, 0, 90) m against OpenFAST's Wind1VelX/Y/Z.
  auto field = std::make_shared<wind::FullField>();
  static_cast<WindGrid&>(*field) = io::read_turbsim_bts(wind_dir / "5MW_Baseline/Wind/90m_12mps_twr.bts");
  wind::WindParams p;
  p.model = wind::WindModel::bts;
  p.file = "90m_12mps_twr.bts";
  p.reference_height_m = 90.0;
  const wind::WindField bts(p, field);
  const io::ChannelTable of = io::read_channels(run_out);
  std::array<std::vector<double>, 3> recorded;
  const char* channels[3] = {"Wind1VelX", "Wind1VelY", "Wind1VelZ"};
  for (int c = 0; c < 3; ++c) recorded[c] = of.columns[of.find(channels[c]).value()];
  const std::array<double, 3> worst = wind::verification::max_velocity_deviation(bts, Vec3(0.0, 0.0, 90.0), of.time(), recorded);
  // Half the file's int16 step per component, 0.5/slope (slopes 3552.05, 4197.02, 7142.20 of the
  // file): the resolution both codes share. Measured 8.4e-7 m/s at most (float32 and 9 digits).
  const double slope[3] = {3552.051513671875, 4197.0185546875, 7142.2021484375};
  for (int c = 0; c < 3; ++c)
    rows.push_back(below("wind", fmt::format("TurbSim .bts at probe vs OpenFAST {} [m/s]", channels[c]), worst[c], 0.5 / slope[c],
                         "openfast-runs/oc3_spar_wturb_wavesirr"));

  // The 600 s file's hub point (the grid's centre node, y = 0, z = 90 m) against the hub-height
  // statistics of TurbSim's summary, which covers the whole 630 s analysis record (12,600 steps)
  // where the file holds its first 12,242.
  const io::TurbSimField long_field = io::read_turbsim_bts(wind_dir / "5MW_Baseline/Wind/90m_12mps_twr_600s.bts");
  const wind::verification::PointStatistics hub =
      wind::verification::grid_point_statistics(long_field, long_field.ny / 2, long_field.nz / 2);
  const double sum_sigma[3] = {1.662, 1.599, 0.999}, sum_mean_u = 12.00;  // 90m_12mps_twr_600s.sum
  fmt::print(out, "TurbSim 600 s file, hub point over {} steps: mean u {:.4f} m/s, σ u, v, w = {:.4f}, {:.4f}, {:.4f} m/s "
             "(summary over 12,600: 12.00; 1.662, 1.599, 0.999)\n\n",
             long_field.nt, hub.mean_m_s[0], hub.sigma_m_s[0], hub.sigma_m_s[1], hub.sigma_m_s[2]);
  const std::string sum = "TurbSim 90m_12mps_twr_600s.sum";
  // Not the same samples: the file lacks the last 2.8 % of the summary's record, which moves the
  // statistics by more than the summary's rounding (2 and 3 decimals). Measured mean −0.026 m/s,
  // σ −0.26, −1.5, −0.42 %; bounds 0.1 m/s and 5 %, well inside the field's own spread (the
  // summary's u σ ranges over 1.541–2.226 m/s across the grid points): the file read right.
  rows.push_back(below("wind", "TurbSim hub mean u vs summary |diff| [m/s]", std::abs(hub.mean_m_s[0] - sum_mean_u), 0.1, sum));
  for (int c = 0; c < 3; ++c)
    rows.push_back(below("wind", fmt::format("TurbSim hub σ_{} vs summary: rel. diff", names[c]),
                         std::abs(hub.sigma_m_s[c] / sum_sigma[c] - 1.0), 0.05, sum));
  return rows;
}

}  // namespace fowtsim::driver
