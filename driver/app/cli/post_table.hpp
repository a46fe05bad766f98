#pragma once
// `fowtsim post` tables on screen (aligned columns) and as CSV (one row per file × channel, so the
// files of a sweep collect into one table; numbers with 17 significant digits, exact round trip).
#include <cstdio>
#include <filesystem>

#include "cli/post_results.hpp"

namespace fowtsim::driver {

void print_post_results(std::FILE* out, const PostResults& results);

// Statistics table to `path`; with a lifetime result also <stem>.lifetime.csv beside it. Throws
// InputError when a file cannot be written.
void write_post_csv(const std::filesystem::path& path, const PostResults& results);

}  // namespace fowtsim::driver
