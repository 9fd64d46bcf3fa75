// Two threads' contexts of one share group at once: rendering queued in one while the other
// changes an object it renders into (the queued rendering must not write freed memory).
#pragma once
#include <GL/gl.h>

#include <atomic>
#include <functional>
#include <thread>

#include "tests/e2e/support/gl_surface.h"

namespace pineda::test {

// In a second thread, with a 16x16 context sharing with `owner` (EGL unless `owner` is
// OSMesa): runs `queue`, which queues rendering without running it; then `change` on this thread;
// then `finish` in the second thread's context. False when the second context could not be made
// (then only `change` ran).
inline bool change_while_another_thread_has_queued(const GlSurface& owner, const std::function<void()>& queue,
                                                   const std::function<void()>& change,
                                                   const std::function<void()>& finish) {
  std::atomic<int> step{0};
  bool started = false;
  std::thread other([&] {
    GlSurface surface({.width = 16, .height = 16, .force_egl = !owner.is_osmesa(), .share = &owner});
    if (!surface.ok()) {
      step = 1;
      return;
    }
    started = true;
    queue();
    step = 1;
    while (step.load() != 2) std::this_thread::yield();
    finish();
    surface.release();
  });
  while (step.load() != 1) std::this_thread::yield();
  change();
  step = 2;
  other.join();
  return started;
}

// A triangle over the whole viewport, in immediate mode (queued until a flush).
inline void queue_full_triangle() {
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glVertex2f(3, -1);
  glVertex2f(-1, 3);
  glEnd();
}

}  // namespace pineda::test
