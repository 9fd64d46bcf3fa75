// eglCreatePbufferSurface, eglDestroySurface, eglQuerySurface, eglSwapBuffers,
// eglSwapInterval. A pbuffer is memory the driver owns: RGBA8 colour, uint32 depth, uint8
// stencil, row 0 at the bottom. Window and pixmap surfaces are egl_x11_surface.cpp's.
#include <algorithm>

#include "driver/egl_config.h"
#include "driver/frame_capture.h"
#include "driver/egl_registry.h"
#include "driver/egl_thread.h"
#include "driver/egl_x11.h"
#include "glapi/egl_entry_points.h"
#include "raster/multisample.h"

namespace pineda::egl {
namespace {

void allocate(Surface& s) {
  size_t pixels = static_cast<size_t>(s.width) * static_cast<size_t>(s.height);
  // A multisampled config renders into 4 planes; `color` is their resolve (Drawable::resolved).
  const int samples = s.config->samples > 1 ? s.config->samples : 1;
  s.color.assign(pixels * 4, 0);
  s.sample_color.assign(samples > 1 ? pixels * 4 * samples : 0, 0);
  s.depth.assign(s.config->depth ? pixels * samples : 0, 0);
  s.stencil.assign(s.config->stencil ? pixels * samples : 0, 0);

  raster::Framebuffer& fb = s.drawable.framebuffer;
  fb.width = s.width;
  fb.height = s.height;
  fb.color = {s.color.data(), static_cast<ptrdiff_t>(s.width) * 4, raster::ColorFormat::RGBA8, {}, 0};
  fb.depth = {s.config->depth ? s.depth.data() : nullptr, s.width, s.config->depth};
  fb.stencil = {s.config->stencil ? s.stencil.data() : nullptr, s.width, s.config->stencil};
  fb.samples = samples;
  s.drawable.resolved = {};
  if (samples > 1) {
    s.drawable.resolved = fb.color;
    fb.color.base = s.sample_color.data();
    fb.color.sample_stride = static_cast<ptrdiff_t>(pixels) * 4;
    fb.depth.sample_stride = fb.stencil.sample_stride = static_cast<ptrdiff_t>(pixels);
  }
  s.drawable.red_bits = s.config->red;
  s.drawable.green_bits = s.config->green;
  s.drawable.blue_bits = s.config->blue;
  s.drawable.alpha_bits = s.config->alpha;
  // EGL pbuffers render to their back buffer (EGL_RENDER_BUFFER is EGL_BACK_BUFFER).
  s.drawable.double_buffered = true;
  s.drawable.track_cleared_tiles(true);
}

}  // namespace

EGLSurface CreatePbufferSurface(EGLDisplay dpy, EGLConfig config, const EGLint* attrib_list) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_NO_SURFACE;
  const Config* c = find_config(*display, config);
  if (!c) return fail(EGL_BAD_CONFIG, EGL_NO_SURFACE);

  EGLint width = 0, height = 0;
  bool largest = false;
  for (const EGLint* a = attrib_list; a && a[0] != EGL_NONE; a += 2) {
    switch (a[0]) {
      case EGL_WIDTH: width = a[1]; break;
      case EGL_HEIGHT: height = a[1]; break;
      case EGL_LARGEST_PBUFFER: largest = a[1] != EGL_FALSE; break;
      case EGL_TEXTURE_FORMAT:
      case EGL_TEXTURE_TARGET:
        // The configs cannot bind to textures.
        if (a[1] != EGL_NO_TEXTURE) return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
        break;
      case EGL_MIPMAP_TEXTURE: break;
      case EGL_GL_COLORSPACE:
        if (a[1] != EGL_GL_COLORSPACE_LINEAR) return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
        break;
      case EGL_VG_ALPHA_FORMAT:
      case EGL_VG_COLORSPACE: break;  // OpenVG only
      default: return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SURFACE);
    }
  }
  if (!(c->surface_type & EGL_PBUFFER_BIT)) return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
  if (width < 0 || height < 0) return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
  if (width > kMaxPbufferWidth || height > kMaxPbufferHeight) {
    if (!largest) return fail(EGL_BAD_ALLOC, EGL_NO_SURFACE);
    width = std::min(width, kMaxPbufferWidth);
    height = std::min(height, kMaxPbufferHeight);
  }

  auto surface = std::make_shared<Surface>();
  surface->config = c;
  surface->width = width;
  surface->height = height;
  surface->largest_pbuffer = largest;
  try {
    allocate(*surface);
  } catch (const std::bad_alloc&) {
    return fail(EGL_BAD_ALLOC, EGL_NO_SURFACE);
  }
  EGLSurface handle = surface.get();
  display->surfaces.emplace(handle, std::move(surface));
  return succeed(handle);
}

EGLBoolean DestroySurface(EGLDisplay dpy, EGLSurface surface) {
  std::shared_ptr<Surface> doomed;  // freed after the lock is released
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  auto it = display->surfaces.find(surface);
  if (it == display->surfaces.end()) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  // A surface current to a thread lives on through that thread's reference.
  doomed = std::move(it->second);
  display->surfaces.erase(it);
  lock.unlock();
  return succeed(EGL_TRUE);
}

EGLBoolean QuerySurface(EGLDisplay dpy, EGLSurface surface, EGLint attribute, EGLint* value) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  auto s = display->find_surface(surface);
  if (!s) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  EGLint result;
  switch (attribute) {
    case EGL_CONFIG_ID: result = s->config->id; break;
    case EGL_WIDTH: result = s->width; break;
    case EGL_HEIGHT: result = s->height; break;
    case EGL_LARGEST_PBUFFER: result = s->largest_pbuffer; break;
    case EGL_TEXTURE_FORMAT:
    case EGL_TEXTURE_TARGET: result = EGL_NO_TEXTURE; break;
    case EGL_MIPMAP_TEXTURE:
    case EGL_MIPMAP_LEVEL: result = 0; break;
    case EGL_RENDER_BUFFER: result = render_buffer(*s); break;
    case EGL_SWAP_BEHAVIOR: result = EGL_BUFFER_PRESERVED; break;
    case EGL_MULTISAMPLE_RESOLVE: result = EGL_MULTISAMPLE_RESOLVE_DEFAULT; break;
    case EGL_HORIZONTAL_RESOLUTION:
    case EGL_VERTICAL_RESOLUTION:
    case EGL_PIXEL_ASPECT_RATIO: result = EGL_UNKNOWN; break;
    case EGL_VG_ALPHA_FORMAT: result = EGL_VG_ALPHA_FORMAT_NONPRE; break;
    case EGL_VG_COLORSPACE: result = EGL_VG_COLORSPACE_sRGB; break;
    case EGL_GL_COLORSPACE: result = EGL_GL_COLORSPACE_LINEAR; break;
    default: return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  }
  if (!value) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  *value = result;
  return succeed(EGL_TRUE);
}

EGLBoolean SwapBuffers(EGLDisplay dpy, EGLSurface surface) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  auto s = display->find_surface(surface);
  if (!s) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  ThreadState& t = thread_state();
  if (!t.context) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
  if (t.draw != s) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  lock.unlock();
  if (s->native) {
    const EGLint error = swap_native(*s, *t.context->gl);
    return error == EGL_SUCCESS ? succeed(EGL_TRUE) : fail(error, EGL_FALSE);
  }
  // A pbuffer has nothing to present; swapping completes the rendering (and the frame can
  // be captured).
  t.context->gl->finish_for_reading();
  const raster::Framebuffer& fb = s->drawable.framebuffer;
  if (fb.samples > 1) raster::resolve_color(fb, s->drawable.resolved);
  driver::capture_frame(fb.samples > 1 ? s->drawable.resolved : fb.color, s->width, s->height);
  return succeed(EGL_TRUE);
}

EGLBoolean SwapInterval(EGLDisplay dpy, EGLint interval) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  ThreadState& t = thread_state();
  if (!t.context || t.display != display) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
  if (!t.draw) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  t.draw->swap_interval = std::clamp(interval, kMinSwapInterval, kMaxSwapInterval);
  return succeed(EGL_TRUE);
}

}  // namespace pineda::egl
