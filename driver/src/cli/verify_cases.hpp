#pragma once
// Named verification cases of `fowtsim verify` and benchmark cases of `fowtsim bench`.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/reports.hpp"

namespace fowtsim::driver {

std::vector<std::string> verification_case_names();
// Runs one case, printing its detail tables to `out`; returns its rows. Throws InputError for an
// unknown name.
std::vector<VerificationRow> run_verification_case(const std::string& name, std::FILE* out);

std::vector<std::string> benchmark_case_names();
void run_benchmark_case(const std::string& name, std::FILE* out);

// Where the reference data (../shared: reference/…) are read from by the beam cases.
void set_shared_dir(const std::filesystem::path& dir);

}  // namespace fowtsim::driver
