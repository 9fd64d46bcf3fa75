#include "local_run.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "egl_session.h"
#include "gl_readback.h"
#include "run_scene.h"

namespace pineda::bench {
namespace {

std::string pngPath(const Options& options, const BenchSceneEntry& entry) {
  return (std::filesystem::path(options.outDir) / (std::string(entry.name) + ".png")).string();
}

// Opens the session, after setting PINEDA_THREADS when asked (read when the driver starts).
bool openSession(const Options& options, tools::EglSession& session) {
  if (options.threads > 0) setenv("PINEDA_THREADS", std::to_string(options.threads).c_str(), 1);
  std::string error;
  if (!session.open(options.width, options.height, error)) {
    std::fprintf(stderr, "pineda-bench: %s\n", error.c_str());
    return false;
  }
  std::error_code ignored;
  std::filesystem::create_directories(options.outDir, ignored);
  return true;
}

}  // namespace

int runChildScene(const Options& options) {
  tools::EglSession session;
  if (!openSession(options, session)) return 1;
  std::printf("%.*s %s\n", int(kRendererTag.size()), kRendererTag.data(), tools::glString(GL_RENDERER));
  const BenchSceneEntry& entry = *findBenchScene(options.childScene);
  SceneResult result;
  std::string error;
  if (!runScene(entry, {options.width, options.height, options.frames}, pngPath(options, entry), result, error)) {
    std::fprintf(stderr, "pineda-bench: %s\n", error.c_str());
    return 1;
  }
  std::printf("%s\n", formatResultLine(result).c_str());
  return 0;
}

int runLocal(const Options& options) {
  tools::EglSession session;
  if (!openSession(options, session)) return 1;
  std::printf("GL_RENDERER: %s\n", tools::glString(GL_RENDERER));
  std::printf("size %dx%d; ms = median of %d frames after a warm-up frame 0 (draw + glFinish); first = frame 0\n"
              "Mpix/s counts the fragments rasterized per frame (stencil INCR count of frame 0); us/draw: the calling "
              "thread's time in the draw calls (before glFinish) per call, for the draw-call scenes; frame us/draw: "
              "the frame's time per call (held-back draws run at glFinish)\n",
              options.width, options.height, options.frames);
  std::printf("%-18s %10s %10s %9s %9s %12s %8s %8s  %s\n", "scene", "ms/frame", "first ms", "Mtri/s", "Mpix/s",
              "frags/frame", "us/draw", "frame us", "png");
  int failures = 0;
  bool first = true;
  for (const BenchSceneEntry* entry : selectedScenes(options)) {
    std::string error;
    if (!first && !session.freshContext(error)) {
      std::fprintf(stderr, "pineda-bench: %s\n", error.c_str());
      return 1;
    }
    first = false;
    SceneResult result;
    const std::string path = pngPath(options, *entry);
    if (!runScene(*entry, {options.width, options.height, options.frames}, path, result, error)) {
      std::fprintf(stderr, "pineda-bench: %s\n", error.c_str());
      ++failures;
    }
    char perDraw[16] = "-", framePerDraw[16] = "-";
    if (result.drawCalls > 0) {
      std::snprintf(perDraw, sizeof perDraw, "%.3f", microsecondsPerDraw(result));
      std::snprintf(framePerDraw, sizeof framePerDraw, "%.3f", frameMicrosecondsPerDraw(result));
    }
    std::printf("%-18s %10.3f %10.3f %9.3f %9.1f %11ld%s %8s %8s  %s\n", result.scene.c_str(), result.medianMs,
                result.firstMs, megaTrianglesPerSecond(result), megaPixelsPerSecond(result), result.fragments,
                result.fragmentsSaturated ? "+" : " ", perDraw, framePerDraw, path.c_str());
    std::fflush(stdout);
  }
  return failures ? 1 : 0;
}

}  // namespace pineda::bench
