// Primitives whose vertices take the same slot of the post-transform window cache (indices a
// multiple of its 1024 slots apart) in an indexed draw: the same pixels as immediate mode.
// A line's second end used to replace its first end's window under the pointer held to it,
// drawing a line from the second end to itself.
#include <cstdint>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class WindowCacheCollisionTest : public GlTest, public ::testing::WithParamInterface<GLenum> {};

TEST_P(WindowCacheCollisionTest, VerticesSharingASlotDrawAsInImmediateMode) {
  pixel_projection();
  // Vertices 0, 1024 and 2048 span the surface; the others lie outside it.
  std::vector<float> xy(2 * 2100, -5.f);
  xy[0] = 2, xy[1] = 2;
  xy[2 * 1024] = 28, xy[2 * 1024 + 1] = 20;
  xy[2 * 2048] = 4, xy[2 * 2048 + 1] = 28;
  glVertexPointer(2, GL_FLOAT, 0, xy.data());
  glEnableClientState(GL_VERTEX_ARRAY);
  // Enough indices for the draw to transform the whole range of vertices and index into it.
  std::vector<uint32_t> indices(600, 5);
  indices[0] = 0, indices[1] = 1024, indices[2] = 2048;
  clear_to(0, 0, 0, 0);
  glBegin(GetParam());
  for (const uint32_t i : indices) glVertex2f(xy[2 * i], xy[2 * i + 1]);
  glEnd();
  const std::vector<uint8_t> expected = read_all();
  size_t lit = 0;
  for (size_t i = 0; i < expected.size(); i += 4) lit += expected[i] != 0;
  EXPECT_GT(lit, 20u);
  clear_to(0, 0, 0, 0);
  glDrawElements(GetParam(), static_cast<GLsizei>(indices.size()), GL_UNSIGNED_INT, indices.data());
  EXPECT_EQ(read_all(), expected);
}

INSTANTIATE_TEST_SUITE_P(Modes, WindowCacheCollisionTest, ::testing::Values(GL_LINES, GL_TRIANGLES),
                         [](const ::testing::TestParamInfo<GLenum>& info) {
                           return info.param == GL_LINES ? "Lines" : "Triangles";
                         });

}  // namespace
}  // namespace pineda::test
