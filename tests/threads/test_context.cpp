#define GL_GLEXT_PROTOTYPES  // before test_context.h: GL/osmesa.h includes GL/gl.h
#include "tests/threads/test_context.h"

#include "tests/e2e/support/egl_display.h"

#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glx.h>

#include <cstdlib>

namespace pineda::threads_test {

using test::egl_display;

std::string api_name(Api api) {
  switch (api) {
    case Api::EglPbuffer: return "EglPbuffer";
    case Api::EglSurfaceless: return "EglSurfaceless";
    case Api::OSMesa: return "OSMesa";
    case Api::GlxPbuffer: return "GlxPbuffer";
  }
  return "?";
}

namespace {

// One connection, shared by the threads (GLX share lists need one display).
Display* x_display() {
  static Display* const display = [] {
    XInitThreads();
    return std::getenv("DISPLAY") ? XOpenDisplay(nullptr) : nullptr;
  }();
  return display;
}

GLXFBConfig glx_rgba8_depth24_config() {
  const int attribs[] = {GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT, GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_RED_SIZE, 8,
                         GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_ALPHA_SIZE, 8, GLX_DEPTH_SIZE, 24, None};
  int count = 0;
  GLXFBConfig* configs = glXChooseFBConfig(x_display(), DefaultScreen(x_display()), attribs, &count);
  GLXFBConfig config = count > 0 ? configs[0] : nullptr;
  if (configs) XFree(configs);
  return config;
}

EGLConfig rgba8_depth24_config() {
  const EGLint attribs[] = {EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                            EGL_DEPTH_SIZE, 24, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                            EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(egl_display(), attribs, &config, 1, &count) || count < 1) return nullptr;
  return config;
}

}  // namespace

bool api_available(Api api) { return api != Api::GlxPbuffer || x_display() != nullptr; }

TestContext::TestContext(Api api, int width, int height, const TestContext* share)
    : api_(api), width_(width), height_(height) {
  if (api == Api::GlxPbuffer) {
    GLXFBConfig config = x_display() ? glx_rgba8_depth24_config() : nullptr;
    if (!config) return;
    glx_context_ = glXCreateNewContext(x_display(), config, GLX_RGBA_TYPE,
                                       share ? static_cast<GLXContext>(share->glx_context_) : nullptr, True);
    const int attribs[] = {GLX_PBUFFER_WIDTH, width, GLX_PBUFFER_HEIGHT, height, None};
    glx_pbuffer_ = glx_context_ ? glXCreatePbuffer(x_display(), config, attribs) : 0;
    ok_ = glx_pbuffer_ != 0;
    return;
  }
  if (api == Api::OSMesa) {
    osmesa_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, share ? share->osmesa_ : nullptr);
    osmesa_buffer_.assign(size_t(width) * height * 4, 0);
    ok_ = osmesa_ != nullptr;
    return;
  }
  EGLDisplay d = egl_display();
  EGLConfig config = d == EGL_NO_DISPLAY ? nullptr : rgba8_depth24_config();
  if (!config || !eglBindAPI(EGL_OPENGL_API)) return;
  egl_context_ = eglCreateContext(d, config, share ? share->egl_context_ : EGL_NO_CONTEXT, nullptr);
  if (egl_context_ == EGL_NO_CONTEXT) return;
  if (api == Api::EglPbuffer) {
    const EGLint attribs[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
    egl_surface_ = eglCreatePbufferSurface(d, config, attribs);
    if (egl_surface_ == EGL_NO_SURFACE) return;
  }
  ok_ = true;
}

TestContext::~TestContext() {
  if (api_ == Api::GlxPbuffer) {
    if (glx_pbuffer_) glXDestroyPbuffer(x_display(), glx_pbuffer_);
    if (glx_context_) glXDestroyContext(x_display(), static_cast<GLXContext>(glx_context_));
    return;
  }
  if (osmesa_) {
    OSMesaDestroyContext(osmesa_);
    return;
  }
  EGLDisplay d = egl_display();
  if (framebuffer_ && make_current()) {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteRenderbuffers(2, renderbuffers_);
    release();
  }
  if (egl_surface_ != EGL_NO_SURFACE) eglDestroySurface(d, egl_surface_);
  if (egl_context_ != EGL_NO_CONTEXT) eglDestroyContext(d, egl_context_);
}

bool TestContext::make_current() {
  if (!ok_) return false;
  if (osmesa_) return OSMesaMakeCurrent(osmesa_, osmesa_buffer_.data(), GL_UNSIGNED_BYTE, width_, height_);
  if (api_ == Api::GlxPbuffer)
    return glXMakeContextCurrent(x_display(), glx_pbuffer_, glx_pbuffer_, static_cast<GLXContext>(glx_context_));
  eglBindAPI(EGL_OPENGL_API);
  if (!eglMakeCurrent(egl_display(), egl_surface_, egl_surface_, egl_context_)) return false;
  if (api_ != Api::EglSurfaceless || framebuffer_) return true;
  glGenFramebuffers(1, &framebuffer_);
  glGenRenderbuffers(2, renderbuffers_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[0]);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_, height_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffers_[1]);
  return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

void TestContext::release() {
  if (osmesa_) {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    return;
  }
  if (api_ == Api::GlxPbuffer) {
    glXMakeContextCurrent(x_display(), None, None, nullptr);
    return;
  }
  eglMakeCurrent(egl_display(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

}  // namespace pineda::threads_test
