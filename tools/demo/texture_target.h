#pragma once
// A square render-to-texture target: an RGBA texture (linear filters, clamped to edge) as colour
// attachment 0 and a depth renderbuffer, in a framebuffer object (desktop GL and OpenGL ES 2.0
// share the calls). Leaves the window-system framebuffer bound.

namespace pineda::demo {

struct TextureTarget {
  unsigned texture = 0, depth = 0, framebuffer = 0;
};

// `depthFormat` is the renderbuffer's internal format (GL_DEPTH_COMPONENT16, ...); an incomplete
// framebuffer is reported on stderr under `scene`.
TextureTarget makeTextureTarget(const char* scene, int size, unsigned depthFormat);

}  // namespace pineda::demo
