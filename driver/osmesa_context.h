// An OSMesa context: a GL context plus the user's image it renders into.
//
// RGBA and BGRA images are rendered in place (a negative stride expresses OSMESA_Y_UP = 0).
// The other formats (ARGB, RGB, BGR) are rendered into an RGBA8 copy: the copy is loaded
// from the user's image when it is bound (OSMesaMakeCurrent, OSMesaPixelStore) and stored
// back at glFinish, glFlush, OSMesaGetColorBuffer and when the binding ends (OSMesaMakeCurrent
// of another image or context, release, OSMesaDestroyContext). In between, the user's
// image is not up to date, as with in-place rendering, whose drawing is deferred until
// one of those points too.
#pragma once
#include <GL/osmesa.h>

#include <memory>
#include <vector>

#include "driver/osmesa_pixels.h"
#include "glapi/flush_listener.h"
#include "raster/cache_line_vector.h"
#include "state/context.h"
#include "state/drawable.h"

namespace pineda::osmesa {

inline constexpr int kMaxSize = 16384;

}  // namespace pineda::osmesa

struct osmesa_context final : pineda::glapi::FlushListener {
  GLenum format = OSMESA_RGBA;
  int depth_bits = 0, stencil_bits = 0;
  std::unique_ptr<pineda::Context> gl;

  // The binding; `user.pixels` is null until the first OSMesaMakeCurrent.
  pineda::osmesa::UserImage user;
  GLint row_length = 0;  // OSMESA_ROW_LENGTH in pixels; 0: the width
  pineda::raster::CacheLineVector<uint8_t> copy;  // RGBA8, for the formats not rendered in place
  pineda::raster::CacheLineVector<uint32_t> depth;
  pineda::raster::CacheLineVector<uint8_t> stencil;
  pineda::Drawable drawable;

  const void* owner = nullptr;  // the thread it is current to; guarded by a mutex
  bool destroy_pending = false;

  // Points the drawable at the user's image (or the copy) with the current layout.
  void attach(uint8_t* pixels, int width, int height);
  // Completes rendering and brings the user's image up to date.
  void update_user_image();
  // Re-lays out the image after OSMESA_ROW_LENGTH / OSMESA_Y_UP changed.
  void relayout();

  void flushed() override { update_user_image(); }

 private:
  void describe_framebuffer();
};
