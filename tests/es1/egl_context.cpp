#include "tests/es1/egl_context.h"

namespace pineda::es1_test {

EglContext::EglContext(EGLenum api, const EGLint* context_attribs, int width, int height,
                       EGLint renderable_type) {
  display_ = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, nullptr, nullptr)) {
    error_ = "no surfaceless display";
    return;
  }
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, renderable_type,
                                   EGL_RED_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n = 0;
  if (!eglChooseConfig(display_, config_attribs, &config, 1, &n) || n < 1) {
    error_ = "no config";
    return;
  }
  if (!eglBindAPI(api)) {
    error_ = "eglBindAPI failed";
    return;
  }
  context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attribs);
  if (context_ == EGL_NO_CONTEXT) {
    error_ = "eglCreateContext failed: " + std::to_string(eglGetError());
    return;
  }
  const EGLint surface_attribs[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
  surface_ = eglCreatePbufferSurface(display_, config, surface_attribs);
  if (surface_ == EGL_NO_SURFACE) {
    error_ = "eglCreatePbufferSurface failed";
    return;
  }
  if (!make_current()) error_ = "eglMakeCurrent failed";
}

EglContext::~EglContext() {
  if (display_ == EGL_NO_DISPLAY) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
  if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
}

bool EglContext::make_current() { return eglMakeCurrent(display_, surface_, surface_, context_); }

namespace {
constexpr EGLint kClientVersion1[] = {EGL_CONTEXT_CLIENT_VERSION, 1, EGL_NONE};
}

Es1Context::Es1Context(int width, int height) : EglContext(EGL_OPENGL_ES_API, kClientVersion1, width, height) {}

}  // namespace pineda::es1_test
