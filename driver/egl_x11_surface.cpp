// eglCreate(Platform)WindowSurface and eglCreate(Platform)PixmapSurface on the X11 platform,
// and what eglSwapBuffers and eglMakeCurrent do with them. A surface's buffers and their
// presentation are a GLX drawable object's (glx_drawable.h), so EGL and GLX windows behave
// alike: front and back buffers, MIT-SHM or XPutImage, the window's size followed at the
// next swap or make-current.
#include "driver/glx_objects.h"  // first: X11 headers

#include "driver/egl_config.h"
#include "driver/egl_registry.h"
#include "driver/egl_thread.h"
#include "driver/egl_x11.h"
#include "driver/glx_config.h"
#include "driver/glx_drawable.h"
#include "glapi/egl_entry_points.h"

namespace pineda::egl {
namespace {

struct SurfaceRequest {
  bool single_buffer = false;
};

template <class Attrib>
EGLint parse_attributes(const Attrib* attribs, bool window, SurfaceRequest* out) {
  for (const Attrib* a = attribs; a && a[0] != EGL_NONE; a += 2) {
    switch (a[0]) {
      case EGL_RENDER_BUFFER:
        if (!window) return EGL_BAD_ATTRIBUTE;
        if (a[1] != EGL_BACK_BUFFER && a[1] != EGL_SINGLE_BUFFER) return EGL_BAD_ATTRIBUTE;
        out->single_buffer = a[1] == EGL_SINGLE_BUFFER;
        break;
      case EGL_GL_COLORSPACE:
        if (a[1] == EGL_GL_COLORSPACE_SRGB) return EGL_BAD_MATCH;
        if (a[1] != EGL_GL_COLORSPACE_LINEAR) return EGL_BAD_ATTRIBUTE;
        break;
      case EGL_VG_ALPHA_FORMAT:
      case EGL_VG_COLORSPACE: break;  // OpenVG only
      default: return EGL_BAD_ATTRIBUTE;
    }
  }
  return EGL_SUCCESS;
}

bool presentable(Visual* visual, int depth) {
  return visual && (depth == 24 || depth == 32) && visual->c_class == TrueColor &&
         visual->red_mask == 0xff0000 && visual->green_mask == 0xff00 && visual->blue_mask == 0xff;
}

std::shared_ptr<glx::Config> glx_config_of(const Config& c, int screen, int x_depth, bool double_buffered) {
  auto g = std::make_shared<glx::Config>();
  g->screen = screen;
  g->visual_id = static_cast<VisualID>(c.native_visual_id);
  g->visual_depth = x_depth;
  g->red = c.red;
  g->green = c.green;
  g->blue = c.blue;
  g->alpha = c.alpha;
  g->depth = c.depth;
  g->stencil = c.stencil;
  g->double_buffered = double_buffered;
  g->samples = c.samples;
  return g;
}

bool already_has_surface(const Display& display, ::Drawable x) {
  for (const auto& [handle, s] : display.surfaces)
    if (s->native && s->native->x_drawable == x) return true;
  return false;
}

template <class Attrib>
EGLSurface create_native(EGLDisplay dpy, EGLConfig config, ::Drawable x, const Attrib* attribs,
                         bool window) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_NO_SURFACE;
  const Config* c = find_config(*display, config);
  if (!c) return fail(EGL_BAD_CONFIG, EGL_NO_SURFACE);
  SurfaceRequest request;
  if (EGLint error = parse_attributes(attribs, window, &request); error != EGL_SUCCESS)
    return fail(error, EGL_NO_SURFACE);
  if (!(c->surface_type & (window ? EGL_WINDOW_BIT : EGL_PIXMAP_BIT)))
    return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
  const EGLint bad_native = window ? EGL_BAD_NATIVE_WINDOW : EGL_BAD_NATIVE_PIXMAP;
  auto* xdpy = static_cast<::Display*>(display->x11);
  if (x == 0) return fail(bad_native, EGL_NO_SURFACE);

  auto object = std::make_shared<glx::DrawableObject>();
  int width = 0, height = 0;
  if (window) {
    XWindowAttributes attributes;
    if (!glx::x_window_attributes(xdpy, x, &attributes)) return fail(bad_native, EGL_NO_SURFACE);
    object->visual = attributes.visual;
    object->x_depth = attributes.depth;
    width = attributes.width;
    height = attributes.height;
  } else {
    if (!glx::x_drawable_size(xdpy, x, &width, &height, &object->x_depth))
      return fail(bad_native, EGL_NO_SURFACE);
    const std::vector<XVisualInfo> visuals = glx::usable_visuals(xdpy, display->screen, object->x_depth);
    object->visual = visuals.empty() ? nullptr : visuals.front().visual;
  }
  if (!presentable(object->visual, object->x_depth)) return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
  // EGL 1.5, 3.5.1: a second surface for one native window is EGL_BAD_ALLOC.
  if (already_has_surface(*display, x)) return fail(EGL_BAD_ALLOC, EGL_NO_SURFACE);

  auto surface = std::make_shared<Surface>();
  surface->config = c;
  surface->native_config =
      glx_config_of(*c, display->screen, object->x_depth, window && !request.single_buffer);
  object->dpy = xdpy;
  object->id = object->x_drawable = x;
  object->kind = window ? glx::DrawableKind::Window : glx::DrawableKind::Pixmap;
  object->config = surface->native_config.get();
  object->gc = XCreateGC(xdpy, x, 0, nullptr);
  try {
    glx::allocate_buffers(*object, width, height);
  } catch (const std::bad_alloc&) {
    return fail(EGL_BAD_ALLOC, EGL_NO_SURFACE);
  }
  if (!window) glx::load_from_x(*object);
  surface->width = width;
  surface->height = height;
  surface->native = std::move(object);
  EGLSurface handle = surface.get();
  display->surfaces.emplace(handle, std::move(surface));
  return succeed(handle);
}

// The platform calls take a pointer to the Window or Pixmap.
::Drawable native_from_pointer(void* native) {
  return native ? *static_cast<const ::Drawable*>(native) : 0;
}

}  // namespace

pineda::Drawable* Surface::gl_drawable() { return native ? &native->drawable : &drawable; }

EGLint render_buffer(const Surface& s) {
  if (!s.native) return EGL_BACK_BUFFER;  // pbuffers
  return s.native->drawable.double_buffered ? EGL_BACK_BUFFER : EGL_SINGLE_BUFFER;
}

bool follow_native_size(Surface& s) {
  glx::DrawableObject* d = s.native.get();
  if (!d || d->kind != glx::DrawableKind::Window) return true;
  int width = 0, height = 0;
  if (!glx::x_drawable_size(d->dpy, d->x_drawable, &width, &height)) return false;
  if (width == d->width && height == d->height) return true;
  try {
    glx::allocate_buffers(*d, width, height);
  } catch (const std::bad_alloc&) {
    return true;  // keeps rendering at the old size
  }
  s.width = width;
  s.height = height;
  return true;
}

void show_front(Surface& s) {
  if (s.native && s.native->drawable.front_drawn) glx::present(*s.native, true);
}

EGLint swap_native(Surface& s, pineda::Context& gl) {
  glx::DrawableObject& d = *s.native;
  gl.finish_for_reading();
  // A pixmap surface is single-buffered: swapping has no effect.
  if (d.kind != glx::DrawableKind::Window) return EGL_SUCCESS;
  int width = 0, height = 0;
  if (!glx::x_drawable_size(d.dpy, d.x_drawable, &width, &height)) return EGL_BAD_NATIVE_WINDOW;
  if (d.drawable.double_buffered) glx::swap_and_present(d);
  else glx::present(d);
  const int old_width = d.width, old_height = d.height;
  {
    auto lock = Registry::instance().lock();
    follow_native_size(s);
  }
  if (d.width != old_width || d.height != old_height) gl.drawable_changed();
  return EGL_SUCCESS;
}

EGLSurface CreateWindowSurface(EGLDisplay dpy, EGLConfig config, EGLNativeWindowType win,
                               const EGLint* attrib_list) {
  return create_native(dpy, config, static_cast<::Drawable>(win), attrib_list, true);
}

EGLSurface CreatePlatformWindowSurface(EGLDisplay dpy, EGLConfig config, void* native_window,
                                       const EGLAttrib* attrib_list) {
  return create_native(dpy, config, native_from_pointer(native_window), attrib_list, true);
}

EGLSurface CreatePixmapSurface(EGLDisplay dpy, EGLConfig config, EGLNativePixmapType pixmap,
                               const EGLint* attrib_list) {
  return create_native(dpy, config, static_cast<::Drawable>(pixmap), attrib_list, false);
}

EGLSurface CreatePlatformPixmapSurface(EGLDisplay dpy, EGLConfig config, void* native_pixmap,
                                       const EGLAttrib* attrib_list) {
  return create_native(dpy, config, native_from_pointer(native_pixmap), attrib_list, false);
}

// EGL_EXT_platform_base's names: EGLint attributes.
EGLSurface CreatePlatformWindowSurfaceEXT(EGLDisplay dpy, EGLConfig config, void* native_window,
                                          const EGLint* attrib_list) {
  return create_native(dpy, config, native_from_pointer(native_window), attrib_list, true);
}

EGLSurface CreatePlatformPixmapSurfaceEXT(EGLDisplay dpy, EGLConfig config, void* native_pixmap,
                                          const EGLint* attrib_list) {
  return create_native(dpy, config, native_from_pointer(native_pixmap), attrib_list, false);
}

}  // namespace pineda::egl
