// A vertex shader that reads generic attributes alone takes its inputs straight from the
// arrays' elements (no vertex is fetched before it runs): positions from the vertex array,
// integer arrays normalized, disabled arrays' current values, edge flags, and draws of many
// vertices, in pieces on several threads. Expected pixels are exact.
#include <cmath>
#include <vector>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

class ArrayElementInputsTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    clear_to(0, 0, 0, 0);
    link_in_use("attribute vec4 pos; attribute vec4 col; varying vec4 c;\n"
                "void main() { c = col; gl_Position = pos; }\n",
                "varying vec4 c; void main() { gl_FragColor = c; }\n", {{0, "pos"}, {3, "col"}});
  }
  // Attribute 0 from 19 vertices (a batch of 16 and three more, neither a multiple of four past
  // the first twelve), a strip round the viewport's corners: its last triangles, drawn over the
  // others, hold the last vertices.
  void use_corner_strip() {
    const GLfloat corners[4][2] = {{-1.f, -1.f}, {1.f, -1.f}, {-1.f, 1.f}, {1.f, 1.f}};
    for (int v = 0; v < 19; ++v) {
      strip_[v][0] = corners[v % 4][0];
      strip_[v][1] = corners[v % 4][1];
    }
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, strip_);
    glEnableVertexAttribArray(0);
  }
  const GLfloat quad_[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  GLfloat strip_[19][2] = {};
};

// Generic array 0 disabled: attribute 0 is the vertex array's position (GL 2.0 2.7).
TEST_F(ArrayElementInputsTest, PositionFromTheVertexArrayAndNormalizedByteColours) {
  const GLubyte col[16] = {255, 0, 51, 255, 255, 0, 51, 255, 255, 0, 51, 255, 255, 0, 51, 255};
  glVertexPointer(2, GL_FLOAT, 0, quad_);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexAttribPointer(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, col);
  glEnableVertexAttribArray(3);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  EXPECT_EQ(count_pixels({255, 0, 51, 255}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Normalized byte arrays of fewer components than the attribute: the rest are (0, 0, 1), over a
// batch of 16 vertices and three more (vertices four at a time, then one at a time).
TEST_F(ArrayElementInputsTest, NormalizedByteArraysOfFewerComponentsEndInOne) {
  use_corner_strip();
  std::vector<GLubyte> rgb;
  for (int v = 0; v < 19; ++v) rgb.insert(rgb.end(), {51, 102, 0});
  glVertexAttribPointer(3, 3, GL_UNSIGNED_BYTE, GL_TRUE, 0, rgb.data());
  glEnableVertexAttribArray(3);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 19);
  EXPECT_EQ(count_pixels({51, 102, 0, 255}), width() * height());
  const std::vector<GLubyte> red(19, 204);
  glVertexAttribPointer(3, 1, GL_UNSIGNED_BYTE, GL_TRUE, 0, red.data());
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 19);
  EXPECT_EQ(count_pixels({204, 0, 0, 255}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ArrayElementInputsTest, DisabledArraysGiveTheCurrentValue) {
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, quad_);
  glEnableVertexAttribArray(0);
  glDisableVertexAttribArray(3);
  glVertexAttrib4f(3, 0.f, 1.f, 0.f, 1.f);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  EXPECT_EQ(count_pixels({0, 255, 0, 255}), width() * height());
  // An array of fewer components than the attribute: the rest are (0, 0, 1).
  const GLfloat red[8] = {0.2f, 0.f, 0.2f, 0.f, 0.2f, 0.f, 0.2f, 0.f};
  glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, 0, red);
  glEnableVertexAttribArray(3);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  EXPECT_EQ(count_pixels({51, 0, 0, 255}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// 19 vertices: the disabled array's current value reaches every lane.
TEST_F(ArrayElementInputsTest, DisabledArraysGiveTheCurrentValueToEveryVertexOfAPartBatch) {
  use_corner_strip();
  glDisableVertexAttribArray(3);
  glVertexAttrib4f(3, 0.f, 0.4f, 0.8f, 1.f);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 19);
  EXPECT_EQ(count_pixels({0, 102, 204, 255}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Interleaved in a buffer object (position, then four colour floats; 24-byte stride): a colour
// array of 3, 1 and 4 components gives (r, g, b, 1), (r, 0, 0, 1) and the four as they are.
TEST_F(ArrayElementInputsTest, FloatArraysOfEachSizeFromABufferObject) {
  std::vector<GLfloat> data;
  for (int v = 0; v < 4; ++v) data.insert(data.end(), {quad_[2 * v], quad_[2 * v + 1], 0.2f, 0.4f, 0.6f, 0.8f});
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(GLfloat)), data.data(), GL_STATIC_DRAW);
  const GLsizei stride = 6 * sizeof(GLfloat);
  const void* colour = reinterpret_cast<const void*>(2 * sizeof(GLfloat));
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, nullptr);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(3);
  const std::pair<GLint, Rgba> sizes[] = {{3, {51, 102, 153, 255}}, {1, {51, 0, 0, 255}}, {4, {51, 102, 153, 204}}};
  for (const auto& [size, expected] : sizes) {
    glVertexAttribPointer(3, size, GL_FLOAT, GL_FALSE, stride, colour);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    EXPECT_EQ(count_pixels(expected), width() * height()) << size << " components";
  }
  glDeleteBuffers(1, &buffer);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// One pixel-sized square (two triangles) per pixel, coloured by its position: thousands of
// vertices, so the vertex shader runs in pieces, on every thread, and in part batches.
TEST_F(ArrayElementInputsTest, EveryVertexOfALargeDrawGetsItsOwnElement) {
  const int w = width(), h = height();
  std::vector<GLfloat> pos, col;
  std::vector<GLuint> indices;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float x0 = 2.f * float(x) / float(w) - 1.f, x1 = 2.f * float(x + 1) / float(w) - 1.f;
      const float y0 = 2.f * float(y) / float(h) - 1.f, y1 = 2.f * float(y + 1) / float(h) - 1.f;
      const float corners[6][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y0}, {x1, y1}, {x0, y1}};
      for (const auto& c : corners) {
        indices.push_back(GLuint(pos.size() / 2));
        pos.insert(pos.end(), {c[0], c[1]});
        col.insert(col.end(), {float(x) / float(w - 1), float(y) / float(h - 1), 0.5f, 1.f});
      }
    }
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, pos.data());
  glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, 0, col.data());
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(3);
  const auto expect_gradient = [&](const char* draw) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const Rgba expected{int(std::lround(255.0 * x / (w - 1))), int(std::lround(255.0 * y / (h - 1))), 128, 255};
        ASSERT_EQ(pixel(x, y), expected) << draw << " at " << x << ", " << y;
      }
  };
  const GLsizei count = GLsizei(pos.size() / 2);
  glDrawArrays(GL_TRIANGLES, 0, count - 6);  // all but the last square
  EXPECT_EQ(pixel(w - 1, h - 1), (Rgba{0, 0, 0, 0}));
  glDrawArrays(GL_TRIANGLES, count - 6, 6);
  expect_gradient("glDrawArrays");
  clear_to(0, 0, 0, 0);
  // The same vertices through indices, in reverse order (elements far from their position in the draw).
  std::vector<GLuint> reversed(indices.rbegin(), indices.rend());
  glDrawElements(GL_TRIANGLES, GLsizei(reversed.size()), GL_UNSIGNED_INT, reversed.data());
  expect_gradient("glDrawElements");
  // Indices far apart (the draw's vertices are the indexed elements, not a range of them).
  clear_to(0, 0, 0, 0);
  std::vector<GLuint> ends(indices.begin(), indices.begin() + 6);
  ends.insert(ends.end(), indices.end() - 6, indices.end());
  glDrawElements(GL_TRIANGLES, GLsizei(ends.size()), GL_UNSIGNED_INT, ends.data());
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 0, 128, 255}));
  EXPECT_EQ(pixel(w - 1, h - 1), (Rgba{255, 255, 128, 255}));
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), w * h - 2);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Edge flags from the edge flag array hide the same polygon edges as glEdgeFlag does.
TEST_F(ArrayElementInputsTest, EdgeFlagsComeFromTheEdgeFlagArray) {
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  const GLfloat tri[6] = {-0.8f, -0.8f, 0.8f, -0.8f, 0.f, 0.8f};
  const GLfloat white[12] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  const GLboolean flags[3] = {GL_FALSE, GL_TRUE, GL_TRUE};
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, tri);
  glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, 0, white);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(3);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  const int all_edges = count_pixels({255, 255, 255, 255});
  clear_to(0, 0, 0, 0);
  glEdgeFlagPointer(0, flags);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  const int two_edges = count_pixels({255, 255, 255, 255});
  const std::vector<uint8_t> from_arrays = read_all();
  glDisableClientState(GL_EDGE_FLAG_ARRAY);
  glDisableVertexAttribArray(0);
  glDisableVertexAttribArray(3);
  clear_to(0, 0, 0, 0);
  glVertexAttrib4f(3, 1, 1, 1, 1);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 3; ++i) {
    glEdgeFlag(flags[i]);
    glVertexAttrib2f(0, tri[2 * i], tri[2 * i + 1]);
  }
  glEnd();
  EXPECT_GT(two_edges, 0);
  EXPECT_LT(two_edges, all_edges);
  EXPECT_EQ(read_all(), from_arrays);
  // With the edge flag array disabled every array element takes the current flag (false: no edge).
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(3);
  clear_to(0, 0, 0, 0);
  glDrawArrays(GL_TRIANGLES, 0, 3);  // the current flag is flags[2], true
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), all_edges);
  glEdgeFlag(GL_FALSE);
  clear_to(0, 0, 0, 0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
