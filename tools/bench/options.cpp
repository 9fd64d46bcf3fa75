#include "options.h"

#include <cstdio>
#include <cstdlib>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

void usage(std::FILE* to) {
  std::fprintf(to,
      "usage: pineda-bench [--size WxH] [--frames N] [--out DIR] [--scene NAME]... [--threads N]\n"
      "                    [--compare llvmpipe] [--reference] [--rounds N] [--lib DIR]\n"
      "                    [--timeout SECONDS]\n"
      "\n"
      "Times GL scenes (fixed function and GLSL 1.20) headless through EGL: per scene the median\n"
      "ms/frame of N frames (default 30) after a warm-up frame 0 (frame = draw + glFinish), frame\n"
      "0's time, Mtri/s, Mpix/s (pixels = fragments rasterized in frame 0, counted with stencil\n"
      "INCR), and frame 0 as DIR/SCENE.png (default DIR out/bench, size 1024x768).\n"
      "\n"
      "Without --compare or --reference, scenes run in this process on whichever driver the\n"
      "library path selects (LD_LIBRARY_PATH=build/lib for Pineda).\n"
      "  --compare llvmpipe  run every scene in a child process on Pineda (LD_LIBRARY_PATH=--lib,\n"
      "                      default <bin>/../lib) and on Mesa llvmpipe, compare the images, print\n"
      "                      a table; images in DIR/{pineda,llvmpipe,diff}/\n"
      "  --reference         also run Pineda with PINEDA_REFERENCE=1 (its exact reference mode)\n"
      "                      and report Pineda's error against it (DIR/{reference,diff-reference}/).\n"
      "                      Pineda honours PINEDA_REFERENCE only once the driver implements it;\n"
      "                      until then both runs are the same renderer.\n"
      "  --threads N         PINEDA_THREADS=N for Pineda (and LP_NUM_THREADS=N for llvmpipe)\n"
      "  --rounds N          with --compare or --reference: run each scene N times on each driver,\n"
      "                      the drivers taking turns, and report each driver's fastest run (on a\n"
      "                      machine whose speed varies from minute to minute; default 1)\n"
      "  --timeout SECONDS   per child process (default 600)\n"
      "  --child NAME        internal: render one scene, print one 'pineda-bench-result' line\n"
      "\n"
      "scenes:\n");
  for (const BenchSceneEntry& entry : allBenchScenes())
    std::fprintf(to, "  %-14.*s %.*s\n", int(entry.name.size()), entry.name.data(), int(entry.description.size()),
                 entry.description.data());
}

bool parseInt(const std::string& text, long low, long high, int& value) {
  char* end = nullptr;
  long parsed = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || parsed < low || parsed > high) return false;
  value = int(parsed);
  return true;
}

}  // namespace

bool parseOptions(int argc, char** argv, Options& options) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      usage(stdout);
      std::exit(0);
    }
    if (arg == "--reference") {
      options.reference = true;
      continue;
    }
    if (i + 1 >= argc) {
      std::fprintf(stderr, "pineda-bench: %s needs a value (see --help)\n", arg.c_str());
      return false;
    }
    const std::string value = argv[++i];
    bool ok = true;
    if (arg == "--out") {
      options.outDir = value;
    } else if (arg == "--size") {
      ok = std::sscanf(value.c_str(), "%dx%d", &options.width, &options.height) == 2 && options.width >= 1 &&
           options.height >= 1 && options.width <= 16384 && options.height <= 16384;
    } else if (arg == "--frames") {
      ok = parseInt(value, 0, 1000000, options.frames);
    } else if (arg == "--threads") {
      ok = parseInt(value, 1, 1024, options.threads);
    } else if (arg == "--rounds") {
      ok = parseInt(value, 1, 100, options.rounds);
    } else if (arg == "--timeout") {
      ok = parseInt(value, 1, 86400, options.timeoutSeconds);
    } else if (arg == "--scene") {
      options.scenes.push_back(value);
    } else if (arg == "--child") {
      options.childScene = value;
    } else if (arg == "--lib") {
      options.libDir = value;
    } else if (arg == "--compare") {
      ok = value == "llvmpipe";
      options.compareLlvmpipe = ok;
    } else {
      std::fprintf(stderr, "pineda-bench: unknown option %s (see --help)\n", arg.c_str());
      return false;
    }
    if (!ok) {
      std::fprintf(stderr, "pineda-bench: bad value '%s' for %s (see --help)\n", value.c_str(), arg.c_str());
      return false;
    }
  }
  if (!options.childScene.empty()) options.scenes = {options.childScene};
  for (const std::string& name : options.scenes) {
    if (!findBenchScene(name)) {
      std::fprintf(stderr, "pineda-bench: unknown scene '%s'\n", name.c_str());
      usage(stderr);
      return false;
    }
  }
  return true;
}

std::vector<const BenchSceneEntry*> selectedScenes(const Options& options) {
  std::vector<const BenchSceneEntry*> scenes;
  if (options.scenes.empty())
    for (const BenchSceneEntry& entry : allBenchScenes()) scenes.push_back(&entry);
  else
    for (const std::string& name : options.scenes) scenes.push_back(findBenchScene(name));
  return scenes;
}

}  // namespace pineda::bench
