// pineda-fill-probe: times the limit probes of pineda-bench's fill-bound scenes (fill_probe.h)
// on one thread and prints CPU milliseconds per frame and pixels per second, for comparing with
// `pineda-bench --threads 1 --scene overdraw --scene blend`.
#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "fill_probe.h"

namespace {

using pineda::bench::probe::FrameBuffers;

struct Probe {
  const char* scene;
  int layers;  // full-screen layers a frame
  void (*frame)(FrameBuffers&, int);
};

// CPU time of this thread: on a shared machine the wall clock counts other processes' time too.
double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

double median_ms(const Probe& probe, int width, int height, int frames) {
  FrameBuffers fb(width, height);
  probe.frame(fb, 0);  // warm-up, as the bench's frame 0
  std::vector<double> times;
  for (int f = 1; f <= frames; ++f) {
    const double start = thread_cpu_ms();
    probe.frame(fb, f);
    times.push_back(thread_cpu_ms() - start);
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int width = 1024, height = 768, frames = 30;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--width" || arg == "--height" || arg == "--frames") && i + 1 < argc) {
      const int value = std::atoi(argv[++i]);
      if (value <= 0 || value > 16384) {
        std::fprintf(stderr, "pineda-fill-probe: %s must be 1..16384\n", arg.c_str());
        return 2;
      }
      (arg == "--width" ? width : arg == "--height" ? height : frames) = value;
    } else {
      std::fprintf(stderr,
                   "usage: pineda-fill-probe [--width W] [--height H] [--frames N]\n"
                   "Times hand-written loops doing the per-pixel memory work of pineda-bench's overdraw and\n"
                   "blend frames (one thread, 64x64 tiles): CPU ms per frame, median of N frames after a warm-up.\n");
      return arg == "--help" ? 0 : 2;
    }
  }
  const Probe probes[] = {{"overdraw", 64, pineda::bench::probe::overdraw_frame},
                          {"blend", 32, pineda::bench::probe::blend_frame}};
  std::printf("size %dx%d, one thread, CPU ms per frame, median of %d frames\nscene        probe ms   Gpix/s\n", width, height, frames);
  for (const Probe& probe : probes) {
    const double ms = median_ms(probe, width, height, frames);
    std::printf("%-12s %9.3f %8.2f\n", probe.scene, ms, double(probe.layers) * width * height / (ms * 1e6));
  }
  return 0;
}
