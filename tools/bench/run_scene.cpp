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

struct FrameTimes {
  double submitMs;  // the draw calls alone, on the calling thread
  double frameMs;   // the draw calls and glFinish
};

FrameTimes drawTimed(BenchScene& scene, int frame) {
  using Clock = std::chrono::steady_clock;
  const auto ms = [](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
  const auto start = Clock::now();
  scene.draw(frame);
  const auto submitted = Clock::now();
  glFinish();
  return {ms(submitted - start), ms(Clock::now() - start)};
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
  result.drawCalls = scene->drawCallsPerFrame();
  result.firstMs = drawTimed(*scene, 0).frameMs;
  const tools::Image image = tools::readFramebuffer(settings.width, settings.height);
  reportGlError(entry, "in frame 0");

  std::vector<double> times, submitTimes;
  for (int frame = 1; frame <= settings.frames; ++frame) {
    const FrameTimes t = drawTimed(*scene, frame);
    times.push_back(t.frameMs);
    submitTimes.push_back(t.submitMs);
  }
  result.medianMs = times.empty() ? result.firstMs : median(times);
  result.submitMs = submitTimes.empty() ? 0 : median(submitTimes);
  reportGlError(entry, "in the timed frames");
  if (scene->drawsWithStencil())
    result.fragments = -1;
  else
    countFragments(*scene, settings.width, settings.height, result);
  return tools::writePng(pngPath, image, error);
}

}  // namespace pineda::bench
