// OpenGL ES 2.0 texture image units: 8 (ES 2.0 requires at least 8 of each kind), every one
// sampled by a program with its own texture; glActiveTexture takes GL_TEXTURE0..7.
#include <gtest/gtest.h>

#include <string>

#include "tests/es2/es2_context.h"

namespace pineda::es2_test {
namespace {

constexpr const char* kVertex = "attribute vec4 a_pos; void main() { gl_Position = a_pos; }\n";

// Unit i holds a 1x1 texture of (1 << i, 10 * i, 255 - i, 255); u_which picks the sampler,
// 8 sums the red of all eight.
constexpr const char* kFragment = R"(
precision mediump float;
uniform sampler2D t0, t1, t2, t3, t4, t5, t6, t7;
uniform int u_which;
void main() {
  vec2 c = vec2(0.5);
  vec4 r = texture2D(t0, c);
  if (u_which == 1) r = texture2D(t1, c);
  if (u_which == 2) r = texture2D(t2, c);
  if (u_which == 3) r = texture2D(t3, c);
  if (u_which == 4) r = texture2D(t4, c);
  if (u_which == 5) r = texture2D(t5, c);
  if (u_which == 6) r = texture2D(t6, c);
  if (u_which == 7) r = texture2D(t7, c);
  if (u_which == 8) r = vec4(texture2D(t0, c).r + texture2D(t1, c).r + texture2D(t2, c).r + texture2D(t3, c).r +
                             texture2D(t4, c).r + texture2D(t5, c).r + texture2D(t6, c).r + texture2D(t7, c).r,
                             0.0, 0.0, 1.0);
  gl_FragColor = r;
}
)";

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}

class Es2TextureUnits : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(context.ok()) << context.error(); }
  Es2Context context{8, 8};
};

TEST_F(Es2TextureUnits, Limits) {
  EXPECT_EQ(get_int(GL_MAX_TEXTURE_IMAGE_UNITS), 8);
  EXPECT_EQ(get_int(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS), 8);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glActiveTexture(GL_TEXTURE7);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_ACTIVE_TEXTURE), GL_TEXTURE7);
  glActiveTexture(GL_TEXTURE8);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_ACTIVE_TEXTURE), GL_TEXTURE7);
}

TEST_F(Es2TextureUnits, EightSamplersReadTheirOwnUnits) {
  std::string log;
  const GLuint program = build_program(kVertex, kFragment, {{"a_pos", 0}}, &log);
  ASSERT_NE(program, 0u) << log;
  GLuint tex[8] = {};
  glGenTextures(8, tex);
  for (int i = 0; i < 8; ++i) {
    const GLubyte texel[4] = {GLubyte(1 << i), GLubyte(10 * i), GLubyte(255 - i), 255};
    glActiveTexture(GL_TEXTURE0 + i);
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), GLint(tex[i]));
  }
  glUseProgram(program);
  for (int i = 0; i < 8; ++i) glUniform1i(glGetUniformLocation(program, ("t" + std::to_string(i)).c_str()), i);
  glUniform1i(glGetUniformLocation(program, "t0"), 8);  // past the last unit
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  const float pos[] = {-1, -1, 0, 1, 3, -1, 0, 1, -1, 3, 0, 1};
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, pos);
  glEnableVertexAttribArray(0);
  const GLint which = glGetUniformLocation(program, "u_which");
  for (int i = 0; i < 9; ++i) {
    glUniform1i(which, i);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    const uint32_t expected = i == 8 ? 0xFF0000FFu : uint32_t(1 << i) << 24 | uint32_t(10 * i) << 16 | uint32_t(255 - i) << 8 | 0xFFu;
    EXPECT_EQ(read_pixel(3, 3), expected) << "u_which " << i;
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::es2_test
