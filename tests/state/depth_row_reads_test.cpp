// Every stored value of 16- and 24-bit depth buffers read by glReadPixels' depth rows
// (state/pixels/depth_stencil_reads.h) as GL_UNSIGNED_INT, GL_UNSIGNED_SHORT and GL_FLOAT: each
// is the general path's value of stored / (2^bits - 1), which the rows compute by a product with
// the reciprocal instead.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "state/pixels/depth_stencil_reads.h"

namespace pineda {
namespace {

// The rows of a buffer holding 0 .. 2^bits - 1, 4096 to a row, read as `type`.
template <typename Out>
std::vector<Out> read_every_value(int bits, GLenum type) {
  constexpr int kWidth = 4096;
  const int rows = (1 << bits) / kWidth;
  std::vector<uint32_t> stored(size_t(kWidth) * rows);
  for (size_t i = 0; i < stored.size(); ++i) stored[i] = uint32_t(i);
  const raster::DepthBuffer depth{stored.data(), kWidth, bits, 0};
  std::vector<Out> out(stored.size());
  gl::read_depth_rows(depth, type, 0, kWidth, 0, rows, reinterpret_cast<uint8_t*>(out.data()), kWidth * sizeof(Out));
  return out;
}

TEST(DepthRowReads, EveryStoredValueIsTheQuotientsConversion) {
  for (const int bits : {16, 24}) {
    const double max = double((1u << bits) - 1);
    const std::vector<GLuint> uints = read_every_value<GLuint>(bits, GL_UNSIGNED_INT);
    const std::vector<GLushort> ushorts = read_every_value<GLushort>(bits, GL_UNSIGNED_SHORT);
    const std::vector<GLfloat> floats = read_every_value<GLfloat>(bits, GL_FLOAT);
    size_t wrong = 0;
    for (uint32_t d = 0; d < uints.size(); ++d) {
      const double c = d / max;
      wrong += uints[d] != GLuint(std::llround(c * 4294967295.0));
      wrong += ushorts[d] != GLushort(std::lround(c * 65535.0));
      wrong += std::memcmp(&floats[d], &static_cast<const GLfloat&>(GLfloat(c)), sizeof(GLfloat)) != 0;
    }
    EXPECT_EQ(wrong, 0u) << bits << " bits";
    EXPECT_EQ(uints.back(), 4294967295u);
    EXPECT_EQ(floats.back(), 1.f);
  }
}

}  // namespace
}  // namespace pineda
