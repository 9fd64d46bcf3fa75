#pragma once
// Runs scenes in this process on whichever driver the library path selected; --child mode
// is the same for one scene, printing the machine-readable line instead of the table.
#include "options.h"

namespace pineda::bench {

int runLocal(const Options& options);
int runChildScene(const Options& options);

}  // namespace pineda::bench
