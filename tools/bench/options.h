#pragma once
// pineda-bench's command line.
#include <string>
#include <vector>

namespace pineda::bench {

struct Options {
  std::string outDir = "out/bench";
  int width = 1024;
  int height = 768;
  int frames = 30;                  // timed frames after the warm-up frame 0
  std::vector<std::string> scenes;  // empty: all
  int threads = 0;                  // 0: each driver's default
  bool compareLlvmpipe = false;
  bool reference = false;
  std::string libDir;       // Pineda's libraries; empty: <dir of the executable>/../lib
  std::string childScene;   // --child: render this one scene and print one result line
  int timeoutSeconds = 600;  // per child
  int rounds = 1;            // --compare/--reference: runs per scene and driver, the fastest kept
};

// Returns false (after printing why) on a bad command line; exits 0 after --help.
bool parseOptions(int argc, char** argv, Options& options);

struct BenchSceneEntry;
// The scenes named by --scene, in that order, or all of them.
std::vector<const BenchSceneEntry*> selectedScenes(const Options& options);

}  // namespace pineda::bench
