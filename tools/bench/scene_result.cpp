#include "scene_result.h"

#include <cstdio>
#include <sstream>

namespace pineda::bench {
namespace {

std::string_view lineAfter(std::string_view output, std::string_view tag) {
  std::size_t start = 0;
  while (start < output.size()) {
    std::size_t end = output.find('\n', start);
    if (end == std::string_view::npos) end = output.size();
    std::string_view line = output.substr(start, end - start);
    if (line.substr(0, tag.size()) == tag && line.size() > tag.size() && line[tag.size()] == ' ')
      return line.substr(tag.size() + 1);
    start = end + 1;
  }
  return {};
}

}  // namespace

double megaTrianglesPerSecond(const SceneResult& result) {
  return result.medianMs > 0 ? double(result.triangles) / (result.medianMs * 1000.0) : 0;
}

double megaPixelsPerSecond(const SceneResult& result) {
  return result.medianMs > 0 && result.fragments >= 0 ? double(result.fragments) / (result.medianMs * 1000.0) : 0;
}

double microsecondsPerDraw(const SceneResult& result) {
  return result.drawCalls > 0 ? result.submitMs * 1000.0 / double(result.drawCalls) : 0;
}

double frameMicrosecondsPerDraw(const SceneResult& result) {
  return result.drawCalls > 0 ? result.medianMs * 1000.0 / double(result.drawCalls) : 0;
}

std::string formatResultLine(const SceneResult& result) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, "%.*s %s %.6f %.6f %ld %ld %d %ld %.6f", int(kResultTag.size()),
                kResultTag.data(), result.scene.c_str(), result.medianMs, result.firstMs, result.triangles,
                result.fragments, result.fragmentsSaturated ? 1 : 0, result.drawCalls, result.submitMs);
  return buffer;
}

std::optional<SceneResult> parseResultLine(std::string_view output) {
  std::istringstream line{std::string(lineAfter(output, kResultTag))};
  SceneResult result;
  int saturated = 0;
  if (!(line >> result.scene >> result.medianMs >> result.firstMs >> result.triangles >> result.fragments >> saturated >>
        result.drawCalls >> result.submitMs))
    return std::nullopt;
  result.fragmentsSaturated = saturated != 0;
  return result;
}

std::string parseRenderer(std::string_view output) { return std::string(lineAfter(output, kRendererTag)); }

}  // namespace pineda::bench
