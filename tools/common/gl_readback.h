#pragma once
// Reading the current GL framebuffer back: colour as a top-down RGBA8 image, the stencil
// buffer, and GL strings. Needs a current context.
#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "png_io.h"

namespace pineda::tools {

Image readFramebuffer(int width, int height);
std::vector<std::uint8_t> readStencil(int width, int height);
// glGetString that never returns null ("(null)" instead).
const char* glString(GLenum name);

}  // namespace pineda::tools
