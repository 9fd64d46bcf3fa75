// A GL context made current on a colour + depth + stencil surface, through the public API
// only. OSMesa is used when the library exports it (then `osmesa_buffer()` is the memory
// the context renders into); otherwise an EGL pbuffer on the surfaceless platform.
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pineda::test {

class GlSurface;

struct SurfaceSpec {
  int width = 32, height = 32;
  int depth_bits = 24, stencil_bits = 8;
  bool force_egl = false;  // use an EGL pbuffer even when OSMesa is available
  bool debug_context = false;  // an EGL debug context (EGL_CONTEXT_OPENGL_DEBUG); implies EGL
  const GlSurface* share = nullptr;  // shares objects with this surface's context (same kind)
};

class GlSurface {
 public:
  explicit GlSurface(const SurfaceSpec& spec = {});
  ~GlSurface();
  GlSurface(const GlSurface&) = delete;
  GlSurface& operator=(const GlSurface&) = delete;

  // False when no context could be made; `error()` says why.
  bool ok() const { return ok_; }
  const std::string& error() const { return error_; }
  // Makes this context current on the calling thread.
  bool make_current();
  void release();

  int width() const { return spec_.width; }
  int height() const { return spec_.height; }
  bool is_osmesa() const { return osmesa_ctx_ != nullptr; }
  // RGBA8 rows, bottom row first (OSMesa's default Y-up); null on EGL.
  const uint8_t* osmesa_buffer() const { return is_osmesa() ? buffer_.data() : nullptr; }

 private:
  bool create_osmesa();
  bool create_egl();

  SurfaceSpec spec_;
  bool ok_ = false;
  std::string error_;
  std::vector<uint8_t> buffer_;
  void* osmesa_ctx_ = nullptr;
  void* egl_display_ = nullptr;
  void* egl_context_ = nullptr;
  void* egl_surface_ = nullptr;
};

}  // namespace pineda::test
