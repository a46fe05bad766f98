#pragma once
// Where a sweep keeps its files, and the case decks: each case is a small YAML deck that includes
// the base deck and sets its own keys over it (io::load_deck: an including mapping's own keys
// override the included ones), so `fowtsim run decks/CASE.yaml` reruns any case alone.
//   OUTPUT_DIR/decks/CASE.yaml    the case deck
//   OUTPUT_DIR/cases/CASE.h5      its output (CASE.running.h5 while it runs)
//   OUTPUT_DIR/logs/CASE.log      what `fowtsim run` printed;  logs/CASE.exit  its exit code
//   OUTPUT_DIR/slurm/             the job-array script, its case list and Slurm's logs
//   OUTPUT_DIR/load_table.{h5,csv,md}
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sweep/case_expansion.hpp"
#include "sweep/sweep_spec.hpp"

namespace fowtsim::driver::sweep {

struct SweepLayout {
  std::filesystem::path root;  // the sweep's output folder

  std::filesystem::path deck(const std::string& c) const { return root / "decks" / (c + ".yaml"); }
  std::filesystem::path output(const std::string& c) const { return root / "cases" / (c + ".h5"); }
  std::filesystem::path running_output(const std::string& c) const { return root / "cases" / (c + ".running.h5"); }
  std::filesystem::path log(const std::string& c) const { return root / "logs" / (c + ".log"); }
  std::filesystem::path exit_code(const std::string& c) const { return root / "logs" / (c + ".exit"); }
  std::filesystem::path slurm_dir() const { return root / "slurm"; }
  std::filesystem::path table_base() const { return root / "load_table"; }
  std::filesystem::path base_deck_record() const { return root / "base_deck.txt"; }
  // Generated turbulence fields the cases of one wind seed share while they run (run --turbulence-cache).
  std::filesystem::path turbulence_dir() const { return root / "turbulence"; }
  std::filesystem::path turbulence(std::uint64_t wind_seed) const { return turbulence_dir() / std::to_string(wind_seed); }
  void create_directories() const;
};

// Binds the folder to the base deck its cases include: the first sweep into it records the deck
// (absolute path); a later one with another base deck (a `--base-deck` forgotten or added) stops
// with InputError before any case deck is rewritten — it would rerun every case on another model
// and replace the load table. A folder from before the record is bound by its next sweep.
void claim_base_deck(const SweepLayout& layout, const std::filesystem::path& base_deck);

// The YAML text of a case deck: a comment saying what it is, `include:` of the base deck (relative
// to the decks folder) and the case's overrides as nested mappings.
std::string case_deck_text(const SweepSpec& spec, const SweepCase& c, const std::filesystem::path& deck_dir);

// Writes every case deck and returns their deck hashes (what `fowtsim run` records as deck_hash),
// after checking each as `fowtsim run` would read it (run/validate_deck.hpp): every problem of
// every case is reported together, naming the case; a schema problem in a key the spec sets is
// reported at its line in the spec (io::DeckError); a rule across keys of a scene (pitch limits,
// rotor geometry) names the case and its deck's file:line and keys (InputError).
std::vector<std::string> write_case_decks(const SweepSpec& spec, const std::vector<SweepCase>& cases, const SweepLayout& layout);

// The same check without writing into the output folder (--list): the decks go to a temporary
// folder, removed after; problems are reported where the sweep would write them (same lines).
void check_case_decks(const SweepSpec& spec, const std::vector<SweepCase>& cases, const SweepLayout& layout);

// A case's exit code as `fowtsim run` returned it (logs/CASE.exit), written by whoever ran it.
void write_exit_code(const SweepLayout& layout, const std::string& case_name, int exit_code);

}  // namespace fowtsim::driver::sweep
