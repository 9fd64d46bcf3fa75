// Client arrays: DrawArrays, DrawElements, ArrayElement and InterleavedArrays draw exactly
// what the same vertices draw in immediate mode.
#define GL_GLEXT_PROTOTYPES  // the GL_EXT_vertex_array names
#include <algorithm>
#include <array>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

struct Vertex {
  float s, t;
  float r, g, b, a;
  float x, y, z;
};

// A fan of smooth-shaded, textured triangles over the surface.
const std::vector<Vertex> kVertices = {
    {0.5f, 0.5f, 1, 1, 1, 1, 16, 16, 0}, {0, 0, 1, 0, 0, 1, 1, 1, 0},    {1, 0, 0, 1, 0, 1, 31, 2, 0},
    {1, 1, 0, 0, 1, 1, 30, 30, 0},       {0, 1, 1, 1, 0, 0.5f, 3, 29, 0}, {0, 0, 0, 1, 1, 1, 1, 1, 0},
};

class ClientArraysTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    const uint8_t texels[2 * 2 * 4] = {255, 255, 255, 255, 128, 128, 128, 255, 200, 100, 50, 255, 50, 100, 200, 255};
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
  }

  std::vector<uint8_t> immediate_reference(GLenum mode, const std::vector<unsigned>& order) {
    clear_to(0, 0, 0, 0);
    glBegin(mode);
    for (unsigned i : order) {
      const Vertex& v = kVertices[i];
      glTexCoord2f(v.s, v.t);
      glColor4f(v.r, v.g, v.b, v.a);
      glVertex3f(v.x, v.y, v.z);
    }
    glEnd();
    return read_all();
  }

  void set_separate_arrays() {
    const Vertex* base = kVertices.data();
    glTexCoordPointer(2, GL_FLOAT, sizeof(Vertex), &base->s);
    glColorPointer(4, GL_FLOAT, sizeof(Vertex), &base->r);
    glVertexPointer(3, GL_FLOAT, sizeof(Vertex), &base->x);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_VERTEX_ARRAY);
  }
};

TEST_F(ClientArraysTest, DrawArraysEqualsImmediateMode) {
  const auto reference = immediate_reference(GL_TRIANGLE_FAN, {0, 1, 2, 3, 4, 5});
  ASSERT_GT(std::count_if(reference.begin(), reference.end(), [](uint8_t b) { return b != 0; }), 1000);
  clear_to(0, 0, 0, 0);
  set_separate_arrays();
  glDrawArrays(GL_TRIANGLE_FAN, 0, 6);
  EXPECT_EQ(read_all(), reference);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// GL_EXT_vertex_array: the same arrays under the extension's names, with their `count`.
TEST_F(ClientArraysTest, ExtVertexArrayEqualsImmediateMode) {
  const auto reference = immediate_reference(GL_TRIANGLE_FAN, {0, 1, 2, 3, 4, 5});
  clear_to(0, 0, 0, 0);
  const Vertex* base = kVertices.data();
  glTexCoordPointerEXT(2, GL_FLOAT, sizeof(Vertex), 6, &base->s);
  glColorPointerEXT(4, GL_FLOAT, sizeof(Vertex), 6, &base->r);
  glVertexPointerEXT(3, GL_FLOAT, sizeof(Vertex), 6, &base->x);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArraysEXT(GL_TRIANGLE_FAN, 0, 6);
  EXPECT_EQ(read_all(), reference);
  void* pointer = nullptr;
  glGetPointervEXT(GL_VERTEX_ARRAY_POINTER, &pointer);
  EXPECT_EQ(pointer, static_cast<const void*>(&base->x));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glVertexPointerEXT(3, GL_FLOAT, 0, -1, &base->s);  // a negative count: nothing changes
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGetPointervEXT(GL_VERTEX_ARRAY_POINTER, &pointer);
  EXPECT_EQ(pointer, static_cast<const void*>(&base->x));
}

TEST_F(ClientArraysTest, DrawArraysWithFirst) {
  const auto reference = immediate_reference(GL_TRIANGLES, {2, 3, 4});
  clear_to(0, 0, 0, 0);
  set_separate_arrays();
  glDrawArrays(GL_TRIANGLES, 2, 3);
  EXPECT_EQ(read_all(), reference);
}

TEST_F(ClientArraysTest, DrawElementsEqualsImmediateModeForEveryIndexType) {
  const std::vector<unsigned> order = {0, 1, 2, 0, 3, 4, 0, 4, 1};
  const auto reference = immediate_reference(GL_TRIANGLES, order);
  set_separate_arrays();
  const std::vector<GLubyte> u8(order.begin(), order.end());
  const std::vector<GLushort> u16(order.begin(), order.end());
  const std::vector<GLuint> u32(order.begin(), order.end());
  clear_to(0, 0, 0, 0);
  glDrawElements(GL_TRIANGLES, 9, GL_UNSIGNED_BYTE, u8.data());
  EXPECT_EQ(read_all(), reference);
  clear_to(0, 0, 0, 0);
  glDrawElements(GL_TRIANGLES, 9, GL_UNSIGNED_SHORT, u16.data());
  EXPECT_EQ(read_all(), reference);
  clear_to(0, 0, 0, 0);
  glDrawElements(GL_TRIANGLES, 9, GL_UNSIGNED_INT, u32.data());
  EXPECT_EQ(read_all(), reference);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ClientArraysTest, ArrayElementEqualsImmediateMode) {
  const std::vector<unsigned> order = {3, 0, 2, 4};
  const auto reference = immediate_reference(GL_QUADS, order);
  set_separate_arrays();
  clear_to(0, 0, 0, 0);
  glBegin(GL_QUADS);
  for (unsigned i : order) glArrayElement(GLint(i));
  glEnd();
  EXPECT_EQ(read_all(), reference);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ClientArraysTest, InterleavedT2fC4fN3fV3fEqualsImmediateMode) {
  const auto reference = immediate_reference(GL_TRIANGLE_FAN, {0, 1, 2, 3, 4, 5});
  std::vector<float> interleaved;
  for (const Vertex& v : kVertices)
    interleaved.insert(interleaved.end(), {v.s, v.t, v.r, v.g, v.b, v.a, 0, 0, 1, v.x, v.y, v.z});
  clear_to(0, 0, 0, 0);
  glInterleavedArrays(GL_T2F_C4F_N3F_V3F, 0, interleaved.data());
  EXPECT_EQ(glIsEnabled(GL_NORMAL_ARRAY), GL_TRUE);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 6);
  EXPECT_EQ(read_all(), reference);
}

TEST_F(ClientArraysTest, InterleavedC4ubV2fWithStride) {
  glDisable(GL_TEXTURE_2D);
  clear_to(0, 0, 0, 0);
  glBegin(GL_TRIANGLES);
  glColor4ub(255, 0, 0, 255);
  glVertex2f(1, 1);
  glColor4ub(0, 255, 0, 255);
  glVertex2f(30, 4);
  glColor4ub(0, 0, 255, 255);
  glVertex2f(10, 28);
  glEnd();
  const auto reference = read_all();
  struct Packed {
    GLubyte c[4];
    float x, y;
    float padding;
  };
  const Packed packed[3] = {{{255, 0, 0, 255}, 1, 1, 0}, {{0, 255, 0, 255}, 30, 4, 0}, {{0, 0, 255, 255}, 10, 28, 0}};
  clear_to(0, 0, 0, 0);
  glInterleavedArrays(GL_C4UB_V2F, sizeof(Packed), packed);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_COORD_ARRAY), GL_FALSE);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(read_all(), reference);
}

TEST_F(ClientArraysTest, IntegerAndShortVertexTypes) {
  glDisable(GL_TEXTURE_2D);
  const GLshort shorts[] = {2, 2, 12, 2, 12, 12, 2, 12};
  const GLint ints[] = {16, 16, 26, 16, 26, 26, 16, 26};
  const GLubyte colors[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 0};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, colors);
  clear_to(0, 0, 0, 0);
  glVertexPointer(2, GL_SHORT, 0, shorts);
  glDrawArrays(GL_QUADS, 0, 4);
  glVertexPointer(2, GL_INT, 0, ints);
  glDrawArrays(GL_QUADS, 0, 4);
  const auto drawn = read_all();
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  clear_to(0, 0, 0, 0);
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) {
    glColor3ubv(colors + 3 * i);
    glVertex2sv(shorts + 2 * i);
  }
  for (int i = 0; i < 4; ++i) {
    glColor3ubv(colors + 3 * i);
    glVertex2iv(ints + 2 * i);
  }
  glEnd();
  EXPECT_EQ(read_all(), drawn);
}

TEST_F(ClientArraysTest, ErrorsAndDisabledVertexArray) {
  set_separate_arrays();
  clear_to(0, 0, 0, 0);
  glDrawArrays(GL_TRIANGLES, 0, -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDrawArrays(GL_POLYGON + 1, 0, 3);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  const GLubyte idx[3] = {0, 1, 2};
  glDrawElements(GL_TRIANGLES, 3, GL_BYTE, idx);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glDrawElements(GL_TRIANGLES, -3, GL_UNSIGNED_BYTE, idx);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBegin(GL_TRIANGLES);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  // Without the vertex array nothing is drawn.
  glDisableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ClientArraysTest, ArrayElementUpdatesTheCurrentAttributes) {
  set_separate_arrays();
  glArrayElement(2);
  GLfloat c[4], t[4];
  glGetFloatv(GL_CURRENT_COLOR, c);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
  EXPECT_EQ(c[0], 0.f);
  EXPECT_EQ(c[1], 1.f);
  EXPECT_EQ(t[0], 1.f);
  EXPECT_EQ(t[1], 0.f);
  EXPECT_EQ(t[3], 1.f);
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(ClientArraysTest, SparseIndicesEqualImmediateMode) {
  glDisable(GL_TEXTURE_2D);
  std::vector<float> positions(2 * 200, 0.f);
  std::vector<float> colours(4 * 200, 0.f);
  const unsigned used[] = {0, 97, 199, 150};
  const float xy[4][2] = {{2, 2}, {30, 3}, {29, 30}, {4, 28}};
  const float rgba[4][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 0, 1}};
  for (int i = 0; i < 4; ++i) {
    positions[2 * used[i]] = xy[i][0];
    positions[2 * used[i] + 1] = xy[i][1];
    std::copy(rgba[i], rgba[i] + 4, &colours[4 * used[i]]);
  }
  clear_to(0, 0, 0, 0);
  glBegin(GL_LINE_LOOP);
  for (int i = 0; i < 4; ++i) {
    glColor4fv(rgba[i]);
    glVertex2fv(xy[i]);
  }
  glEnd();
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) {
    glColor4fv(rgba[i]);
    glVertex2f(xy[i][0] / 2 + 8, xy[i][1] / 2 + 8);
  }
  glEnd();
  const auto reference = read_all();

  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions.data());
  glColorPointer(4, GL_FLOAT, 0, colours.data());
  clear_to(0, 0, 0, 0);
  const GLuint indices[4] = {used[0], used[1], used[2], used[3]};
  glDrawElements(GL_LINE_LOOP, 4, GL_UNSIGNED_INT, indices);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(8, 8, 0);
  glScalef(0.5f, 0.5f, 1);
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_INT, indices);
  glLoadIdentity();
  EXPECT_EQ(read_all(), reference);
}

// glArrayElement fetches with the array draws' plan, kept from call to call while nothing but
// glArrayElement ran: values that calls between them change (the current colour of a disabled
// colour array, the vertex array's pointer, the colour array enabled) reach the next element,
// called directly and compiled into a display list (which takes the elements' values as it
// compiles).
TEST_F(ClientArraysTest, ArrayElementSeesWhatChangedSinceTheLastOne) {
  glDisable(GL_TEXTURE_2D);
  const GLfloat first[4][2] = {{2.5f, 2.5f}, {6.5f, 2.5f}, {10.5f, 2.5f}, {14.5f, 2.5f}};
  const GLfloat second[4][2] = {{2.5f, 9.5f}, {6.5f, 9.5f}, {10.5f, 9.5f}, {14.5f, 9.5f}};
  const GLfloat colors[4][3] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {1, 1, 1}};
  glVertexPointer(2, GL_FLOAT, 0, first);
  glColorPointer(3, GL_FLOAT, 0, colors);
  glEnableClientState(GL_VERTEX_ARRAY);
  auto points = [&] {
    glBegin(GL_POINTS);
    glColor3f(1, 0, 0);
    glArrayElement(0);
    glArrayElement(1);
    glColor3f(0, 1, 0);
    glArrayElement(2);
    glEnd();
    glVertexPointer(2, GL_FLOAT, 0, second);
    glBegin(GL_POINTS);
    glArrayElement(0);
    glEnd();
    glEnableClientState(GL_COLOR_ARRAY);
    glBegin(GL_POINTS);
    glArrayElement(3);
    glEnd();
    glDisableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, first);
  };
  auto expect_points = [&](const char* how) {
    const std::vector<uint8_t> all = read_all();
    auto at = [&](int x, int y) {
      const uint8_t* p = &all[(size_t(y) * size_t(width()) + size_t(x)) * 4];
      return std::array<int, 3>{p[0], p[1], p[2]};
    };
    EXPECT_EQ(at(2, 2), (std::array<int, 3>{255, 0, 0})) << how;
    EXPECT_EQ(at(6, 2), (std::array<int, 3>{255, 0, 0})) << how;
    EXPECT_EQ(at(10, 2), (std::array<int, 3>{0, 255, 0})) << how;
    EXPECT_EQ(at(2, 9), (std::array<int, 3>{0, 255, 0})) << how;    // the second vertex array
    EXPECT_EQ(at(14, 9), (std::array<int, 3>{255, 255, 255})) << how;  // the colour array's
    EXPECT_EQ(at(14, 2), (std::array<int, 3>{0, 0, 0})) << how;
  };
  clear_to(0, 0, 0, 0);
  points();
  expect_points("called");
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  points();
  glEndList();
  clear_to(0, 0, 0, 0);
  glCallList(list);
  expect_points("from a list");
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Found by the API fuzzer (UBSan: offset applied to a null pointer): with an array buffer bound,
// glInterleavedArrays' pointer is an offset, 0 among them; each array starts at its place in it.
TEST_F(ClientArraysTest, InterleavedArraysAtOffsetZeroOfABuffer) {
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glInterleavedArrays(GL_C3F_V3F, 0, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  void* color = reinterpret_cast<void*>(1);
  void* vertex = nullptr;
  glGetPointerv(GL_COLOR_ARRAY_POINTER, &color);
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &vertex);
  EXPECT_EQ(color, nullptr);
  EXPECT_EQ(vertex, reinterpret_cast<void*>(12));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glDeleteBuffers(1, &buffer);
}

}  // namespace
}  // namespace pineda::test
