#pragma once
// --compare llvmpipe / --reference: every scene in child processes, once per driver, and a
// table of times and of Pineda's image error against the others.
#include "options.h"

namespace pineda::bench {

int runComparison(const Options& options);

}  // namespace pineda::bench
