#include "cli/sweep_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <map>

#include <fmt/format.h>

#include "fowtsim/wind/iec_conditions.hpp"
#include "run/interrupt.hpp"
#include "sweep/case_expansion.hpp"
#include "sweep/case_files.hpp"
#include "sweep/case_outcome.hpp"
#include "sweep/folder_lock.hpp"
#include "sweep/frequency_domain_screening.hpp"
#include "sweep/iec_presets.hpp"
#include "sweep/load_table.hpp"
#include "sweep/local_pool.hpp"
#include "sweep/slurm_job.hpp"
#include "sweep/sweep_spec.hpp"
#include "sweep/trim.hpp"

namespace fowtsim::driver {

namespace {

using namespace sweep;

// The product goal of issue 14: 1000 ten-minute cases in one hour on 2 cores.
constexpr double kGoalCases = 1000.0, kGoalCaseLength_s = 600.0, kGoalWall_s = 3600.0, kGoalCores = 2.0;
constexpr double kGoalRealTimePerCore = kGoalCases * kGoalCaseLength_s / kGoalWall_s / kGoalCores;  // ≈ 83

std::string clock_text(double seconds) {
  const auto s = static_cast<long>(std::lround(std::max(seconds, 0.0)));
  return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60) : fmt::format("{}:{:02}", s / 60, s % 60);
}

std::string optional_number(const std::optional<double>& v, const char* format = "{:g}") {
  return v ? fmt::format(fmt::runtime(format), *v) : "–";
}

std::optional<double> turbulence_sigma_m_s(const SweepCase& c, const TurbineClass& turbine) {
  std::string model;
  for (const DeckOverride& o : c.overrides)
    if (o.key_path == "wind.turbulence.model") model = o.yaml_value;
  if (model.empty() || !c.wind_speed_m_s) return std::nullopt;
  const wind::TurbulenceCategory category = wind::parse_turbulence_category(turbine.turbulence_class);
  if (model == "ETM") return wind::etm_sigma(category, turbine.wind_class, *c.wind_speed_m_s);
  if (model == "EWM") return wind::ewm_sigma(*c.wind_speed_m_s);
  return wind::ntm_sigma(category, *c.wind_speed_m_s);
}

void print_cases(std::FILE* out, const SweepSpec& spec, const std::vector<SweepCase>& cases) {
  fmt::print(out, "sweep {}: {} cases over {} (each {} s: {} s transient + {} s analysed)\n", spec.name, cases.size(),
             spec.base_deck.string(), spec.transient_s + spec.analysis_s, spec.transient_s, spec.analysis_s);
  fmt::print(out, "{:<32} {:>7} {:>7} {:>11} {:>11} {:>6} {:>6}  {}\n", "case", "V m/s", "σ1 m/s", "wind seed", "wave seed", "Hs m",
             "Tp s", "factors");
  for (const SweepCase& c : cases) {
    const LoadCaseGroup& g = spec.groups[c.group];
    // σ1 the generator draws for a preset's turbulent wind (NTM, ETM or EWM: fowtsim/wind/iec_conditions.hpp).
    const std::optional<double> sigma = g.preset.empty() ? std::nullopt : turbulence_sigma_m_s(c, spec.turbine);
    std::string factors = g.preset.empty() ? "" : g.preset;
    for (const auto& [label, value] : c.factors) factors += (factors.empty() ? "" : " ") + label + "=" + value;
    fmt::print(out, "{:<32} {:>7} {:>7} {:>11} {:>11} {:>6} {:>6}  {}\n", c.name, optional_number(c.wind_speed_m_s),
               optional_number(sigma, "{:.3f}"), c.wind_seed ? std::to_string(*c.wind_seed) : "–",
               c.wave_seed ? std::to_string(*c.wave_seed) : "–", optional_number(c.hs_m, "{:.3g}"), optional_number(c.tp_s, "{:.3g}"),
               factors);
  }
  // The table of contents of the basis: cases and simulated hours per load-case group.
  fmt::print(out, "\n{:<14} {:<8} {:>6} {:>10}  {}\n", "group", "preset", "cases", "sim. hours", "analysis, γ_f");
  for (std::size_t gi = 0; gi < spec.groups.size(); ++gi) {
    const LoadCaseGroup& g = spec.groups[gi];
    const auto n = std::count_if(cases.begin(), cases.end(), [&](const SweepCase& c) { return c.group == gi; });
    std::string analysis = g.ultimate ? fmt::format("U γ_f {}", g.partial_safety_factor) : "";
    if (g.fatigue) analysis += analysis.empty() ? "F" : ", F";
    fmt::print(out, "{:<14} {:<8} {:>6} {:>10.2f}  {}\n", g.name, g.preset.empty() ? "–" : g.preset, n,
               static_cast<double>(n) * (spec.transient_s + spec.analysis_s) / 3600.0, analysis);
  }
  fmt::print(out, "{:<14} {:<8} {:>6} {:>10.2f}\n", "total", "", cases.size(),
             static_cast<double>(cases.size()) * (spec.transient_s + spec.analysis_s) / 3600.0);
}

const char* case_end_word(int exit_code) {
  if (exit_code == 0) return "ended  ";
  if (exit_code == interrupted_exit_code(SIGINT) || exit_code == interrupted_exit_code(SIGTERM)) return "stopped";
  return "FAILED ";
}

const char* action_name(SweepRequest::Action action) {
  switch (action) {
    case SweepRequest::Action::run_local: return "local pool";
    case SweepRequest::Action::list: return "list";
    case SweepRequest::Action::slurm: return "Slurm submission";
    case SweepRequest::Action::collect: return "collect";
  }
  return "?";
}

// Removes the temporary outputs (CASE.running.h5, .running.out) that local runs killed outright left
// in cases/: under the folder lock no local case is running (each holds the lock while it lives),
// and the cases about to run would write over them anyway. Not for --slurm: a Slurm task does not
// hold the lock and may still be writing its temporary. Returns how many were removed.
std::size_t remove_dead_temporaries(const SweepLayout& layout) {
  std::size_t removed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(layout.root / "cases"))
    if (entry.path().stem().extension() == ".running" && std::filesystem::remove(entry.path())) ++removed;
  return removed;
}

// Cases whose output is not `completed` for their current deck.
std::vector<std::size_t> cases_to_run(const std::vector<SweepCase>& cases, const std::vector<std::string>& hashes,
                                      const SweepLayout& layout) {
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (read_case_outcome(layout, cases[i].name, hashes[i]).state != CaseState::completed) pending.push_back(i);
  return pending;
}

// Writes the table and prints where, and every case without a result with its exit code and reason.
int finish_with_table(std::FILE* out, const SweepSpec& spec, const std::vector<SweepCase>& cases,
                      const std::vector<std::string>& hashes, const SweepLayout& layout) {
  const LoadTable table = build_load_table(spec, cases, hashes, layout);
  write_load_table(table, layout.table_base());
  std::size_t completed = 0;
  for (const LoadTableRow& row : table.rows) completed += row.outcome.state == CaseState::completed;
  fmt::print(out, "  cases            {} completed of {}\n", completed, table.rows.size());
  for (const LoadTableRow& row : table.rows) {
    if (row.outcome.state == CaseState::completed) continue;
    fmt::print(out, "  {:<16} {}{}{}\n", state_name(row.outcome.state), row.case_->name,
               row.outcome.exit_code ? fmt::format(" (exit {})", *row.outcome.exit_code) : "",
               row.outcome.message.empty() ? "" : ": " + row.outcome.message);
  }
  for (const LifetimeRow& l : table.lifetime)
    if (l.load)
      fmt::print(out, "  lifetime DEL     {} (m = {}): {:.6g} {} over {} runs\n", l.channel.channel, l.channel.wohler_exponent,
                 l.load->damage_equivalent_load, table.fatigue_units[static_cast<std::size_t>(&l - table.lifetime.data())], l.runs);
  for (const std::string& note : table.notes) fmt::print(out, "  note             {}\n", note);
  fmt::print(out, "  load table       {0}.csv, {0}.h5, {0}.md\n", layout.table_base().string());
  return completed == table.rows.size() ? 0 : 1;
}

int run_local(std::FILE* out, const SweepRequest& request, const SweepSpec& spec, const std::vector<SweepCase>& cases,
              const std::vector<std::string>& hashes, const SweepLayout& layout, int lock_descriptor) {
  const std::vector<std::size_t> pending = cases_to_run(cases, hashes, layout);
  const double case_length_s = spec.transient_s + spec.analysis_s;
  fmt::print(out, "── fowtsim sweep {} ─────────────────────────────────\n", spec.name);
  fmt::print(out, "  cases            {} ({} completed earlier and skipped), {} to run in {} processes\n", cases.size(),
             cases.size() - pending.size(), pending.size(), request.jobs);
  if (const std::size_t removed = remove_dead_temporaries(layout))
    fmt::print(out, "  cleaned          {} temporary output(s) of runs killed earlier\n", removed);
  // Cases of one wind seed (the variants of a realisation that leave the field alone: yaw, fault
  // time, sea) share its generated field through a folder of the sweep, removed when the last of them
  // has ended (turbulence_cache.hpp): each field is generated once and at most one per open seed sits on disk.
  std::map<std::uint64_t, std::size_t> sharing;  // wind seed → pending cases with it
  for (const std::size_t i : pending)
    if (cases[i].wind_seed) ++sharing[*cases[i].wind_seed];
  std::erase_if(sharing, [](const auto& s) { return s.second < 2; });
  std::map<std::string, std::uint64_t> shared_seed;  // case → its shared wind seed
  std::vector<CaseCommand> commands;
  for (const std::size_t i : pending) {
    const std::string& name = cases[i].name;
    std::filesystem::remove(layout.exit_code(name));
    commands.push_back({name, {"run", layout.deck(name).string(), "-o", layout.output(name).string()}, layout.log(name), case_length_s});
    if (cases[i].wind_seed && sharing.contains(*cases[i].wind_seed)) {
      shared_seed[name] = *cases[i].wind_seed;
      std::vector<std::string>& arguments = commands.back().arguments;
      arguments.insert(arguments.end(), {"--turbulence-cache", layout.turbulence(*cases[i].wind_seed).string()});
    }
  }
  if (!sharing.empty())
    fmt::print(out, "  turbulence       {} field(s) shared by {} case(s), each generated once\n", sharing.size(), shared_seed.size());

  const bool terminal = isatty(fileno(out)) != 0;
  const InterruptHandlers handlers;
  std::size_t completed_now = 0;
  double completed_cpu_s = 0.0;
  const PoolReport report = run_pool(
      request.executable.empty() ? own_executable() : request.executable, commands, request.jobs,
      [&](const CaseExit& e) {
        write_exit_code(layout, e.name, e.exit_code);
        if (const auto s = shared_seed.find(e.name); s != shared_seed.end() && --sharing[s->second] == 0) {
          std::error_code ignored;
          std::filesystem::remove_all(layout.turbulence(s->second), ignored);
        }
        if (e.exit_code != 0) return;
        ++completed_now;
        completed_cpu_s += e.cpu_s;
      },
      [&](const PoolProgress& p) {
        const std::string line = fmt::format("{}/{} done, {} failed, {} running, {} queued, {} elapsed{}", p.done, commands.size(),
                                             p.failed, p.running, p.queued, clock_text(p.elapsed_s),
                                             p.eta_s >= 0 ? ", ETA " + clock_text(p.eta_s) : "");
        // One line for the sweep on a terminal; a line per ended case in a log.
        if (terminal)
          fmt::print(out, "\r  {:<78}", line);
        else if (!p.last_case.empty())
          fmt::print(out, "  {} {} (exit {}): {}\n", case_end_word(p.last_exit_code), p.last_case, p.last_exit_code, line);
        std::fflush(out);
      },
      lock_descriptor);
  if (terminal) fmt::print(out, "\n");
  std::error_code ignored;
  std::filesystem::remove(layout.turbulence_dir(), ignored);  // only if empty: an interrupted sweep keeps its fields
  if (report.interrupted_by)
    fmt::print(out, "  interrupted      by {}: finished cases are kept, the others run on the next `fowtsim sweep`\n",
               signal_name(report.interrupted_by));
  if (completed_now > 0) {
    // Simulated seconds per wall second of the whole pool: what sizes a load basis on this machine.
    const double throughput = static_cast<double>(completed_now) * case_length_s / report.wall_s;
    const double per_process = throughput / std::min<double>(request.jobs, static_cast<double>(commands.size()));
    fmt::print(out, "  throughput       {:.1f} simulated s per wall s ({} cases in {:.1f} s, {:.1f}× real time per process)\n",
               throughput, completed_now, report.wall_s, per_process);
    // Per CPU second the figure does not depend on what else runs on the machine.
    const double per_cpu_second = static_cast<double>(completed_now) * case_length_s / completed_cpu_s;
    fmt::print(out, "  CPU time         {:.1f} s: {:.1f} simulated s per CPU s\n", completed_cpu_s, per_cpu_second);
    fmt::print(out, "  product goal     1000 ten-minute cases in 1 h on 2 cores = {:.0f}× real time per core: this sweep reaches "
               "{:.2f}× of it per process, {:.2f}× per CPU second\n",
               kGoalRealTimePerCore, per_process / kGoalRealTimePerCore, per_cpu_second / kGoalRealTimePerCore);
  }
  const int status = finish_with_table(out, spec, cases, hashes, layout);
  return report.interrupted_by ? interrupted_exit_code(report.interrupted_by) : status;
}

int run_slurm(std::FILE* out, const SweepRequest& request, const SweepSpec& spec, const std::vector<SweepCase>& cases,
              const std::vector<std::string>& hashes, const SweepLayout& layout) {
  std::vector<std::string> names;
  for (const std::size_t i : cases_to_run(cases, hashes, layout)) {
    names.push_back(cases[i].name);
    std::filesystem::remove(layout.exit_code(cases[i].name));
  }
  fmt::print(out, "── fowtsim sweep {} (Slurm) ─────────────────────────\n", spec.name);
  fmt::print(out, "  cases            {} ({} completed earlier and skipped), {} to run\n", cases.size(), cases.size() - names.size(),
             names.size());
  if (names.empty()) return finish_with_table(out, spec, cases, hashes, layout);
  const SlurmJob job = write_slurm_job(spec.name, layout, names, request.executable.empty() ? own_executable() : request.executable,
                                       merge_slurm_options(spec.slurm, request.slurm));
  std::string command;
  for (const std::string& word : sbatch_command(job)) command += (command.empty() ? "" : " ") + word;
  fmt::print(out, "  job array        {} tasks of {} case(s): {}\n", job.tasks, std::max(1, request.slurm.cases_per_task), job.script.string());
  if (request.dry_run) {
    fmt::print(out, "  dry run          submit with: {}\n", command);
    return 0;
  }
  const std::string job_id = submit_slurm_job(job);
  fmt::print(out, "  submitted        job {}; when it has run: fowtsim sweep {} --collect{}\n", job_id, request.spec.string(),
             request.output_dir ? " --output-dir " + request.output_dir->string() : "");
  return 0;
}


// The steady runs of `sweep.trim` (trim.hpp), run here whatever the action (they are short), cached
// in OUTPUT_DIR/trim; then their operating points go into the cases. Throws when one fails.
void trim_cases_in_place(std::FILE* out, const SweepRequest& request, const SweepSpec& spec, const BaseDeckFacts& base,
                         std::vector<SweepCase>& cases, const SweepLayout& layout, int lock_descriptor) {
  const std::vector<SweepCase> runs = trim_cases(spec, cases);
  if (runs.empty()) return;
  const SweepLayout trims = trim_layout(layout);
  trims.create_directories();
  const std::vector<std::string> hashes = write_case_decks(spec, runs, trims);
  std::vector<CaseCommand> commands;
  for (const std::size_t i : cases_to_run(runs, hashes, trims))
    commands.push_back({runs[i].name, {"run", trims.deck(runs[i].name).string(), "-o", trims.output(runs[i].name).string()},
                        trims.log(runs[i].name), spec.trim->duration_s});
  fmt::print(out, "  trim             {} steady run(s) of {} s ({} cached), one per wind speed\n", runs.size(), spec.trim->duration_s,
             runs.size() - commands.size());
  std::fflush(out);
  if (!commands.empty()) {
    const InterruptHandlers handlers;
    const PoolReport report = run_pool(request.executable.empty() ? own_executable() : request.executable, commands, request.jobs,
                                       [&](const CaseExit& e) { write_exit_code(trims, e.name, e.exit_code); }, [](const PoolProgress&) {},
                                       lock_descriptor);
    if (report.interrupted_by) throw InputError({"sweep", std::nullopt, "trim", "rerun the sweep"}, "interrupted during the trim runs");
  }
  std::map<double, OperatingPoint> points;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const CaseOutcome outcome = read_case_outcome(trims, runs[i].name, hashes[i]);
    if (outcome.state != CaseState::completed)
      throw InputError({"sweep", std::nullopt, "trim", "see " + trims.log(runs[i].name).string()},
                       fmt::format("the trim run {} did not complete ({}): {}", runs[i].name, state_name(outcome.state), outcome.message));
    points[*runs[i].wind_speed_m_s] = read_operating_point(trims.output(runs[i].name), *spec.trim);
  }
  apply_trim(cases, points, base.rayleigh_ritz_blades);
}

}  // namespace

int run_sweep_command(const SweepRequest& request, std::FILE* out) {
  SweepSpec spec = read_sweep_spec(request.spec);
  if (request.output_dir) spec.output_dir = *request.output_dir;
  if (request.base_deck) spec.base_deck = std::filesystem::absolute(*request.base_deck);
  const BaseDeckFacts base = read_base_deck_facts(spec.base_deck);
  std::vector<SweepCase> cases = expand_cases(spec, base);
  const SweepLayout layout{spec.output_dir};
  if (request.frequency_domain) return screen_sweep(out, spec, cases);
  if (request.action == SweepRequest::Action::list) {
    check_case_decks(spec, cases, layout);  // a case `fowtsim run` would reject shows here, not after hours of others
    print_cases(out, spec, cases);
    if (spec.trim)
      fmt::print(out, "trim: {} steady run(s) of {} s before the cases set the initial conditions of {} operating case(s)\n",
                 trim_cases(spec, cases).size(), spec.trim->duration_s,
                 std::count_if(cases.begin(), cases.end(), [](const SweepCase& c) { return is_trimmed(c); }));
    return 0;
  }
  // One sweep per folder, before any file in it changes (folder_lock.hpp).
  const SweepFolderLock lock(layout.root, fmt::format("fowtsim sweep {} ({})", request.spec.string(), action_name(request.action)), out);
  layout.create_directories();
  claim_base_deck(layout, spec.base_deck);
  if (spec.trim) trim_cases_in_place(out, request, spec, base, cases, layout, lock.descriptor());
  const std::vector<std::string> hashes = write_case_decks(spec, cases, layout);
  switch (request.action) {
    case SweepRequest::Action::collect:
      fmt::print(out, "── fowtsim sweep {} (collect) ───────────────────────\n", spec.name);
      return finish_with_table(out, spec, cases, hashes, layout);
    case SweepRequest::Action::slurm: return run_slurm(out, request, spec, cases, hashes, layout);
    case SweepRequest::Action::run_local: return run_local(out, request, spec, cases, hashes, layout, lock.descriptor());
    case SweepRequest::Action::list: break;
  }
  return 0;
}

}  // namespace fowtsim::driver
