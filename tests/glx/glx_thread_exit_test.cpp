// GLX calls made while a thread ends: from a thread_local destructor that runs after the
// driver's own per-thread state would have been destroyed, and from an atexit handler (as
// freeglut's clean-up does). Neither may touch destroyed state (UBSan reported it).
#include "glx_fixture.h"

#include <cstdlib>
#include <functional>
#include <thread>

namespace pineda_test {
namespace {

using GlxThreadExitTest = GlxTest;

// Runs `work` when the thread's thread_local objects are destroyed. Made before the thread's
// first GLX call, it is destroyed after the driver's per-thread state would have been.
struct AtThreadEnd {
  std::function<void()> work;
  ~AtThreadEnd() {
    if (work) work();
  }
};

TEST_F(GlxThreadExitTest, ThreadLocalDestructorBindsDrawsAndTheThreadStillLetsGo) {
  GLXFBConfig config = rgba8(true, true);
  Window w = window(config, 8, 8);
  GLXContext ctx = context(config);
  Bool bound_late = False;
  std::thread([&] {
    thread_local AtThreadEnd late;
    late.work = [&] {
      bound_late = glXMakeCurrent(dpy, w, ctx);
      glClearColor(0, 1, 0, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      glFinish();  // left current: the thread's end must release it
    };
    ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
  }).join();
  EXPECT_TRUE(bound_late);
  // Free again (not BadAccess), with what the late call drew.
  ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
  EXPECT_EQ(gl_pixel(1, 1), 0x00ff00u);
  EXPECT_TRUE(take_errors().empty());
}

struct AtExitScene {
  Display* dpy = nullptr;
  Window window = 0;
  GLXContext context = nullptr;
};
AtExitScene& at_exit_scene() {
  static AtExitScene scene;  // trivially destructible: still there for the handler
  return scene;
}

// Binds again, draws, checks the pixel and ends the process with the verdict.
void draw_at_exit() {
  const AtExitScene& s = at_exit_scene();
  bool ok = glXMakeCurrent(s.dpy, s.window, s.context);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ok = ok && gl_pixel(2, 2) == 0x0000ffu;
  ok = glXMakeCurrent(s.dpy, None, nullptr) && ok;
  std::_Exit(ok ? 0 : 3);
}

// The child opens its own connection: it must not share the parent's X stream.
void exit_after_drawing() {
  Display* dpy = XOpenDisplay(nullptr);
  if (!dpy) std::_Exit(4);
  int attribs[] = {GLX_RGBA, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, None};
  XVisualInfo* vi = glXChooseVisual(dpy, DefaultScreen(dpy), attribs);
  if (!vi) std::_Exit(5);
  XSetWindowAttributes swa{};
  swa.colormap = XCreateColormap(dpy, RootWindow(dpy, vi->screen), vi->visual, AllocNone);
  Window w = XCreateWindow(dpy, RootWindow(dpy, vi->screen), 0, 0, 8, 8, 0, vi->depth, InputOutput,
                           vi->visual, CWColormap, &swa);
  GLXContext ctx = glXCreateContext(dpy, vi, nullptr, True);
  XFree(vi);
  at_exit_scene() = {dpy, w, ctx};
  if (!glXMakeCurrent(dpy, w, ctx)) std::_Exit(6);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  std::atexit(draw_at_exit);
  std::exit(1);  // thread_local destructors run first, then draw_at_exit decides the status
}

TEST_F(GlxThreadExitTest, AtexitHandlerBindsAndDraws) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(exit_after_drawing(), ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace pineda_test
