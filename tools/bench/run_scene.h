#pragma once
// Times one scene in the current GL context and writes its frame 0 as a PNG.
#include <string>

#include "bench_scene.h"
#include "scene_result.h"

namespace pineda::bench {

struct RunSettings {
  int width = 0;
  int height = 0;
  int frames = 0;
};

// Returns false and sets `error` when the PNG cannot be written; GL errors are only reported
// on stderr.
bool runScene(const BenchSceneEntry& entry, const RunSettings& settings, const std::string& pngPath,
              SceneResult& result, std::string& error);

}  // namespace pineda::bench
