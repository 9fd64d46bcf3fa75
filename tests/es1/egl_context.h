// An EGL pbuffer and a context of the asked API made current on it (surfaceless platform),
// through the public EGL API only, so that OpenGL ES and desktop GL code can share it.
#pragma once
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>

namespace pineda::es1_test {

class EglContext {
 public:
  // api: EGL_OPENGL_ES_API or EGL_OPENGL_API. The config is chosen with `renderable_type`.
  EglContext(EGLenum api, const EGLint* context_attribs, int width, int height,
             EGLint renderable_type = EGL_OPENGL_ES_BIT);
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  bool ok() const { return context_ != EGL_NO_CONTEXT && surface_ != EGL_NO_SURFACE; }
  const std::string& error() const { return error_; }
  bool make_current();
  EGLDisplay display() const { return display_; }
  EGLContext context() const { return context_; }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLSurface surface_ = EGL_NO_SURFACE;
  std::string error_;
};

// An OpenGL ES 1.1 context (EGL_CONTEXT_CLIENT_VERSION 1), current after construction.
struct Es1Context : EglContext {
  explicit Es1Context(int width = 32, int height = 32);
};

}  // namespace pineda::es1_test
