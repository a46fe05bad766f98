// Rigid NREL 5MW rotor in steady uniform wind against OpenFAST v5.0.0 AeroDyn (BEMT) at seven
// operating points (../shared/reference/openfast-runs/aero_steady), and the peak power
// coefficient of the NREL 5MW definition report.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/aero/aero.hpp"
#include "fowtsim/aero/verification.hpp"
#include "fowtsim/testing/skip.hpp"
#include "nrel5mw_deck.hpp"

using namespace fowtsim;
using namespace fowtsim::aero;

namespace {

// An OpenFAST text output: header line starting with "Time", a units line, tab-separated rows.
struct OutFile {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  int column(const std::string& name) const {
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] == name) return static_cast<int>(i);
    }
    FAIL("channel " << name << " not in the .out file");
    return -1;
  }
  bool has(const std::string& name) const { return std::find(names.begin(), names.end(), name) != names.end(); }
};

OutFile read_out(const std::string& path) {
  std::ifstream file(path);
  REQUIRE(file.good());
  OutFile out;
  std::string line;
  while (std::getline(file, line) && line.rfind("Time", 0) != 0) {}
  std::istringstream header(line);
  for (std::string name; std::getline(header, name, '\t');) out.names.push_back(name);
  std::getline(file, line);  // units
  while (std::getline(file, line)) {
    std::istringstream row(line);
    std::vector<double> values;
    for (std::string cell; std::getline(row, cell, '\t');) {
      values.push_back(cell == "INVALID" ? 0.0 : std::stod(cell));
    }
    if (values.size() == out.names.size()) out.rows.push_back(values);
  }
  return out;
}

struct SummaryRow {
  double wind, rpm, pitch, tsr, cp, ct, power_kW, thrust_kN, torque_kNm;
};

std::vector<SummaryRow> read_summary(const std::string& path) {
  std::ifstream file(path);
  REQUIRE(file.good());
  std::string line;
  std::getline(file, line);  // header
  std::vector<SummaryRow> rows;
  while (std::getline(file, line)) {
    SummaryRow r;
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &r.wind, &r.rpm, &r.pitch, &r.tsr,
                    &r.cp, &r.ct, &r.power_kW, &r.thrust_kN, &r.torque_kNm) == 9) {
      rows.push_back(r);
    }
  }
  return rows;
}

double relative_error(double value, double reference) { return std::abs(value / reference - 1.0); }

}  // namespace

// Intent: the whole BEM chain (geometry with precone and tilt, skewed inflow, Ning solver, losses,
// Buhl, Pitt–Peters redistribution, spline polars, exact load integration) reproduces AeroDyn's
// rotor loads and section states. Evaluated at the azimuths of OpenFAST's output rows 15–20 s and
// averaged the same way as summary.csv.
TEST_CASE("rigid NREL 5MW rotor matches OpenFAST AeroDyn at seven steady operating points",
          "[verification][aero]") {
  const auto ref = fowtsim::testing::shared_dir_or_skip() / "reference" / "openfast-runs" / "aero_steady";
  const Params params = aero::testing::load_nrel5mw_deck();
  const RigidRotor rotor = verification::nrel5mw_rigid_rotor();
  const std::vector<SummaryRow> cases = read_summary((ref / "summary.csv").string());
  REQUIRE(cases.size() == 7);
  double worst_load = 0.0, worst_alpha = 0.0, worst_induction = 0.0;  // reported below
  // The other AeroDyn channels, as the module writes them (channel_values: units, frames, signs):
  // rotor channels, then blade 1's node loads where AeroDyn's run wrote them (B1N2 and B1N3 = nodes
  // 9 and 19; it lists no B1N1Fx/Fy). Differences: relative; RtSkew in degrees; node loads relative
  // to the largest |F| among the point's compared node loads (B1N3Fx, the tip node, passes near
  // zero at 12 m/s, where its own relative difference would only measure that). Bounds about ten
  // times the measured worst (printed below):
  //   RtSpeed, RtVAvgxh 1e-6: the same input; AeroDyn writes single precision (12.1000004 rpm).
  //   RtTSR 5e-4: measured 4.9e-5 at 25 m/s; AeroDyn's largest node radius shrinks with pitch
  //     (RtArea 12445.3 → 12444.1 m² from 0° to 23°, 3 mm of R), ours is the unpitched geometry.
  //   RtAeroCq 0.01: the torque's 1 % (Cq is RtAeroMxh over a common factor); measured 0.109 %.
  //   RtSkew 1e-5°: both acos of the disk-mean inflow on x_h = the 5° tilt; measured ~1e-14°.
  //   node loads 0.03: measured 0.26 % (B1N3Fx at 15 m/s); B1N2 ≤ 0.023 %.
  struct ChannelCheck {
    std::string name;
    double bound;
    double worst = 0.0;
  };
  std::vector<ChannelCheck> checks = {{"RtSpeed", 1e-6}, {"RtVAvgxh", 1e-6}, {"RtTSR", 5e-4}, {"RtAeroCq", 0.01},
                                      {"RtSkew", 1e-5}, {"B1N·Fx/Fy", 0.03}};
  std::printf("\n U   | P kW (ref)          | Fxh kN (ref)      | Mxh kNm (ref)       | Cp (ref)        | Ct (ref)        "
              "| N2 alpha deg (ref)   | N2 a (ref)\n");
  for (const SummaryRow& c : cases) {
    char dir[8];
    std::snprintf(dir, sizeof dir, "U%02d", static_cast<int>(c.wind));
    const OutFile of = read_out((ref / dir / (std::string("aero_steady_") + dir + ".out")).string());
    const int c_time = of.column("Time"), c_az = of.column("Azimuth");
    std::vector<double> azimuths;
    std::vector<double> ref_alpha(params.output_nodes.size(), 0.0), ref_axind(ref_alpha.size(), 0.0);
    std::vector<std::string> compared;
    for (std::size_t k = 0; k + 1 < checks.size(); ++k) compared.push_back(checks[k].name);
    const std::size_t first_node_load = compared.size();
    for (std::size_t j = 1; j <= params.output_nodes.size(); ++j)
      for (const char* f : {"Fx", "Fy"})
        if (of.has("B1N" + std::to_string(j) + f)) compared.push_back("B1N" + std::to_string(j) + f);
    std::vector<double> ref_channel(compared.size(), 0.0);
    for (const std::vector<double>& row : of.rows) {
      if (row[c_time] < 15.0 - 1e-9) continue;
      azimuths.push_back(row[c_az]);
      for (std::size_t k = 0; k < compared.size(); ++k) ref_channel[k] += row[of.column(compared[k])];
      for (std::size_t j = 0; j < ref_alpha.size(); ++j) {
        ref_alpha[j] += row[of.column("B1N" + std::to_string(j + 1) + "Alpha")];
        ref_axind[j] += row[of.column("B1N" + std::to_string(j + 1) + "AxInd")];
      }
    }
    const int samples = static_cast<int>(azimuths.size());
    REQUIRE(samples >= 50);
    for (std::size_t j = 0; j < ref_alpha.size(); ++j) ref_alpha[j] /= samples, ref_axind[j] /= samples;
    for (double& x : ref_channel) x /= samples;
    const verification::RotorMean m = verification::rotor_mean(params, rotor, c.wind, c.rpm, c.pitch, azimuths);
    REQUIRE(m.unconverged_evaluations == 0);
    double node_scale = 0.0;
    for (std::size_t k = first_node_load; k < compared.size(); ++k) node_scale = std::max(node_scale, std::abs(ref_channel[k]));
    for (std::size_t k = 0; k < compared.size(); ++k) {
      const double ours = m.channel(compared[k]), theirs = ref_channel[k];
      ChannelCheck& check = checks[std::min(k, checks.size() - 1)];
      const double difference = k >= first_node_load  ? std::abs(ours - theirs) / node_scale
                                : check.name == "RtSkew" ? std::abs(ours - theirs)
                                                         : relative_error(ours, theirs);
      std::printf("     %-9s %12.5f (%12.5f)\n", compared[k].c_str(), ours, theirs);
      check.worst = std::max(check.worst, difference);
      INFO("wind " << c.wind << " m/s: " << compared[k] << " " << ours << " vs AeroDyn " << theirs);
      CHECK(difference < check.bound);
    }
    const double power = m.power_W, thrust = m.thrust_N, torque = m.torque_N_m, cp = m.cp, ct = m.ct;
    const std::vector<double>& alpha = m.alpha_deg;
    const std::vector<double>& axind = m.axial_induction;
    std::printf("%4.0f | %8.1f (%8.1f) | %7.2f (%7.2f) | %8.1f (%8.1f) | %.4f (%.4f) | %.4f (%.4f) | %7.3f (%7.3f) | %.4f (%.4f)\n",
                c.wind, power / 1e3, c.power_kW, thrust / 1e3, c.thrust_kN, torque / 1e3, c.torque_kNm, cp, c.cp,
                ct, c.ct, alpha[1], ref_alpha[1], axind[1], ref_axind[1]);
    for (double e : {relative_error(power, c.power_kW * 1e3), relative_error(thrust, c.thrust_kN * 1e3),
                     relative_error(torque, c.torque_kNm * 1e3), relative_error(cp, c.cp), relative_error(ct, c.ct)}) {
      worst_load = std::max(worst_load, e);
    }
    for (std::size_t j = 0; j < alpha.size(); ++j) {
      worst_alpha = std::max(worst_alpha, std::abs(alpha[j] - ref_alpha[j]));
      worst_induction = std::max(worst_induction, std::abs(axind[j] - ref_axind[j]));
    }
    INFO("wind " << c.wind << " m/s");
    // Tolerance 1 %: issue 4 acceptance bound for rotor loads against AeroDyn (same theory, same
    // data; differences come from implementation details such as the skew-angle definition).
    CHECK(relative_error(power, c.power_kW * 1e3) < 0.01);
    CHECK(relative_error(thrust, c.thrust_kN * 1e3) < 0.01);
    CHECK(relative_error(torque, c.torque_kNm * 1e3) < 0.01);
    CHECK(relative_error(cp, c.cp) < 0.01);
    CHECK(relative_error(ct, c.ct) < 0.01);
    for (std::size_t j = 0; j < alpha.size(); ++j) {
      INFO("output node " << params.output_nodes[j]);
      // Tolerances 0.3° and 0.01: issue 4 acceptance bounds for section states against AeroDyn.
      CHECK(std::abs(alpha[j] - ref_alpha[j]) < 0.3);
      CHECK(std::abs(axind[j] - ref_axind[j]) < 0.01);
    }
  }
  std::printf("worst over 7 cases: rotor loads/coefficients %.3f %%, alpha %.4f deg, axial induction %.5f "
              "(output nodes 1, 9, 19)\n", 100.0 * worst_load, worst_alpha, worst_induction);
  for (const ChannelCheck& check : checks) std::printf("worst over 7 cases: %s %.2e (bound %g)\n", check.name.c_str(), check.worst, check.bound);
}

// Intent: the peak of the Cp–λ curve at 0° pitch. Reference: Jonkman et al. 2009 (NREL/TP-500-38060)
// Ch. 7, via ../shared/reference/PUBLISHED.md: "peak power coefficient Cp = 0.482 at tip-speed ratio
// 7.55 and 0° pitch". That is the rotor (aerodynamic, shaft) power coefficient of FAST/AeroDyn
// steady runs, the quantity computed here (RtAeroCp); the electrical one would be 0.944 times it.
// Same turbine geometry as above (precone, tilt), 8 m/s, λ = Ω R / RtVAvgxh, azimuth-averaged.
TEST_CASE("NREL 5MW peak power coefficient at 0 deg pitch", "[verification][aero]") {
  const Params params = aero::testing::load_nrel5mw_deck();
  const verification::CpPeak peak = verification::peak_power_coefficient(params, verification::nrel5mw_rigid_rotor(), 8.0);
  const double cp_max = peak.cp, lambda_max = peak.tsr;
  std::printf("\nCp-lambda peak: Cp = %.4f at lambda = %.3f (38060: 0.482 at 7.55)\n", cp_max, lambda_max);
  // Tolerance 2 %: issue 4 bound for the published peak (older AeroDyn, different BEM options).
  CHECK(relative_error(cp_max, 0.482) < 0.02);
  CHECK(relative_error(lambda_max, 7.55) < 0.02);
}
