// Drawing with ES 2.0 programs: a textured, shaded triangle with exact pixels, generic
// attribute 0 used as something other than the position, its current value, and a draw
// without a program (nothing drawn, no error).
#include <gtest/gtest.h>

#include <string>

#include "tests/es2/es2_context.h"

namespace pineda::es2_test {
namespace {

constexpr const char* kTexturedVertex = R"(
attribute vec2 a_uv;
attribute vec4 a_pos;
varying vec2 v_uv;
void main() { v_uv = a_uv; gl_Position = a_pos; }
)";

constexpr const char* kTexturedFragment = R"(
precision mediump float;
uniform sampler2D u_tex;
uniform vec4 u_tint;
varying vec2 v_uv;
void main() { gl_FragColor = texture2D(u_tex, v_uv) * u_tint; }
)";

class Es2Draw : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(context.ok()) << context.error(); }
  // A program of one `color` (GLSL vec4 text) in use, over four client-array vertices at
  // location 3: (9, 9), then a triangle (-1, -1), (3, -1), (-1, 3) over the whole pbuffer; and
  // an element buffer of `bytes` bytes bound. False when the program does not build.
  bool solid_indexed_setup(const std::string& color, GLsizeiptr bytes) {
    const char* vs = "attribute vec2 a_pos; void main() { gl_Position = vec4(a_pos, 0.0, 1.0); }\n";
    const std::string fs = "precision mediump float; void main() { gl_FragColor = " + color + "; }\n";
    const GLuint program = build_program(vs, fs.c_str(), {{"a_pos", 3}});
    if (program == 0) return false;
    glUseProgram(program);
    glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, 0, kPositions);
    glEnableVertexAttribArray(3);
    GLuint buffer = 0;
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, bytes, nullptr, GL_DYNAMIC_DRAW);
    return true;
  }
  static constexpr float kPositions[] = {9, 9, -1, -1, 3, -1, -1, 3};
  Es2Context context{16, 16};
};

// A triangle over the whole 16x16 pbuffer samples a 2x2 NEAREST texture: each quadrant is one
// texel times the tint. a_uv is bound to location 0: in ES 2.0 it is not the position.
TEST_F(Es2Draw, TexturedTriangleExactPixels) {
  std::string log;
  const GLuint program = build_program(kTexturedVertex, kTexturedFragment, {{"a_uv", 0}, {"a_pos", 1}}, &log);
  ASSERT_NE(program, 0u) << log;
  const uint8_t texels[] = {254, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 200, 100, 50, 255};
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glUseProgram(program);
  glUniform1i(glGetUniformLocation(program, "u_tex"), 0);
  glUniform4f(glGetUniformLocation(program, "u_tint"), 0.5f, 1.f, 1.f, 1.f);
  const float uv[] = {0, 0, 2, 0, 0, 2};
  const float pos[] = {-1, -1, 0, 1, 3, -1, 0, 1, -1, 3, 0, 1};
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, uv);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 0, pos);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const uint32_t expected = y < 8 ? (x < 8 ? 0x7F0000FFu : 0x00FF00FFu) : (x < 8 ? 0x0000FFFFu : 0x646432FFu);
      ASSERT_EQ(read_pixel(x, y), expected) << x << "," << y;
    }
}

// Only the lower-left half is covered; the rest keeps the clear colour. The colour comes from
// attribute 0's current value (no array), which ES 2.0 keeps like any other attribute's.
TEST_F(Es2Draw, Attribute0CurrentValueAndHalfCoverage) {
  const char* vs = "attribute vec4 a_color; attribute vec2 a_pos; varying vec4 v_color;\n"
                   "void main() { v_color = a_color; gl_Position = vec4(a_pos, 0.0, 1.0); }\n";
  const char* fs = "precision mediump float; varying vec4 v_color; void main() { gl_FragColor = v_color; }\n";
  std::string log;
  const GLuint program = build_program(vs, fs, {{"a_color", 0}, {"a_pos", 1}}, &log);
  ASSERT_NE(program, 0u) << log;
  glUseProgram(program);
  glVertexAttrib4f(0, 0.2f, 0.4f, 0.6f, 1.f);
  GLfloat current[4] = {};
  glGetVertexAttribfv(0, GL_CURRENT_VERTEX_ATTRIB, current);
  EXPECT_EQ(current[0], 0.2f);
  EXPECT_EQ(current[3], 1.f);
  const float pos[] = {-1, -1, 1, -1, -1, 1};
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 0, pos);
  glEnableVertexAttribArray(1);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(read_pixel(0, 0), 0x336699FFu);
  EXPECT_EQ(read_pixel(5, 5), 0x336699FFu);
  EXPECT_EQ(read_pixel(15, 15), 0xFFFFFFFFu);
  EXPECT_EQ(read_pixel(9, 9), 0xFFFFFFFFu);
}

// ES 2.0 has no fixed function: a draw without a program draws nothing and is no error.
TEST_F(Es2Draw, NoProgramDrawsNothing) {
  const float pos[] = {-1, -1, 3, -1, -1, 3};
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, pos);
  glEnableVertexAttribArray(0);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  const GLushort indices[] = {0, 1, 2};
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, indices);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(read_pixel(4, 4), 0x0000FFFFu);
}

// GL_OES_element_index_uint and GL_OES_mapbuffer: 32-bit indices out of a mapped-then-unmapped
// element buffer.
TEST_F(Es2Draw, UintIndicesFromMappedBuffer) {
  ASSERT_TRUE(solid_indexed_setup("vec4(1.0, 0.0, 1.0, 1.0)", 3 * sizeof(GLuint)));
  auto map = reinterpret_cast<PFNGLMAPBUFFEROESPROC>(eglGetProcAddress("glMapBufferOES"));
  auto unmap = reinterpret_cast<PFNGLUNMAPBUFFEROESPROC>(eglGetProcAddress("glUnmapBufferOES"));
  ASSERT_TRUE(map && unmap);
  EXPECT_EQ(map(GL_ELEMENT_ARRAY_BUFFER, 0x88B8), nullptr);  // READ_ONLY: not an ES 2.0 access
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  auto* indices = static_cast<GLuint*>(map(GL_ELEMENT_ARRAY_BUFFER, GL_WRITE_ONLY_OES));
  ASSERT_NE(indices, nullptr);
  indices[0] = 1;
  indices[1] = 2;
  indices[2] = 3;
  EXPECT_EQ(unmap(GL_ELEMENT_ARRAY_BUFFER), GL_TRUE);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(read_pixel(7, 7), 0xFF00FFFFu);
  EXPECT_EQ(read_pixel(15, 0), 0xFF00FFFFu);
}

// GL_EXT_map_buffer_range: indices written through a mapped range, and its errors.
TEST_F(Es2Draw, IndicesWrittenThroughAMappedRange) {
  ASSERT_TRUE(solid_indexed_setup("vec4(0.0, 1.0, 1.0, 1.0)", 6 * sizeof(GLushort)));
  auto map = reinterpret_cast<PFNGLMAPBUFFERRANGEEXTPROC>(eglGetProcAddress("glMapBufferRangeEXT"));
  auto flush = reinterpret_cast<PFNGLFLUSHMAPPEDBUFFERRANGEEXTPROC>(eglGetProcAddress("glFlushMappedBufferRangeEXT"));
  auto unmap = reinterpret_cast<PFNGLUNMAPBUFFEROESPROC>(eglGetProcAddress("glUnmapBufferOES"));
  ASSERT_TRUE(map && flush && unmap);
  EXPECT_EQ(map(GL_ELEMENT_ARRAY_BUFFER, 0, 0, GL_MAP_WRITE_BIT_EXT), nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(map(GL_ELEMENT_ARRAY_BUFFER, 4, 10, GL_MAP_WRITE_BIT_EXT), nullptr);  // past the end
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  // Indices 3..5 of the buffer: the second triangle's.
  auto* indices = static_cast<GLushort*>(map(GL_ELEMENT_ARRAY_BUFFER, 3 * sizeof(GLushort), 3 * sizeof(GLushort),
                                             GL_MAP_WRITE_BIT_EXT | GL_MAP_FLUSH_EXPLICIT_BIT_EXT));
  ASSERT_NE(indices, nullptr);
  indices[0] = 1;
  indices[1] = 2;
  indices[2] = 3;
  flush(GL_ELEMENT_ARRAY_BUFFER, 0, 3 * sizeof(GLushort));
  EXPECT_EQ(unmap(GL_ELEMENT_ARRAY_BUFFER), GL_TRUE);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, reinterpret_cast<const void*>(3 * sizeof(GLushort)));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(read_pixel(7, 7), 0x00FFFFFFu);
  GLint flags = -1;
  glGetBufferParameteriv(GL_ELEMENT_ARRAY_BUFFER, 0x911F, &flags);  // GL_BUFFER_ACCESS_FLAGS: not ES 2.0's
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

}  // namespace
}  // namespace pineda::es2_test
