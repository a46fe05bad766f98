#pragma once
// Named verification cases of `fowtsim verify` and benchmark cases of `fowtsim bench`.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "verify/reports.hpp"

namespace fowtsim::driver {

std::vector<std::string> verification_case_names();

// A case that ran no check, and why (e.g. its reference data are absent).
struct SkippedCase {
  std::string case_name;
  std::string reason;
};
// What `fowtsim verify` found: the rows of every check that ran, and the cases that ran none.
struct VerificationOutcome {
  std::vector<VerificationRow> rows;
  std::vector<SkippedCase> skipped;
  // 0 when at least one check ran and every check passed; 1 when one failed or none ran.
  int exit_code() const;
};
// Runs `cases` (empty or {"all"}: every case) with the reference data under `shared_dir`,
// printing each case's detail tables to `out`.
VerificationOutcome run_verification(std::vector<std::string> cases, const std::filesystem::path& shared_dir,
                                     std::FILE* out);
// The table of rows, one SKIPPED line per skipped case, and the verdict line.
void print_verification_outcome(std::FILE* out, const VerificationOutcome& outcome);

// The repository this binary was built from, and the reference-data folder next to it
// (<repository>/../shared): the default of --shared, whatever the current folder.
std::filesystem::path source_root();
std::filesystem::path default_shared_dir();
// Runs one case, printing its detail tables to `out`; returns its rows. Throws InputError for an
// unknown name.
std::vector<VerificationRow> run_verification_case(const std::string& name, std::FILE* out);

std::vector<std::string> benchmark_case_names();
void run_benchmark_case(const std::string& name, std::FILE* out);

// Where the reference data (../shared: reference/…) are read from by the beam and turbine cases.
void set_shared_dir(const std::filesystem::path& dir);
const std::filesystem::path& shared_dir();

// A shipped input deck: inputs/<relative> under the working directory when run from the source
// tree, else the source tree this binary was built from.
std::filesystem::path source_input(const std::string& relative);

}  // namespace fowtsim::driver
