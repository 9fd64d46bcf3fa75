// pineda-bench: times standard GL 1.1 scenes headless through EGL, on Pineda or on Mesa
// llvmpipe, and compares the two (time per frame against image error). See --help.
#include "compare_run.h"
#include "local_run.h"
#include "options.h"

int main(int argc, char** argv) {
  pineda::bench::Options options;
  if (!pineda::bench::parseOptions(argc, argv, options)) return 2;
  if (!options.childScene.empty()) return pineda::bench::runChildScene(options);
  if (options.compareLlvmpipe || options.reference) return pineda::bench::runComparison(options);
  return pineda::bench::runLocal(options);
}
