#include "run_scene.h"

#include <GL/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "gl_readback.h"
#include "png_io.h"

namespace pineda::bench {
namespace {

double drawTimed(BenchScene& scene, int frame) {
  const auto start = std::chrono::steady_clock::now();
  scene.draw(frame);
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 ? values[mid] : (values[mid - 1] + values[mid]) / 2;
}

// Draws frame 0 again with every fragment that reaches the stencil stage incrementing the
// stencil buffer (including those failing the depth test), then sums it.
void countFragments(BenchScene& scene, int width, int height, SceneResult& result) {
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glStencilMask(0xff);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_INCR, GL_INCR, GL_INCR);
  glEnable(GL_STENCIL_TEST);
  scene.draw(0);
  glDisable(GL_STENCIL_TEST);
  long fragments = 0;
  for (std::uint8_t count : tools::readStencil(width, height)) {
    fragments += count;
    result.fragmentsSaturated |= count == 255;
  }
  result.fragments = glGetError() == GL_NO_ERROR ? fragments : -1;
}

void reportGlError(const BenchSceneEntry& entry, const char* when) {
  if (GLenum glError = glGetError(); glError != GL_NO_ERROR)
    std::fprintf(stderr, "pineda-bench: scene %.*s raised GL error 0x%04x %s\n", int(entry.name.size()),
                 entry.name.data(), glError, when);
}

}  // namespace

bool runScene(const BenchSceneEntry& entry, const RunSettings& settings, const std::string& pngPath,
              SceneResult& result, std::string& error) {
  glViewport(0, 0, settings.width, settings.height);
  std::unique_ptr<BenchScene> scene = entry.create(settings.width, settings.height);
  reportGlError(entry, "during setup");
  result.scene = std::string(entry.name);
  result.triangles = scene->trianglesPerFrame();
  result.firstMs = drawTimed(*scene, 0);
  const tools::Image image = tools::readFramebuffer(settings.width, settings.height);
  reportGlError(entry, "in frame 0");

  std::vector<double> times;
  for (int frame = 1; frame <= settings.frames; ++frame) times.push_back(drawTimed(*scene, frame));
  result.medianMs = times.empty() ? result.firstMs : median(times);
  reportGlError(entry, "in the timed frames");
  if (scene->drawsWithStencil())
    result.fragments = -1;
  else
    countFragments(*scene, settings.width, settings.height, result);
  return tools::writePng(pngPath, image, error);
}

}  // namespace pineda::bench
