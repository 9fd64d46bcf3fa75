// pineda-demo: renders the demo scenes headless through EGL and writes one PNG per scene.
#include <GL/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "egl_session.h"
#include "gl_readback.h"
#include "png_io.h"
#include "scene.h"

namespace pineda::demo {
namespace {

struct Options {
  std::string outDir = ".";
  int width = 512;
  int height = 512;
  int frames = 10;
  std::vector<std::string> scenes;
};

void usage(std::FILE* to) {
  std::fprintf(to,
               "usage: pineda-demo [--out DIR] [--size WxH] [--frames N] [--scene NAME]...\n"
               "scenes:");
  for (const SceneEntry& entry : allScenes()) std::fprintf(to, " %.*s", int(entry.name.size()), entry.name.data());
  std::fprintf(to, "\n");
}

bool parseOptions(int argc, char** argv, Options& options) {
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      usage(stdout);
      std::exit(0);
    }
    if (i + 1 >= argc) {
      std::fprintf(stderr, "pineda-demo: %s needs a value\n", arg.c_str());
      return false;
    }
    std::string value = argv[++i];
    if (arg == "--out") {
      options.outDir = value;
    } else if (arg == "--size") {
      if (std::sscanf(value.c_str(), "%dx%d", &options.width, &options.height) != 2 ||
          options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384) {
        std::fprintf(stderr, "pineda-demo: bad --size '%s' (want WxH)\n", value.c_str());
        return false;
      }
    } else if (arg == "--frames") {
      char* end = nullptr;
      long frames = std::strtol(value.c_str(), &end, 10);
      if (*end != '\0' || frames < 0 || frames > 1000000) {
        std::fprintf(stderr, "pineda-demo: bad --frames '%s'\n", value.c_str());
        return false;
      }
      options.frames = int(frames);
    } else if (arg == "--scene") {
      options.scenes.push_back(value);
    } else {
      std::fprintf(stderr, "pineda-demo: unknown option %s\n", arg.c_str());
      return false;
    }
  }
  for (const std::string& name : options.scenes) {
    bool known = std::any_of(allScenes().begin(), allScenes().end(),
                             [&](const SceneEntry& entry) { return entry.name == name; });
    if (!known) {
      std::fprintf(stderr, "pineda-demo: unknown scene '%s'\n", name.c_str());
      usage(stderr);
      return false;
    }
  }
  return true;
}

double drawTimed(Scene& scene, int frame) {
  auto start = std::chrono::steady_clock::now();
  scene.draw(frame);
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

int run(const Options& options) {
  std::string error;
  tools::EglSession session;
  if (!session.open(options.width, options.height, error)) {
    std::fprintf(stderr, "pineda-demo: %s\n", error.c_str());
    return 1;
  }
  std::printf("GL_RENDERER: %s\nGL_VERSION: %s\n", tools::glString(GL_RENDERER), tools::glString(GL_VERSION));
  std::filesystem::create_directories(options.outDir);
  std::printf("%-14s %-40s %16s %10s\n", "scene", "png", "median ms/frame", "first ms");

  int failures = 0;
  bool firstScene = true;
  for (const SceneEntry& entry : allScenes()) {
    if (!options.scenes.empty() &&
        std::find(options.scenes.begin(), options.scenes.end(), entry.name) == options.scenes.end())
      continue;
    // Each scene but the first gets a fresh context; a scene of another API always gets its own.
    if ((!firstScene || entry.api != tools::ContextApi::GL11) && !session.freshContext(error, entry.api)) {
      std::fprintf(stderr, "pineda-demo: %s\n", error.c_str());
      return 1;
    }
    firstScene = false;
    glViewport(0, 0, options.width, options.height);
    auto scene = entry.create(options.width, options.height);

    double firstMs = drawTimed(*scene, 0);
    tools::Image image = tools::readFramebuffer(options.width, options.height);
    std::string path = (std::filesystem::path(options.outDir) / (std::string(entry.name) + ".png")).string();
    if (!tools::writePng(path, image, error)) {
      std::fprintf(stderr, "pineda-demo: %s\n", error.c_str());
      ++failures;
    }
    if (GLenum glError = glGetError(); glError != GL_NO_ERROR)
      std::fprintf(stderr, "pineda-demo: scene %.*s raised GL error 0x%04x\n", int(entry.name.size()),
                   entry.name.data(), glError);

    std::vector<double> times;
    for (int frame = 1; frame <= options.frames; ++frame) times.push_back(drawTimed(*scene, frame));
    double median = firstMs;
    if (!times.empty()) {
      std::sort(times.begin(), times.end());
      std::size_t mid = times.size() / 2;
      median = times.size() % 2 ? times[mid] : (times[mid - 1] + times[mid]) / 2;
    }
    std::printf("%-14.*s %-40s %16.3f %10.3f\n", int(entry.name.size()), entry.name.data(), path.c_str(),
                median, firstMs);
    std::fflush(stdout);
  }
  return failures ? 1 : 0;
}

}  // namespace
}  // namespace pineda::demo

int main(int argc, char** argv) {
  pineda::demo::Options options;
  if (!pineda::demo::parseOptions(argc, argv, options)) return 2;
  return pineda::demo::run(options);
}
