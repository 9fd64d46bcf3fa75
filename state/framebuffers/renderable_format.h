// Which internal formats framebuffer objects render into (GL 3.0 4.4.4 "color-, depth- and
// stencil-renderable", with Mesa's compatibility-profile additions: alpha, luminance and
// intensity colour formats), and how their images are stored.
#pragma once
#include <GL/gl.h>

#include <optional>

#include "raster/framebuffer.h"
#include "state/textures/texture_format.h"

namespace pineda {

struct RenderableFormat {
  enum class Kind { Color, Depth, Stencil, DepthStencil };
  Kind kind = Kind::Color;
  TextureFormat color;  // the colour bits and base format (Color only)
  int depth_bits = 0, stencil_bits = 0;
  // The depth is a float (ARB_depth_buffer_float); it renders as 32-bit integer depth.
  bool depth_float = false;
  bool has_depth() const { return kind == Kind::Depth || kind == Kind::DepthStencil; }
  bool has_stencil() const { return kind == Kind::Stencil || kind == Kind::DepthStencil; }
};

// The storage of a glRenderbufferStorage internal format; nullopt: INVALID_ENUM.
std::optional<RenderableFormat> renderbuffer_format(GLenum internal_format);

// A texture level's internal format as an attachment; nullopt when no attachment point can
// render into it (compressed formats, the unsized 1..4 counts as their base formats).
std::optional<RenderableFormat> texture_renderable_format(GLint internal_format);

// The write-stage reduction of a colour format (RGBA8 storage, R in the lowest byte).
raster::ColorReduction color_reduction(const TextureFormat& format);

// The base internal format GL reports for a colour format (GL_RGBA, GL_RGB, GL_ALPHA, ...).
GLenum color_base_enum(const TextureFormat& format);

}  // namespace pineda
