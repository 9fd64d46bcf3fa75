// Vertex buffer objects (GL 1.5): names, data, mapping, bindings, and drawing from buffers.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstring>
#include <string>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class BufferObjectTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
  }
  GLint buffer_param(GLenum target, GLenum pname) {
    GLint v = -1;
    glGetBufferParameteriv(target, pname, &v);
    return v;
  }
  GLint get_int(GLenum pname) {
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
  }
  // A buffer holding `bytes` bytes of `data`, left bound to `target`.
  GLuint make_buffer(GLenum target, const void* data, size_t bytes) {
    GLuint b = 0;
    glGenBuffers(1, &b);
    glBindBuffer(target, b);
    glBufferData(target, GLsizeiptr(bytes), data, GL_STATIC_DRAW);
    return b;
  }
};

// Two quads as x, y pairs: (0,0)-(8,8) and (16,16)-(20,20).
constexpr GLfloat kQuads[] = {0, 0, 8, 0, 8, 8, 0, 8, 16, 16, 20, 16, 20, 20, 16, 20};

TEST_F(BufferObjectTest, NamesBindingsAndDeletion) {
  GLuint b[2] = {0, 0};
  glGenBuffers(2, b);
  EXPECT_NE(b[0], 0u);
  EXPECT_NE(b[0], b[1]);
  EXPECT_EQ(glIsBuffer(b[0]), GL_FALSE);  // a name becomes a buffer at its first binding
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  EXPECT_EQ(glIsBuffer(b[0]), GL_TRUE);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  EXPECT_EQ(get_int(GL_ARRAY_BUFFER_BINDING), GLint(b[0]));
  EXPECT_EQ(get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING), GLint(b[1]));
  glDeleteBuffers(2, b);
  EXPECT_EQ(glIsBuffer(b[0]), GL_FALSE);
  EXPECT_EQ(get_int(GL_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

  glBindBuffer(GL_TEXTURE_2D, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGenBuffers(-1, b);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDeleteBuffers(-1, b);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(BufferObjectTest, DataSubDataAndParameters) {
  const uint8_t bytes[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  make_buffer(GL_ARRAY_BUFFER, bytes, 8);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 8);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_USAGE), GL_STATIC_DRAW);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), GL_READ_WRITE);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_FALSE);
  const uint8_t patch[2] = {90, 91};
  glBufferSubData(GL_ARRAY_BUFFER, 6, 2, patch);
  uint8_t out[8] = {};
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 8, out);
  const uint8_t expected[8] = {1, 2, 3, 4, 5, 6, 90, 91};
  EXPECT_EQ(std::memcmp(out, expected, 8), 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

  glBufferSubData(GL_ARRAY_BUFFER, 7, 2, patch);  // past the end
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGetBufferSubData(GL_ARRAY_BUFFER, -1, 2, out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBufferData(GL_ARRAY_BUFFER, -4, nullptr, GL_STATIC_DRAW);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBufferData(GL_ARRAY_BUFFER, 4, nullptr, GL_RGBA);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint param = -1;
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_RGBA, &param);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(param, -1);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 8);  // nothing changed by the errors

  glBufferData(GL_ARRAY_BUFFER, 3, nullptr, GL_DYNAMIC_COPY);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 3);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_USAGE), GL_DYNAMIC_COPY);

  glBindBuffer(GL_ARRAY_BUFFER, 0);  // nothing bound: the operations have no buffer
  glBufferData(GL_ARRAY_BUFFER, 4, nullptr, GL_STATIC_DRAW);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY), nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

// glBufferData again at the buffer's size (its store is reused): new contents, zeros without
// data, from a pointer into the buffer's own mapping too, and the mapping ends.
TEST_F(BufferObjectTest, DataAgainAtTheSameSizeReplacesTheContents) {
  const uint8_t first[6] = {1, 2, 3, 4, 5, 6}, second[6] = {9, 8, 7, 6, 5, 4};
  make_buffer(GL_ARRAY_BUFFER, first, 6);
  glBufferData(GL_ARRAY_BUFFER, 6, second, GL_STREAM_DRAW);
  uint8_t out[6] = {};
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 6, out);
  EXPECT_EQ(std::memcmp(out, second, 6), 0);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_USAGE), GL_STREAM_DRAW);

  glBufferData(GL_ARRAY_BUFFER, 6, nullptr, GL_STREAM_DRAW);
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 6, out);
  const uint8_t zeros[6] = {};
  EXPECT_EQ(std::memcmp(out, zeros, 6), 0);

  glBufferData(GL_ARRAY_BUFFER, 6, first, GL_STREAM_DRAW);
  auto* mapped = static_cast<const uint8_t*>(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY));
  ASSERT_NE(mapped, nullptr);
  glBufferData(GL_ARRAY_BUFFER, 6, mapped, GL_STREAM_DRAW);  // its own bytes, in place
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_FALSE);
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 6, out);
  EXPECT_EQ(std::memcmp(out, first, 6), 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BufferObjectTest, MapAndUnmap) {
  const uint8_t zeros[16] = {};
  make_buffer(GL_ARRAY_BUFFER, zeros, 16);
  auto* p = static_cast<uint8_t*>(glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY));
  ASSERT_NE(p, nullptr);
  p[3] = 77;
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_TRUE);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), GL_WRITE_ONLY);
  void* queried = nullptr;
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &queried);
  EXPECT_EQ(queried, p);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY), nullptr);  // already mapped
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBufferSubData(GL_ARRAY_BUFFER, 0, 1, zeros);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_POINTS, 0, 1);  // a draw may not read a mapped buffer
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));

  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &queried);
  EXPECT_EQ(queried, nullptr);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  uint8_t out[4] = {};
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, out);
  EXPECT_EQ(out[3], 77);
  glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE + 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BufferObjectTest, DrawArraysReadsOffsetsIntoTheBuffer) {
  // Interleaved: 4 padding bytes, then per vertex x, y (float) and r, g, b, a (bytes).
  struct Vertex {
    GLfloat x, y;
    GLubyte rgba[4];
  };
  std::vector<uint8_t> store(4 + 4 * sizeof(Vertex));
  const Vertex v[4] = {{2, 2, {0, 255, 0, 255}}, {12, 2, {0, 255, 0, 255}}, {12, 7, {0, 255, 0, 255}},
                       {2, 7, {0, 255, 0, 255}}};
  std::memcpy(store.data() + 4, v, sizeof v);
  const GLuint b = make_buffer(GL_ARRAY_BUFFER, store.data(), store.size());
  glVertexPointer(2, GL_FLOAT, sizeof(Vertex), reinterpret_cast<const void*>(4));
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), reinterpret_cast<const void*>(4 + 8));
  glBindBuffer(GL_ARRAY_BUFFER, 0);  // the arrays keep the buffer they were specified with
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(count_pixels({0, 255, 0, 255}), 10 * 5);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BUFFER_BINDING), GLint(b));
  EXPECT_EQ(get_int(GL_COLOR_ARRAY_BUFFER_BINDING), GLint(b));
  EXPECT_EQ(get_int(GL_NORMAL_ARRAY_BUFFER_BINDING), 0);
  void* ptr = nullptr;
  glGetPointerv(GL_COLOR_ARRAY_POINTER, &ptr);
  EXPECT_EQ(ptr, reinterpret_cast<void*>(12));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // Deleting the buffer unbinds it from the arrays: nothing is drawn from offset 4 then.
  glDeleteBuffers(1, &b);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BUFFER_BINDING), 0);
}

// GL 2.1 2.9: a deleted buffer's bindings in the current context revert to zero, in every array
// (the colour index and generic attribute arrays too), not only the one drawn from.
TEST_F(BufferObjectTest, DeletingABufferUnbindsItFromEveryArray) {
  const uint8_t bytes[64] = {};
  const GLuint b = make_buffer(GL_ARRAY_BUFFER, bytes, sizeof bytes);
  glIndexPointer(GL_FLOAT, 0, reinterpret_cast<const void*>(8));
  glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, 0, reinterpret_cast<const void*>(16));
  glFogCoordPointer(GL_FLOAT, 0, reinterpret_cast<const void*>(4));
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_BUFFER_BINDING), GLint(b));
  GLint attrib = -1;
  glGetVertexAttribiv(3, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &attrib);
  EXPECT_EQ(attrib, GLint(b));
  glDeleteBuffers(1, &b);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(get_int(GL_FOG_COORD_ARRAY_BUFFER_BINDING), 0);
  glGetVertexAttribiv(3, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &attrib);
  EXPECT_EQ(attrib, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BufferObjectTest, DrawElementsReadsIndicesFromTheElementBuffer) {
  make_buffer(GL_ARRAY_BUFFER, kQuads, sizeof kQuads);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  const GLushort indices[] = {99, 4, 5, 6, 7};  // the draw starts at byte 2
  make_buffer(GL_ELEMENT_ARRAY_BUFFER, indices, sizeof indices);
  glColor3f(1, 1, 1);
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_SHORT, reinterpret_cast<const void*>(2));
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 4 * 4);
  EXPECT_EQ(pixel(17, 17), (Rgba{255, 255, 255, 255}));
  glDrawRangeElements(GL_QUADS, 4, 7, 4, GL_UNSIGNED_SHORT, reinterpret_cast<const void*>(2));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BufferObjectTest, OutOfRangeReadsDropTheDraw) {
  make_buffer(GL_ARRAY_BUFFER, kQuads, sizeof kQuads);  // 8 vertices
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glColor3f(1, 1, 1);
  glDrawArrays(GL_QUADS, 4, 8);  // vertices 4..11
  glDrawArrays(GL_QUADS, 2147483640, 8);
  glVertexPointer(2, GL_FLOAT, 0, reinterpret_cast<const void*>(sizeof kQuads));  // offset at the end
  glDrawArrays(GL_QUADS, 0, 4);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  const GLuint far_indices[] = {0, 1, 2, 100000};
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_INT, far_indices);
  const GLuint huge_indices[] = {0, 1, 2, 0xffffffffu};
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_INT, huge_indices);
  const GLubyte in_range[] = {0, 1, 2, 3};
  make_buffer(GL_ELEMENT_ARRAY_BUFFER, in_range, sizeof in_range);
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, reinterpret_cast<const void*>(1));  // 1 byte past the end
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, reinterpret_cast<const void*>(~uintptr_t{0}));
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, nullptr);  // the same, in range, draws
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 8 * 8);
}

// A draw whose arrays a draw before found inside their buffer is not let through on that alone
// after the store shrank (arrays_ready keeps what it found while the state stays the same).
TEST_F(BufferObjectTest, ADrawAfterTheBufferShrankIsDropped) {
  const GLuint b = make_buffer(GL_ARRAY_BUFFER, kQuads, sizeof kQuads);  // 8 vertices
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glColor3f(1, 1, 1);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 8 * 8);
  clear_to(0, 0, 0, 0);
  glDrawArrays(GL_QUADS, 0, 8);  // a larger draw of the same state: both quads
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 8 * 8 + 4 * 4);
  clear_to(0, 0, 0, 0);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, 3 * 2 * sizeof(GLfloat), kQuads, GL_STATIC_DRAW);  // 3 vertices
  glDrawArrays(GL_QUADS, 0, 4);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BufferObjectTest, ClientAttribStackKeepsBufferBindings) {
  const GLuint a = make_buffer(GL_ARRAY_BUFFER, kQuads, sizeof kQuads);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  const GLuint b = make_buffer(GL_ARRAY_BUFFER, kQuads, sizeof kQuads);
  glVertexPointer(3, GL_FLOAT, 0, nullptr);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BUFFER_BINDING), GLint(b));
  glPopClientAttrib();
  EXPECT_EQ(get_int(GL_ARRAY_BUFFER_BINDING), GLint(a));
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BUFFER_BINDING), GLint(a));
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_SIZE), 2);
}

TEST_F(BufferObjectTest, DisplayListsCopyBufferDataAndDoNotCompileBufferCommands) {
  const GLuint b = make_buffer(GL_ARRAY_BUFFER, kQuads, sizeof kQuads);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glDrawArrays(GL_QUADS, 0, 4);
  glBufferData(GL_ARRAY_BUFFER, 4, nullptr, GL_STREAM_DRAW);  // executed now, not compiled
  glEndList();
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 4);
  EXPECT_EQ(get_int(GL_ARRAY_BUFFER_BINDING), GLint(b));
  glColor3f(1, 0, 0);
  glCallList(list);  // the vertices were read when the list was compiled
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), 8 * 8);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 4);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BufferObjectTest, ArbNamesShareTheObjects) {
  GLuint b = 0;
  glGenBuffersARB(1, &b);
  glBindBufferARB(GL_ARRAY_BUFFER_ARB, b);
  const uint32_t v = 0xdeadbeef;
  glBufferDataARB(GL_ARRAY_BUFFER_ARB, 4, &v, GL_STREAM_READ_ARB);
  uint32_t out = 0;
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, &out);
  EXPECT_EQ(out, v);
  EXPECT_EQ(glIsBufferARB(b), GL_TRUE);
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_ARB_vertex_buffer_object"), std::string::npos);
}

TEST_F(BufferObjectTest, FogAndSecondaryColorArraysTakeBufferOffsets) {
  const GLfloat fog[] = {0.25f, 0.5f, 0.5f, 0.5f};
  const GLuint b = make_buffer(GL_ARRAY_BUFFER, fog, sizeof fog);
  glFogCoordPointer(GL_FLOAT, 0, nullptr);  // offset 0 of the buffer
  glSecondaryColorPointer(3, GL_FLOAT, 0, reinterpret_cast<const void*>(4096));  // an offset, not an address
  EXPECT_EQ(get_int(GL_FOG_COORD_ARRAY_BUFFER_BINDING), GLint(b));
  EXPECT_EQ(get_int(GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING), GLint(b));
  glEnableClientState(GL_FOG_COORD_ARRAY);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  make_buffer(GL_ARRAY_BUFFER, kQuads, sizeof kQuads);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glColor3f(1, 1, 1);
  glDrawArrays(GL_QUADS, 0, 4);  // the secondary colours lie outside their buffer: dropped
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 8 * 8);
  clear_to(0, 0, 0, 0);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glFogCoordPointer(GL_FLOAT, 0, reinterpret_cast<const void*>(4));  // holds vertices 0..2 only
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BufferObjectTest, BufferCommandsInsideBeginEndAreErrors) {
  GLuint b = 0;
  glBegin(GL_POINTS);
  glGenBuffers(1, &b);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(b, 0u);
}

}  // namespace
}  // namespace pineda::test
