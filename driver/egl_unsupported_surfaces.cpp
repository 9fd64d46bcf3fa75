// The EGL 1.5 calls for what Pineda does not have: client-buffer pbuffers, textures from
// pbuffers, copies to native pixmaps, EGL images. Each validates its arguments
// and fails with the error the spec gives for an unsupported request.
#include "driver/egl_config.h"
#include "driver/egl_registry.h"
#include "driver/egl_thread.h"
#include "glapi/egl_entry_points.h"

namespace pineda::egl {

EGLSurface CreatePbufferFromClientBuffer(EGLDisplay dpy, EGLenum buftype, EGLClientBuffer buffer,
                                         EGLConfig config, const EGLint* attrib_list) {
  auto lock = Registry::instance().lock();
  if (!initialized_display(dpy)) return EGL_NO_SURFACE;
  // EGL_OPENVG_IMAGE is the only buffer type EGL defines, and OpenVG is not offered.
  return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
}

EGLBoolean CopyBuffers(EGLDisplay dpy, EGLSurface surface, EGLNativePixmapType target) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  if (!display->find_surface(surface)) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  return fail(EGL_BAD_NATIVE_PIXMAP, EGL_FALSE);
}

// Pbuffers are created with EGL_TEXTURE_FORMAT EGL_NO_TEXTURE only.
EGLBoolean BindTexImage(EGLDisplay dpy, EGLSurface surface, EGLint buffer) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  if (!display->find_surface(surface)) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  if (buffer != EGL_BACK_BUFFER) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  return fail(EGL_BAD_MATCH, EGL_FALSE);
}

EGLBoolean ReleaseTexImage(EGLDisplay dpy, EGLSurface surface, EGLint buffer) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  if (!display->find_surface(surface)) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  if (buffer != EGL_BACK_BUFFER) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  return fail(EGL_BAD_MATCH, EGL_FALSE);
}

EGLBoolean SurfaceAttrib(EGLDisplay dpy, EGLSurface surface, EGLint attribute, EGLint value) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  if (!display->find_surface(surface)) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  switch (attribute) {
    case EGL_MIPMAP_LEVEL: return succeed(EGL_TRUE);  // no mipmap texture: no effect
    case EGL_SWAP_BEHAVIOR:
      // Swapping a pbuffer never touches it: its contents are always preserved.
      if (value != EGL_BUFFER_PRESERVED && value != EGL_BUFFER_DESTROYED)
        return fail(EGL_BAD_PARAMETER, EGL_FALSE);
      return succeed(EGL_TRUE);
    case EGL_MULTISAMPLE_RESOLVE:
      if (value == EGL_MULTISAMPLE_RESOLVE_DEFAULT) return succeed(EGL_TRUE);
      if (value == EGL_MULTISAMPLE_RESOLVE_BOX) return fail(EGL_BAD_MATCH, EGL_FALSE);
      return fail(EGL_BAD_PARAMETER, EGL_FALSE);
    default: return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  }
}

EGLImage CreateImage(EGLDisplay dpy, EGLContext ctx, EGLenum target, EGLClientBuffer buffer,
                     const EGLAttrib* attrib_list) {
  auto lock = Registry::instance().lock();
  if (!initialized_display(dpy)) return EGL_NO_IMAGE;
  // No image source (GL textures, renderbuffers) is supported yet.
  return fail(EGL_BAD_PARAMETER, EGL_NO_IMAGE);
}

EGLBoolean DestroyImage(EGLDisplay dpy, EGLImage image) {
  auto lock = Registry::instance().lock();
  if (!initialized_display(dpy)) return EGL_FALSE;
  return fail(EGL_BAD_PARAMETER, EGL_FALSE);
}

}  // namespace pineda::egl
