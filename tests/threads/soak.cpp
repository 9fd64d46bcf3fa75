// The soak test: for a given time, creates and destroys contexts (of every API, some sharing
// objects), surfaces, textures, buffers, programs, display lists and framebuffer objects in a
// loop, rendering with each, while another thread renders through one long-lived context.
// Every image must be the one expected; resident memory is printed at the start, after the
// warm-up and at the end, and must not grow by more than the bound after the warm-up.
//   pineda_soak [seconds (20)] [--warmup seconds (a quarter, at most 10)] [--max-growth-kib (8192)]
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <thread>

#include "tests/threads/scene.h"
#include "tests/threads/test_context.h"

namespace pineda::threads_test {
namespace {

using Clock = std::chrono::steady_clock;

long resident_kib() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

// Objects of the other kinds, made, used and deleted in the current context; the image
// read back from the framebuffer object they drew into.
uint64_t render_with_short_lived_objects() {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0.5f, 0.25f);
  glVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(0, 1);
  glEnd();
  glEndList();

  GLuint texture = 0, framebuffer = 0, buffer = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  glViewport(0, 0, 64, 32);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glCallList(list);

  // A pixel buffer object the image is read into, then mapped.
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer);
  glBufferData(GL_PIXEL_PACK_BUFFER, 64 * 32 * 4, nullptr, GL_STREAM_READ);
  glReadPixels(0, 0, 64, 32, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  std::vector<uint8_t> image(64 * 32 * 4);
  if (const void* p = glMapBuffer(GL_PIXEL_PACK_BUFFER, GL_READ_ONLY)) std::memcpy(image.data(), p, image.size());
  glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  glDeleteBuffers(1, &buffer);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &texture);
  glDeleteLists(list, 1);
  return image_hash(image);
}

struct Expected {
  std::map<int, uint64_t> scene;  // frame -> hash
  uint64_t objects = 0;
};

// One iteration: a context of `api` (with a second one sharing its objects every other
// time), objects made, drawn and deleted. Returns whether every image was as expected.
bool cycle(Api api, int iteration, Expected& expected) {
  auto context = std::make_unique<TestContext>(api, kWidth, kHeight);
  if (!context->ok() || !context->make_current()) return false;
  const SceneObjects objects = create_scene_objects();
  const int frame = iteration % 8;
  bool ok = true;
  auto check = [&](uint64_t hash, uint64_t& slot) {
    if (slot == 0) slot = hash;
    ok = ok && hash == slot;
  };
  check(image_hash(render_frame(objects, frame)), expected.scene[frame]);
  check(render_with_short_lived_objects(), expected.objects);
  context->release();
  if (iteration % 2 == 0) {
    TestContext sharing(api, kWidth, kHeight, context.get());
    ok = ok && sharing.ok() && sharing.make_current();
    if (ok) {
      check(image_hash(render_frame(objects, frame)), expected.scene[frame]);
      sharing.release();
    }
  }
  ok = ok && context->make_current();
  if (ok) {
    delete_scene_objects(objects);
    ok = glGetError() == GL_NO_ERROR;
    context->release();
  }
  return ok;
}

int run(double seconds, double warmup, long max_growth_kib) {
  const long start_kib = resident_kib();
  std::printf("soak: %.0f s, warm-up %.0f s, bound %ld KiB\nRSS at start: %ld KiB\n", seconds, warmup,
              max_growth_kib, start_kib);
  std::fflush(stdout);

  // The long-lived context, rendering all along on its own thread.
  std::atomic<bool> stop{false}, background_ok{true};
  std::atomic<long> background_frames{0};
  std::thread background([&] {
    TestContext context(Api::EglPbuffer, kWidth, kHeight);
    if (!context.ok() || !context.make_current()) {
      background_ok = false;
      return;
    }
    const SceneObjects objects = create_scene_objects();
    const std::vector<uint64_t> reference = render_frames(objects, 8);
    for (long f = 0; !stop.load(); ++f, background_frames.fetch_add(1))
      if (image_hash(render_frame(objects, int(f % 8))) != reference[f % 8]) background_ok = false;
    delete_scene_objects(objects);
    context.release();
  });

  const auto begin = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - begin).count(); };
  Expected expected[3];
  long iterations = 0, warm_kib = -1;
  bool ok = true;
  while (ok && elapsed() < seconds) {
    const int api = int(iterations % 3);
    ok = cycle(static_cast<Api>(api), int(iterations), expected[api]);
    ++iterations;
    if (warm_kib < 0 && elapsed() >= warmup) {
      warm_kib = resident_kib();
      std::printf("RSS after warm-up (%ld iterations): %ld KiB\n", iterations, warm_kib);
      std::fflush(stdout);
    }
  }
  stop = true;
  background.join();
  const long end_kib = resident_kib();
  if (warm_kib < 0) warm_kib = end_kib;
  std::printf("RSS at end (%ld iterations, %ld background frames, %.1f s): %ld KiB; growth after warm-up %ld KiB\n",
              iterations, background_frames.load(), elapsed(), end_kib, end_kib - warm_kib);
  if (!ok) std::printf("FAIL: iteration %ld rendered an unexpected image or failed\n", iterations - 1);
  if (!background_ok) std::printf("FAIL: the long-lived context rendered an unexpected image\n");
  const bool flat = end_kib - warm_kib <= max_growth_kib;
  if (!flat) std::printf("FAIL: resident memory grew by more than %ld KiB after the warm-up\n", max_growth_kib);
  return ok && background_ok && flat ? 0 : 1;
}

}  // namespace
}  // namespace pineda::threads_test

int main(int argc, char** argv) {
  double seconds = 20, warmup = -1;
  long max_growth_kib = 8192;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--warmup") && i + 1 < argc)
      warmup = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--max-growth-kib") && i + 1 < argc)
      max_growth_kib = std::atol(argv[++i]);
    else
      seconds = std::atof(argv[i]);
  }
  if (warmup < 0) warmup = std::min(10.0, seconds / 4);
  return pineda::threads_test::run(seconds, warmup, max_growth_kib);
}
