#include "driver/osmesa_pixels.h"

#include <GL/osmesa.h>

#include <cstring>

namespace pineda::osmesa {
namespace {

// Where R, G, B, A sit in a user pixel; -1 when absent.
struct Layout {
  int r, g, b, a;
};

Layout layout_of(GLenum format) {
  switch (format) {
    case OSMESA_RGBA: return {0, 1, 2, 3};
    case OSMESA_BGRA: return {2, 1, 0, 3};
    case OSMESA_ARGB: return {1, 2, 3, 0};
    case OSMESA_RGB: return {0, 1, 2, -1};
    case OSMESA_BGR: return {2, 1, 0, -1};
    default: return {0, 1, 2, 3};
  }
}

}  // namespace

int bytes_per_pixel(GLenum format) {
  switch (format) {
    case OSMESA_RGBA:
    case OSMESA_BGRA:
    case OSMESA_ARGB: return 4;
    case OSMESA_RGB:
    case OSMESA_BGR: return 3;
    default: return 0;
  }
}

bool renders_in_place(GLenum format) { return format == OSMESA_RGBA || format == OSMESA_BGRA; }

void store(const uint8_t* rgba, const UserImage& image) {
  const Layout l = layout_of(image.format);
  const int bpp = bytes_per_pixel(image.format);
  for (int y = 0; y < image.height; ++y) {
    const uint8_t* src = rgba + static_cast<size_t>(y) * image.width * 4;
    uint8_t* dst = image.row(y);
    for (int x = 0; x < image.width; ++x, src += 4, dst += bpp) {
      dst[l.r] = src[0];
      dst[l.g] = src[1];
      dst[l.b] = src[2];
      if (l.a >= 0) dst[l.a] = src[3];
    }
  }
}

void load(uint8_t* rgba, const UserImage& image) {
  const Layout l = layout_of(image.format);
  const int bpp = bytes_per_pixel(image.format);
  for (int y = 0; y < image.height; ++y) {
    uint8_t* dst = rgba + static_cast<size_t>(y) * image.width * 4;
    const uint8_t* src = image.row(y);
    for (int x = 0; x < image.width; ++x, src += bpp, dst += 4) {
      dst[0] = src[l.r];
      dst[1] = src[l.g];
      dst[2] = src[l.b];
      dst[3] = l.a >= 0 ? src[l.a] : 255;
    }
  }
}

}  // namespace pineda::osmesa
