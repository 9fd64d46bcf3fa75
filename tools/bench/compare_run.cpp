#include "compare_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "bench_scene.h"
#include "child_process.h"
#include "image_compare.h"
#include "png_io.h"
#include "scene_result.h"

namespace pineda::bench {
namespace {

namespace fs = std::filesystem;

struct Driver {
  std::string name;  // also the folder of its images
  std::vector<EnvChange> env;
};

struct DriverOutcome {
  std::optional<SceneResult> result;
  std::string renderer;
  std::string png;
};

std::vector<EnvChange> pinedaEnv(const Options& options, const std::string& libDir, bool reference) {
  std::vector<EnvChange> env = {{"LD_LIBRARY_PATH", libDir}, {"LD_PRELOAD", std::nullopt}};
  if (options.threads > 0) env.push_back({"PINEDA_THREADS", std::to_string(options.threads)});
  env.push_back({"PINEDA_REFERENCE", reference ? std::optional<std::string>("1") : std::nullopt});
  return env;
}

std::vector<EnvChange> llvmpipeEnv(const Options& options) {
  std::vector<EnvChange> env = {{"LD_LIBRARY_PATH", std::nullopt}, {"LD_PRELOAD", std::nullopt},
                                {"LIBGL_ALWAYS_SOFTWARE", "1"},    {"GALLIUM_DRIVER", "llvmpipe"},
                                {"EGL_PLATFORM", "surfaceless"}};
  if (options.threads > 0) env.push_back({"LP_NUM_THREADS", std::to_string(options.threads)});
  return env;
}

// Returns an empty string (after saying why) when Pineda's libraries are not there: glvnd would
// silently fall back to Mesa and the "Pineda" column would be llvmpipe.
std::string findLibDir(const Options& options) {
  fs::path dir = options.libDir.empty() ? fs::path(selfExecutable()).parent_path().parent_path() / "lib"
                                        : fs::path(options.libDir);
  std::error_code error;
  dir = fs::absolute(dir, error);
  if (!fs::exists(dir / "libEGL.so.1", error)) {
    std::fprintf(stderr, "pineda-bench: no libEGL.so.1 in %s; build the 'pineda' target or pass --lib DIR\n",
                 dir.c_str());
    return {};
  }
  return dir.string();
}

DriverOutcome runOn(const Options& options, const Driver& driver, const BenchSceneEntry& entry) {
  DriverOutcome outcome;
  const fs::path dir = fs::path(options.outDir) / driver.name;
  std::error_code ignored;
  fs::create_directories(dir, ignored);
  outcome.png = (dir / (std::string(entry.name) + ".png")).string();
  fs::remove(outcome.png, ignored);
  char size[32];
  std::snprintf(size, sizeof size, "%dx%d", options.width, options.height);
  const std::vector<std::string> args = {"--child", std::string(entry.name), "--size", size,
                                         "--frames", std::to_string(options.frames), "--out", dir.string()};
  ChildOutcome child = runChild(selfExecutable(), args, driver.env, options.timeoutSeconds);
  outcome.renderer = parseRenderer(child.output);
  if (!child.succeeded) {
    std::fprintf(stderr, "pineda-bench: %s on %s failed: %s\n", std::string(entry.name).c_str(),
                 driver.name.c_str(), child.failure.c_str());
    return outcome;
  }
  if (driver.name != "llvmpipe" && outcome.renderer.find("llvmpipe") != std::string::npos) {
    std::fprintf(stderr, "pineda-bench: the %s run got Mesa (%s), not Pineda\n", driver.name.c_str(),
                 outcome.renderer.c_str());
    return outcome;
  }
  outcome.result = parseResultLine(child.output);
  if (!outcome.result)
    std::fprintf(stderr, "pineda-bench: %s on %s printed no result line\n", std::string(entry.name).c_str(),
                 driver.name.c_str());
  return outcome;
}

// The best of a driver's runs of one scene (--rounds): the run with the lowest median; a
// failed run ends that driver's turns and is what is kept.
struct BestOutcome {
  DriverOutcome best;
  bool ran = false;
  void take(DriverOutcome&& outcome) {
    if (!ran || (best.result && (!outcome.result || outcome.result->medianMs < best.result->medianMs)))
      best = std::move(outcome);
    ran = true;
  }
  bool done() const { return ran && !best.result; }
};

// Pineda's image against `other`'s; writes where they differ to OUT/<diffFolder>/SCENE.png.
std::optional<tools::ImageDifference> imageError(const Options& options, const DriverOutcome& pineda,
                                                 const DriverOutcome& other, const std::string& diffFolder,
                                                 const BenchSceneEntry& entry) {
  if (!pineda.result || !other.result) return std::nullopt;
  tools::Image a, b, diff;
  std::string error;
  if (!tools::readPng(pineda.png, a, error) || !tools::readPng(other.png, b, error)) {
    std::fprintf(stderr, "pineda-bench: %s\n", error.c_str());
    return std::nullopt;
  }
  if (a.width != b.width || a.height != b.height) return std::nullopt;
  tools::ImageDifference difference = tools::compareImages(a, b, &diff);
  const fs::path dir = fs::path(options.outDir) / diffFolder;
  std::error_code ignored;
  fs::create_directories(dir, ignored);
  if (!tools::writePng((dir / (std::string(entry.name) + ".png")).string(), diff, error))
    std::fprintf(stderr, "pineda-bench: %s\n", error.c_str());
  return difference;
}

std::string number(const std::optional<SceneResult>& result, double SceneResult::*field) {
  if (!result) return "FAILED";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", (*result).*field);
  return buffer;
}

void printError(const std::optional<tools::ImageDifference>& difference) {
  if (!difference) {
    std::printf(" %8s %9s %8s", "-", "-", "-");
    return;
  }
  char psnr[16];
  if (std::isinf(difference->psnr))
    std::snprintf(psnr, sizeof psnr, "inf");
  else
    std::snprintf(psnr, sizeof psnr, "%.2f", difference->psnr);
  std::printf(" %8d %9.4f %8s", difference->maxDiff, 100.0 * difference->differShare, psnr);
}

// Both drivers rasterize the same geometry, so their fragment counts should agree closely;
// a gap points at coverage (fill rule, clipping) rather than at shading.
void noteFragmentCounts(const SceneResult& pineda, const SceneResult& llvmpipe) {
  if (pineda.fragments < 0 || llvmpipe.fragments < 0) return;
  const double gap = std::abs(double(pineda.fragments - llvmpipe.fragments));
  if (gap > 0.001 * double(std::max(pineda.fragments, llvmpipe.fragments)))
    std::printf("  note: fragments per frame differ: Pineda %ld, llvmpipe %ld\n", pineda.fragments,
                llvmpipe.fragments);
}

// The draw-call scenes: the calling thread's time per call (the calls alone, before glFinish),
// and the frame's time per call (microsecondsPerDraw: Pineda runs held-back draws at glFinish).
void notePerDraw(const SceneResult& pineda, const std::optional<SceneResult>& llvmpipe) {
  if (pineda.drawCalls <= 0) return;
  std::printf("  note: %ld draw calls a frame; calling thread us/draw: Pineda %.3f", pineda.drawCalls,
              microsecondsPerDraw(pineda));
  if (llvmpipe) std::printf(", llvmpipe %.3f", microsecondsPerDraw(*llvmpipe));
  std::printf("; frame us/draw: Pineda %.3f", frameMicrosecondsPerDraw(pineda));
  if (llvmpipe) std::printf(", llvmpipe %.3f", frameMicrosecondsPerDraw(*llvmpipe));
  std::printf("\n");
}

void printHeader(const Options& options) {
  std::printf("size %dx%d; ms = median of %d frames after a warm-up frame 0 (frame = draw + glFinish); "
              "first = frame 0's ms\n",
              options.width, options.height, options.frames);
  if (options.rounds > 1)
    std::printf("each driver's fastest of %d runs per scene (lowest median), the drivers taking turns\n",
                options.rounds);
  std::printf("Mtri/s and Mpix/s are Pineda's; pixels = fragments rasterized per frame, counted in frame 0 "
              "with stencil INCR (depth-rejected fragments included)\n");
  if (options.compareLlvmpipe)
    std::printf("ratio = llvmpipe ms / Pineda ms: > 1 means Pineda is faster. "
                "max/differ%%/PSNR: Pineda's frame 0 against llvmpipe's\n");
  if (options.reference)
    std::printf("ref: Pineda with PINEDA_REFERENCE=1; ref max/differ%%/PSNR: Pineda against it\n");
  if (options.threads > 0)
    std::printf("threads: PINEDA_THREADS=%d, LP_NUM_THREADS=%d\n", options.threads, options.threads);
  std::printf("%-18s %9s %9s", "scene", "Pineda ms", "first");
  if (options.compareLlvmpipe) std::printf(" %11s %9s %7s", "llvmpipe ms", "first", "ratio");
  std::printf(" %8s %8s", "Mtri/s", "Mpix/s");
  if (options.compareLlvmpipe) std::printf(" %8s %9s %8s", "max diff", "differ %", "PSNR dB");
  if (options.reference) std::printf(" %9s %8s %9s %8s", "ref ms", "ref max", "ref dif %", "ref PSNR");
  std::printf("\n");
}

}  // namespace

int runComparison(const Options& options) {
  const std::string libDir = findLibDir(options);
  if (libDir.empty()) return 2;
  const Driver pinedaDriver{"pineda", pinedaEnv(options, libDir, false)};
  const Driver llvmpipeDriver{"llvmpipe", llvmpipeEnv(options)};
  const Driver referenceDriver{"reference", pinedaEnv(options, libDir, true)};

  printHeader(options);
  std::fflush(stdout);
  bool failed = false;
  std::string pinedaRenderer, llvmpipeRenderer;
  for (const BenchSceneEntry* entry : selectedScenes(options)) {
    // The drivers take turns, so that a slow minute of the machine falls on both.
    BestOutcome best_pineda, best_llvmpipe, best_reference;
    for (int round = 0; round < options.rounds; ++round) {
      if (!best_pineda.done()) best_pineda.take(runOn(options, pinedaDriver, *entry));
      if (options.compareLlvmpipe && !best_llvmpipe.done()) best_llvmpipe.take(runOn(options, llvmpipeDriver, *entry));
      if (options.reference && !best_reference.done()) best_reference.take(runOn(options, referenceDriver, *entry));
    }
    const DriverOutcome& pineda = best_pineda.best;
    const DriverOutcome& llvmpipe = best_llvmpipe.best;
    const DriverOutcome& reference = best_reference.best;
    failed |= !pineda.result || (options.compareLlvmpipe && !llvmpipe.result) ||
              (options.reference && !reference.result);
    if (pinedaRenderer.empty()) pinedaRenderer = pineda.renderer;
    if (llvmpipeRenderer.empty()) llvmpipeRenderer = llvmpipe.renderer;

    std::printf("%-18s %9s %9s", std::string(entry->name).c_str(), number(pineda.result, &SceneResult::medianMs).c_str(),
                number(pineda.result, &SceneResult::firstMs).c_str());
    if (options.compareLlvmpipe) {
      std::printf(" %11s %9s", number(llvmpipe.result, &SceneResult::medianMs).c_str(),
                  number(llvmpipe.result, &SceneResult::firstMs).c_str());
      if (pineda.result && llvmpipe.result && pineda.result->medianMs > 0)
        std::printf(" %7.2f", llvmpipe.result->medianMs / pineda.result->medianMs);
      else
        std::printf(" %7s", "-");
    }
    if (pineda.result)
      std::printf(" %8.3f %8.1f%s", megaTrianglesPerSecond(*pineda.result), megaPixelsPerSecond(*pineda.result),
                  pineda.result->fragmentsSaturated ? "+" : "");
    else
      std::printf(" %8s %8s", "-", "-");
    if (options.compareLlvmpipe) printError(imageError(options, pineda, llvmpipe, "diff", *entry));
    if (options.reference) {
      std::printf(" %9s", number(reference.result, &SceneResult::medianMs).c_str());
      printError(imageError(options, pineda, reference, "diff-reference", *entry));
    }
    std::printf("\n");
    if (pineda.result && llvmpipe.result) noteFragmentCounts(*pineda.result, *llvmpipe.result);
    if (pineda.result) notePerDraw(*pineda.result, llvmpipe.result);
    std::fflush(stdout);
  }
  std::printf("Pineda:   %s (LD_LIBRARY_PATH=%s)\n", pinedaRenderer.empty() ? "?" : pinedaRenderer.c_str(),
              libDir.c_str());
  if (options.compareLlvmpipe)
    std::printf("llvmpipe: %s\n", llvmpipeRenderer.empty() ? "?" : llvmpipeRenderer.c_str());
  std::printf("images: %s/{pineda%s%s}/SCENE.png\n", options.outDir.c_str(),
              options.compareLlvmpipe ? ",llvmpipe,diff" : "", options.reference ? ",reference,diff-reference" : "");
  return failed ? 1 : 0;
}

}  // namespace pineda::bench
