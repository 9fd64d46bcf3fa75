#define GL_GLEXT_PROTOTYPES  // before test_context.h: GL/osmesa.h includes GL/gl.h
#include "tests/threads/test_context.h"

#include "tests/e2e/support/gl_surface.h"

#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

namespace pineda::threads_test {

using test::egl_display;

std::string api_name(Api api) {
  switch (api) {
    case Api::EglPbuffer: return "EglPbuffer";
    case Api::EglSurfaceless: return "EglSurfaceless";
    case Api::OSMesa: return "OSMesa";
  }
  return "?";
}

namespace {

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

TestContext::TestContext(Api api, int width, int height, const TestContext* share)
    : api_(api), width_(width), height_(height) {
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
  eglMakeCurrent(egl_display(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

}  // namespace pineda::threads_test
