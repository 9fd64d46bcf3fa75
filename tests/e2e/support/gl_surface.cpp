#include "tests/e2e/support/gl_surface.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <cstdlib>

#include "tests/e2e/support/egl_display.h"

namespace pineda::test {
namespace {

// OSMesa is looked up at run time so that the tests build before driver/ exports it.
struct OSMesaApi {
  decltype(&OSMesaCreateContextExt) create = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaDestroyContext) destroy = nullptr;
};

const OSMesaApi& osmesa() {
  static const OSMesaApi api = [] {
    OSMesaApi a;
    a.create = reinterpret_cast<decltype(a.create)>(dlsym(RTLD_DEFAULT, "OSMesaCreateContextExt"));
    a.make_current = reinterpret_cast<decltype(a.make_current)>(dlsym(RTLD_DEFAULT, "OSMesaMakeCurrent"));
    a.destroy = reinterpret_cast<decltype(a.destroy)>(dlsym(RTLD_DEFAULT, "OSMesaDestroyContext"));
    if (!a.create || !a.make_current || !a.destroy) a = {};
    return a;
  }();
  return api;
}

}  // namespace

EGLDisplay egl_display() {
  static const EGLDisplay display = [] {
    EGLDisplay d = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d == EGL_NO_DISPLAY || !eglInitialize(d, nullptr, nullptr)) return EGL_NO_DISPLAY;
    return d;
  }();
  return display;
}

GlSurface::GlSurface(const SurfaceSpec& spec) : spec_(spec) {
  // PINEDA_TEST_SURFACE=egl runs every test on EGL pbuffers.
  const char* env = std::getenv("PINEDA_TEST_SURFACE");
  const bool egl = spec.force_egl || spec.debug_context || (spec.share && !spec.share->is_osmesa()) || (env && std::string(env) == "egl");
  ok_ = osmesa().create && !egl ? create_osmesa() : create_egl();
}

GlSurface::~GlSurface() {
  if (osmesa_ctx_) {
    osmesa().destroy(static_cast<OSMesaContext>(osmesa_ctx_));
  } else if (egl_display_) {
    EGLDisplay d = egl_display_;
    if (eglGetCurrentContext() == egl_context_) eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (egl_surface_) eglDestroySurface(d, egl_surface_);
    if (egl_context_) eglDestroyContext(d, egl_context_);
  }
}

bool GlSurface::create_osmesa() {
  OSMesaContext share = spec_.share ? static_cast<OSMesaContext>(spec_.share->osmesa_ctx_) : nullptr;
  OSMesaContext ctx = osmesa().create(OSMESA_RGBA, spec_.depth_bits, spec_.stencil_bits, 0, share);
  if (!ctx) {
    error_ = "OSMesaCreateContextExt failed";
    return false;
  }
  osmesa_ctx_ = ctx;
  buffer_.assign(size_t(spec_.width) * spec_.height * 4, 0xA5);  // not a colour any test clears to
  return make_current();
}

bool GlSurface::create_egl() {
  EGLDisplay d = egl_display();
  if (d == EGL_NO_DISPLAY) {
    error_ = "no surfaceless EGL display";
    return false;
  }
  egl_display_ = d;
  const EGLint config_attribs[] = {EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                                   EGL_DEPTH_SIZE, spec_.depth_bits, EGL_STENCIL_SIZE, spec_.stencil_bits,
                                   EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                   EGL_NONE};
  EGLConfig config;
  EGLint count = 0;
  if (!eglChooseConfig(d, config_attribs, &config, 1, &count) || count == 0) {
    error_ = "no EGL config";
    return false;
  }
  eglBindAPI(EGL_OPENGL_API);
  const EGLint debug_attribs[] = {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE, EGL_NONE};
  EGLContext share = spec_.share ? spec_.share->egl_context_ : EGL_NO_CONTEXT;
  egl_context_ = eglCreateContext(d, config, share, spec_.debug_context ? debug_attribs : nullptr);
  const EGLint surface_attribs[] = {EGL_WIDTH, spec_.width, EGL_HEIGHT, spec_.height, EGL_NONE};
  egl_surface_ = eglCreatePbufferSurface(d, config, surface_attribs);
  if (!egl_context_ || !egl_surface_) {
    error_ = "EGL context or pbuffer creation failed";
    return false;
  }
  return make_current();
}

bool GlSurface::make_current() {
  if (osmesa_ctx_)
    return osmesa().make_current(static_cast<OSMesaContext>(osmesa_ctx_), buffer_.data(), GL_UNSIGNED_BYTE,
                                 spec_.width, spec_.height);
  return eglMakeCurrent(egl_display_, egl_surface_, egl_surface_, egl_context_);
}

void GlSurface::release() {
  if (osmesa_ctx_) {
    osmesa().make_current(nullptr, nullptr, 0, 0, 0);
  } else if (egl_display_) {
    eglMakeCurrent(egl_display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
}

}  // namespace pineda::test
