#include "egl_session.h"

#include <EGL/eglext.h>

#include <cstdio>

namespace pineda::tools {
namespace {

std::string eglError(const char* what) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%s failed (EGL error 0x%04x)", what, eglGetError());
  return buffer;
}

EGLDisplay openDisplay() {
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (getPlatformDisplay) {
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY) return display;
  }
  return eglGetDisplay(EGL_DEFAULT_DISPLAY);
}

}  // namespace

EglSession::~EglSession() {
  if (display_ == EGL_NO_DISPLAY) return;
  destroyContext();
  if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
  eglTerminate(display_);
  eglReleaseThread();
}

bool EglSession::open(int width, int height, std::string& error) {
  display_ = openDisplay();
  if (display_ == EGL_NO_DISPLAY) {
    error = eglError("eglGetDisplay");
    return false;
  }
  if (!eglInitialize(display_, nullptr, nullptr)) {
    error = eglError("eglInitialize");
    display_ = EGL_NO_DISPLAY;
    return false;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    error = eglError("eglBindAPI(EGL_OPENGL_API)");
    return false;
  }
  const EGLint configAttribs[] = {
      EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
      EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
      EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_NONE};
  EGLint count = 0;
  if (!eglChooseConfig(display_, configAttribs, &config_, 1, &count) || count < 1) {
    error = eglError("eglChooseConfig (RGBA8, depth 24, stencil 8, pbuffer, OpenGL)");
    return false;
  }
  const EGLint surfaceAttribs[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
  surface_ = eglCreatePbufferSurface(display_, config_, surfaceAttribs);
  if (surface_ == EGL_NO_SURFACE) {
    error = eglError("eglCreatePbufferSurface");
    return false;
  }
  return freshContext(error);
}

bool EglSession::freshContext(std::string& error, ContextApi api) {
  destroyContext();
  if (api == ContextApi::ES11 || api == ContextApi::ES20) {
    const EGLint version = api == ContextApi::ES11 ? 1 : 2;
    const EGLint esAttribs[] = {EGL_CONTEXT_CLIENT_VERSION, version, EGL_NONE};
    eglBindAPI(EGL_OPENGL_ES_API);
    context_ = eglCreateContext(display_, config_, EGL_NO_CONTEXT, esAttribs);
    eglBindAPI(EGL_OPENGL_API);
    if (context_ == EGL_NO_CONTEXT) {
      error = eglError(version == 1 ? "eglCreateContext (OpenGL ES 1.1)" : "eglCreateContext (OpenGL ES 2.0)");
      return false;
    }
    return makeCurrent(error);
  }
  const EGLint major = api == ContextApi::GL11 ? 1 : 2;  // 1.1 or 2.1
  const EGLint versioned[] = {EGL_CONTEXT_MAJOR_VERSION, major, EGL_CONTEXT_MINOR_VERSION, 1, EGL_NONE};
  context_ = eglCreateContext(display_, config_, EGL_NO_CONTEXT, versioned);
  if (context_ == EGL_NO_CONTEXT && api == ContextApi::GL11)  // EGL 1.4 without EGL_KHR_create_context
    context_ = eglCreateContext(display_, config_, EGL_NO_CONTEXT, nullptr);
  if (context_ == EGL_NO_CONTEXT) {
    error = eglError(api == ContextApi::GL11 ? "eglCreateContext (OpenGL 1.1)" : "eglCreateContext (OpenGL 2.1)");
    return false;
  }
  return makeCurrent(error);
}

bool EglSession::makeCurrent(std::string& error) {
  if (!eglMakeCurrent(display_, surface_, surface_, context_)) {
    error = eglError("eglMakeCurrent");
    return false;
  }
  return true;
}

void EglSession::destroyContext() {
  if (context_ == EGL_NO_CONTEXT) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  context_ = EGL_NO_CONTEXT;
}

}  // namespace pineda::tools
