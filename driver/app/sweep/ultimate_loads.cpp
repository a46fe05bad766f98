#include "sweep/ultimate_loads.hpp"

#include <cmath>
#include <map>

#include "sweep/load_table.hpp"

namespace fowtsim::driver::sweep {

namespace {

// A load case: one factor combination of a group, its realisations together.
struct LoadCase {
  const LoadCaseGroup* group = nullptr;
  std::vector<const LoadTableRow*> completed;  // its completed realisations
};

std::vector<LoadCase> ultimate_load_cases(const LoadTable& table, const SweepSpec& spec) {
  std::map<std::pair<std::size_t, std::vector<std::pair<std::string, std::string>>>, std::size_t> index;
  std::vector<LoadCase> cases;
  for (const LoadTableRow& row : table.rows) {
    const LoadCaseGroup& g = spec.groups[row.case_->group];
    if (!g.ultimate) continue;
    const auto key = std::make_pair(row.case_->group, row.case_->factors);
    const auto [it, added] = index.try_emplace(key, cases.size());
    if (added) cases.push_back({&g, {}});
    if (row.outcome.state == CaseState::completed) cases[it->second].completed.push_back(&row);
  }
  return cases;
}

// γ_f is a partial safety factor for loads: forces and moments. A motion, an angle, a speed or a
// power keeps its characteristic value (γ_f = 1) — 1.35 × 90° of pitch means nothing.
bool is_load_unit(const std::string& unit) {
  static const char* const kLoadUnits[] = {"N", "kN", "MN", "N-m", "kN-m", "MN-m", "N·m", "kN·m", "MN·m", "Nm", "kNm"};
  for (const char* u : kLoadUnits)
    if (unit == u) return true;
  return false;
}

}  // namespace

std::vector<UltimateLoad> ultimate_loads(const LoadTable& table, const SweepSpec& spec) {
  const std::vector<LoadCase> cases = ultimate_load_cases(table, spec);
  std::vector<UltimateLoad> result;
  for (std::size_t k = 0; k < table.channels.size(); ++k) {
    for (const UltimateLoad::Sense sense : {UltimateLoad::Sense::maximum, UltimateLoad::Sense::minimum}) {
      const bool max = sense == UltimateLoad::Sense::maximum;
      std::optional<UltimateLoad> best;
      for (const LoadCase& lc : cases) {
        double sum = 0.0;
        const LoadTableRow* extreme_row = nullptr;
        const ChannelExtreme* extreme = nullptr;
        std::size_t n = 0;
        for (const LoadTableRow* row : lc.completed) {
          const std::optional<ChannelExtreme>& e = max ? row->maxima[k] : row->minima[k];
          if (!e) continue;
          ++n;
          sum += e->value;
          if (extreme == nullptr || (max ? e->value > extreme->value : e->value < extreme->value)) {
            extreme = &*e;
            extreme_row = row;
          }
        }
        if (n == 0) continue;
        UltimateLoad u;
        u.channel = k;
        u.sense = sense;
        u.realisations = n;
        u.mean_of_realisations = n >= kRealisationsForMean;
        u.characteristic_value = u.mean_of_realisations ? sum / static_cast<double>(n) : extreme->value;
        u.partial_safety_factor = is_load_unit(table.units[k]) ? lc.group->partial_safety_factor : 1.0;
        u.design_value = u.partial_safety_factor * u.characteristic_value;
        u.governing = extreme_row;
        u.time_s = extreme->time_s;
        u.concurrent = extreme->concurrent;
        // Larger maxima and smaller minima govern; ties keep the first load case.
        if (!best || (max ? u.design_value > best->design_value : u.design_value < best->design_value)) best = std::move(u);
      }
      if (best) result.push_back(std::move(*best));
    }
  }
  return result;
}

}  // namespace fowtsim::driver::sweep
