#include "gl_readback.h"

#include <algorithm>

namespace pineda::tools {

Image readFramebuffer(int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(std::size_t(width) * height * 4);
  std::vector<std::uint8_t> bottomUp(image.rgba.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
  const std::size_t rowBytes = std::size_t(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(bottomUp.data() + rowBytes * (height - 1 - y), rowBytes, image.rgba.data() + rowBytes * y);
  return image;
}

std::vector<std::uint8_t> readStencil(int width, int height) {
  std::vector<std::uint8_t> stencil(std::size_t(width) * height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data());
  return stencil;
}

const char* glString(GLenum name) {
  const GLubyte* value = glGetString(name);
  return value ? reinterpret_cast<const char*>(value) : "(null)";
}

}  // namespace pineda::tools
