#include "sweep/frequency_domain_screening.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "scenes/floating_screening.hpp"

namespace fowtsim::driver::sweep {
namespace {

struct Row {
  const SweepCase* c = nullptr;
  std::optional<ScreeningResult> result;
  std::string failure;
  double seconds = 0.0;
};

// The case's keys as `--set` settings over the base deck (what its case deck says).
std::vector<std::string> case_settings(const SweepCase& c) {
  std::vector<std::string> settings;
  for (const DeckOverride& o : c.overrides) settings.push_back(o.key_path + "=" + o.yaml_value);
  return settings;
}

double ranked_std(const Row& r, const std::string& channel) {
  if (!r.result) return -1.0;
  const auto it = std::find(r.result->outputs.begin(), r.result->outputs.end(), channel);
  return it == r.result->outputs.end() ? -1.0 : r.result->std_total[static_cast<std::size_t>(it - r.result->outputs.begin())];
}

}  // namespace

int screen_sweep(std::FILE* out, const SweepSpec& spec, const std::vector<SweepCase>& cases) {
  const std::string ranking = "TwrBsMyt";
  std::vector<Row> rows;
  for (const SweepCase& c : cases) {
    Row r;
    r.c = &c;
    const auto start = std::chrono::steady_clock::now();
    try {
      r.result = screen_floating(spec.base_deck, case_settings(c));
    } catch (const std::exception& e) {  // InputError, NumericalError: the case's row says why
      r.failure = e.what();
      std::replace(r.failure.begin(), r.failure.end(), '\n', ' ');
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rows.push_back(std::move(r));
  }
  std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) { return ranked_std(a, ranking) > ranked_std(b, ranking); });
  const std::vector<std::string> channels = screening_channels(true);
  fmt::print(out, "── fowtsim sweep {} --frequency-domain: {} cases, ranked by std {} ─────────\n", spec.name, cases.size(), ranking);
  fmt::print(out, "{:>4} {:<32} {:>6} {:>5} {:>5} {:<9}", "rank", "case", "V m/s", "Hs m", "Tp s", "region");
  for (const std::string& ch : channels) fmt::print(out, " {:>10}", "σ " + ch);
  fmt::print(out, " {:>7}\n", "ms");
  const std::filesystem::path csv_path = spec.output_dir / "frequency_domain_screening.csv";
  std::filesystem::create_directories(spec.output_dir);
  std::ofstream csv(csv_path);
  if (!csv) throw InputError({"sweep", std::nullopt, "--output-dir", "a writable folder"}, "cannot create " + csv_path.string());
  csv << "rank,case,wind_speed_m_s,hs_m,tp_s,region";
  for (const std::string& ch : channels) csv << ",std_" << ch;
  csv << ",milliseconds,failure\n";
  int failed = 0;
  double total = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    const SweepCase& c = *r.c;
    total += r.seconds;
    auto number = [](const std::optional<double>& v) { return v ? fmt::format("{:g}", *v) : std::string("–"); };
    const std::string region = r.result ? r.result->operating_point.region : "failed";
    fmt::print(out, "{:>4} {:<32} {:>6} {:>5} {:>5} {:<9}", r.result ? std::to_string(i + 1) : "–", c.name, number(c.wind_speed_m_s),
               number(r.result ? std::optional(r.result->hs_m) : c.hs_m), number(r.result ? std::optional(r.result->tp_s) : c.tp_s), region);
    csv << (r.result ? std::to_string(i + 1) : "") << ',' << c.name << ',' << (c.wind_speed_m_s ? fmt::format("{:g}", *c.wind_speed_m_s) : "")
        << ',' << (r.result ? fmt::format("{:g},{:g}", r.result->hs_m, r.result->tp_s) : ",") << ',' << region;
    for (const std::string& ch : channels) {
      std::optional<double> v;
      if (r.result) {
        const auto it = std::find(r.result->outputs.begin(), r.result->outputs.end(), ch);
        if (it != r.result->outputs.end()) v = r.result->std_total[static_cast<std::size_t>(it - r.result->outputs.begin())];
      }
      fmt::print(out, " {:>10}", v ? fmt::format("{:.4g}", *v) : "–");
      csv << ',' << (v ? fmt::format("{:.6g}", *v) : "");
    }
    fmt::print(out, " {:>7.1f}{}\n", 1e3 * r.seconds, r.failure.empty() ? "" : "  " + r.failure);
    csv << fmt::format(",{:.2f},\"{}\"\n", 1e3 * r.seconds, r.failure);
    failed += r.result ? 0 : 1;
  }
  fmt::print(out, "  {} cases screened in {:.2f} s ({:.1f} ms a case){}\n  table            {}\n", rows.size() - static_cast<std::size_t>(failed),
             total, rows.empty() ? 0.0 : 1e3 * total / static_cast<double>(rows.size()),
             failed ? fmt::format(", {} could not be", failed) : "", csv_path.string());
  return failed ? 1 : 0;
}

}  // namespace fowtsim::driver::sweep
