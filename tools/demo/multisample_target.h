#pragma once
// A multisampled render target: an RGBA8 and a DEPTH_COMPONENT24 renderbuffer of `samples`
// samples (glRenderbufferStorageMultisample) in a framebuffer object, resolved by the caller
// with glBlitFramebuffer. Leaves the window-system framebuffer bound.

namespace pineda::demo {

struct MultisampleTarget {
  unsigned color = 0, depth = 0, framebuffer = 0;
};

// An incomplete framebuffer, or one whose GL_SAMPLES is not `samples`, is reported on stderr
// under `scene`.
MultisampleTarget makeMultisampleTarget(const char* scene, int width, int height, int samples);

}  // namespace pineda::demo
