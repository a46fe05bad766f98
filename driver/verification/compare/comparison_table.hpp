#pragma once
// The table `fowtsim compare` prints: one line per compared channel, a pass count, the channels
// not compared with why, and the channels of one file only summarised in one line each way.
#include <cstdio>

#include "compare/channel_compare.hpp"

namespace fowtsim::driver {

void print_comparison(std::FILE* out, const ComparisonReport& report);

}  // namespace fowtsim::driver
