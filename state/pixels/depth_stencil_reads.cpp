#include "state/pixels/depth_stencil_reads.h"

#include <cstring>

namespace pineda::gl {
namespace {

// One row of n stored depths as `Out`, each stored / max converted as store_component does.
// Below 32 bits the quotient is taken as a product with 1 / max (cheaper than a division; the
// loop itself stays scalar at -O2): the same floats, unsigned shorts and unsigned ints for every
// stored value of 16- and 24-bit buffers (tests/state/depth_row_reads_test.cpp checks them all).
template <typename Out, typename Convert>
void depth_row(const uint32_t* src, int n, double max, uint8_t* dst, Convert convert) {
  auto row = [&](auto quotient) {
    for (int i = 0; i < n; ++i) {
      const Out value = convert(quotient(src[i]));
      std::memcpy(dst + sizeof(Out) * static_cast<size_t>(i), &value, sizeof(Out));
    }
  };
  if (max < 4294967295.0) row([reciprocal = 1.0 / max](uint32_t d) { return d * reciprocal; });
  else row([max](uint32_t d) { return d / max; });
}

// depth_row's GL_FLOAT below 32 bits four at a time (vector extensions: -O2 leaves the loop
// scalar): the same products, stored values below 2^31 converted as signed integers.
void float_depth_row(const uint32_t* src, int n, double max, uint8_t* dst) {
  typedef int32_t I4 __attribute__((vector_size(16)));
  typedef double D4 __attribute__((vector_size(32)));
  typedef float F4 __attribute__((vector_size(16)));
  const double reciprocal = 1.0 / max;
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    I4 stored;
    std::memcpy(&stored, src + i, sizeof stored);
    const F4 value = __builtin_convertvector(__builtin_convertvector(stored, D4) * reciprocal, F4);
    std::memcpy(dst + sizeof(GLfloat) * static_cast<size_t>(i), &value, sizeof value);
  }
  depth_row<GLfloat>(src + i, n - i, max, dst + sizeof(GLfloat) * static_cast<size_t>(i),
                     [](double c) { return GLfloat(c); });
}

}  // namespace

bool reads_depth_rows(const PixelMode& mode, GLenum type, bool swap_bytes) {
  return !swap_bytes && mode.depth_scale == 1.f && mode.depth_bias == 0.f &&
         (type == GL_UNSIGNED_INT || type == GL_UNSIGNED_SHORT || type == GL_FLOAT);
}

void read_depth_rows(const raster::DepthBuffer& depth, GLenum type, int x0, int x1, int y0, int y1, uint8_t* first,
                     size_t row_stride) {
  // transfer_depth with scale 1 and bias 0 leaves a stored / max in [0, 1] as it is.
  const double max = depth.bits >= 32 ? 4294967295.0 : double((uint64_t{1} << depth.bits) - 1);
  for (int y = y0; y < y1; ++y) {
    const uint32_t* src = depth.base + depth.stride * y + x0;
    uint8_t* dst = first + row_stride * static_cast<size_t>(y - y0);
    const int n = x1 - x0;
    switch (type) {
      // x + 0.5 truncated is std::llround(x) / std::lround(x) here: checked for every stored value
      // of 16-, 24- and 32-bit depth buffers (std::llround does not vectorize).
      case GL_UNSIGNED_INT:
        depth_row<GLuint>(src, n, max, dst, [](double c) { return GLuint(c * 4294967295.0 + 0.5); });
        break;
      case GL_UNSIGNED_SHORT:
        depth_row<GLushort>(src, n, max, dst, [](double c) { return GLushort(GLuint(c * 65535.0 + 0.5)); });
        break;
      default:
        if (max < 4294967295.0) float_depth_row(src, n, max, dst);
        else depth_row<GLfloat>(src, n, max, dst, [](double c) { return GLfloat(c); });
        break;
    }
  }
}

bool reads_stencil_rows(const PixelMode& mode, GLenum type) {
  return type == GL_UNSIGNED_BYTE && mode.index_shift == 0 && mode.index_offset == 0 && !mode.map_stencil;
}

void read_stencil_rows(const raster::StencilBuffer& stencil, int x0, int x1, int y0, int y1, uint8_t* first,
                       size_t row_stride) {
  for (int y = y0; y < y1; ++y)
    std::memcpy(first + row_stride * static_cast<size_t>(y - y0), stencil.base + stencil.stride * y + x0,
                static_cast<size_t>(x1 - x0));
}

}  // namespace pineda::gl
