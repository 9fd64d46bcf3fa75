#pragma once
// What one scene's run measured, and the one-line form a --child prints it in.
#include <optional>
#include <string>
#include <string_view>

namespace pineda::bench {

struct SceneResult {
  std::string scene;
  double medianMs = 0;  // median of the timed frames (frame 0's time when there are none)
  double firstMs = 0;   // frame 0, the warm-up frame
  long triangles = 0;   // submitted per frame
  long fragments = -1;  // rasterized in frame 0; -1 when they could not be counted
  bool fragmentsSaturated = false;  // some pixel took 255+ fragments: a lower bound
  long drawCalls = 0;       // per frame, for the scenes that report them
  double submitMs = 0;      // median of the timed frames' draw calls alone, before glFinish
};

// The calling thread's microseconds per draw call (submitMs over drawCalls); 0 when not reported.
// Pineda holds back draws made with nothing changed since the last and runs them at a later call
// (a later draw, or glFinish): the work of the last ones is outside the calls' time, inside the
// frame's.
double microsecondsPerDraw(const SceneResult& result);
// The frame's wall-clock microseconds per draw call (medianMs over drawCalls).
double frameMicrosecondsPerDraw(const SceneResult& result);

double megaTrianglesPerSecond(const SceneResult& result);
double megaPixelsPerSecond(const SceneResult& result);  // 0 when fragments are unknown

constexpr std::string_view kResultTag = "pineda-bench-result";
constexpr std::string_view kRendererTag = "pineda-bench-renderer";

std::string formatResultLine(const SceneResult& result);
// Finds the result line in a child's output.
std::optional<SceneResult> parseResultLine(std::string_view output);
std::string parseRenderer(std::string_view output);

}  // namespace pineda::bench
