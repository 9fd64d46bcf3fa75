// Renderbuffer objects and their name space, which contexts of a share group hold in common
// (ARB_framebuffer_object: renderbuffers are shared, framebuffer objects are not).
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "raster/cache_line_vector.h"
#include "state/framebuffers/renderable_format.h"

namespace pineda {

// A renderbuffer's pixels, held apart from the object: another context of the group may
// respecify or delete the renderbuffer while rendering that this context queued still writes
// the old pixels, which the views and the context keep alive until then (Drawable::kept_storage).
struct RenderbufferPixels {
  raster::CacheLineVector<uint32_t> color;  // RGBA8, R in the lowest byte, bottom row first
  raster::CacheLineVector<uint32_t> depth;
  raster::CacheLineVector<uint8_t> stencil;
};

struct Renderbuffer {
  GLsizei width = 0, height = 0;
  GLenum internal_format = GL_RGBA;
  RenderableFormat format;
  // GL_RENDERBUFFER_SAMPLES: 0, or 4 (multisampled: every buffer holds 4 planes of
  // width x height, sample s in plane s; raster/multisample.h).
  GLsizei samples = 0;
  std::shared_ptr<RenderbufferPixels> pixels = std::make_shared<RenderbufferPixels>();
};

// Names to objects; a null object: generated, not yet bound.
using RenderbufferNames = std::map<GLuint, std::shared_ptr<Renderbuffer>>;

}  // namespace pineda
