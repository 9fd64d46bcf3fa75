// A GL context of one of the window-system APIs, with its own drawing surface, made and
// used by one thread: an EGL pbuffer, an EGL surfaceless context drawing into a framebuffer
// object, an OSMesa context drawing into client memory, or a GLX pbuffer (on the X display
// that DISPLAY names, one connection for the process).
#pragma once
#include <EGL/egl.h>
#include <GL/osmesa.h>

#include <string>
#include <vector>

namespace pineda::threads_test {

enum class Api { EglPbuffer, EglSurfaceless, OSMesa, GlxPbuffer };

// Whether contexts of `api` can be made here (GLX needs an X server).
bool api_available(Api api);

std::string api_name(Api api);

class TestContext {
 public:
  // Creates the context (sharing objects with `share` if given) and its surface; not current.
  TestContext(Api api, int width, int height, const TestContext* share = nullptr);
  ~TestContext();
  TestContext(const TestContext&) = delete;
  TestContext& operator=(const TestContext&) = delete;

  bool ok() const { return ok_; }
  Api api() const { return api_; }
  EGLContext egl_context() const { return egl_context_; }
  // Binds the context (and its surface) to the calling thread; a surfaceless context also
  // gets its framebuffer object on first use.
  bool make_current();
  // Leaves the calling thread with no current context.
  void release();

 private:
  Api api_;
  int width_, height_;
  bool ok_ = false;
  EGLContext egl_context_ = EGL_NO_CONTEXT;
  EGLSurface egl_surface_ = EGL_NO_SURFACE;
  OSMesaContext osmesa_ = nullptr;
  // GLX objects, typed without the X11 header and its macros.
  void* glx_context_ = nullptr;
  unsigned long glx_pbuffer_ = 0;
  std::vector<unsigned char> osmesa_buffer_;
  unsigned framebuffer_ = 0, renderbuffers_[2] = {0, 0};
};

}  // namespace pineda::threads_test
