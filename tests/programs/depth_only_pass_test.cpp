// A program's draw that writes no colour (colour mask off) after early depth tests: Pineda runs
// no shader for it (raster/shader_quads.cpp, runs_shader), and the depth buffer and the
// occlusion query's count must be those of the same draw with colour writes on, the colour
// buffer untouched, with one sample a pixel and with four. Triangles from a few pixels (blocks
// of several triangles) to tens of pixels across (whole blocks), over one another.
#include <random>
#include <vector>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

const char* const kDepthOnlyVertex = R"(#version 120
attribute vec4 position;
varying vec4 v_position;
void main() {
  v_position = position;
  gl_Position = position;
})";

const char* const kDepthOnlyFragment = R"(#version 120
varying vec4 v_position;
void main() { gl_FragColor = vec4(fract(v_position.xyz * 7.0), 1.0); })";

class DepthOnlyPassTest : public ProgramTest {
 protected:
  SurfaceSpec spec() const override { return {64, 64, 24, 8}; }

  struct Result {
    std::vector<uint32_t> depth;
    std::vector<uint8_t> color;
    GLuint samples = 0;
  };

  // Into the framebuffer object `multisampled` when not 0 (its colour and depth resolved into
  // the window's buffers by a blit, then read there).
  Result render(const std::vector<float>& positions, bool color_writes, GLuint multisampled = 0) {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const GLboolean write = color_writes ? GL_TRUE : GL_FALSE;
    glColorMask(write, write, write, write);
    GLuint query = 0;
    glGenQueries(1, &query);
    glBeginQuery(GL_SAMPLES_PASSED, query);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, positions.data());
    glEnableVertexAttribArray(0);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(positions.size() / 4));
    glEndQuery(GL_SAMPLES_PASSED);
    Result r;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &r.samples);
    glDeleteQueries(1, &query);
    if (multisampled) {
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled);
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
      glBlitFramebuffer(0, 0, 64, 64, 0, 0, 64, 64, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    r.depth.resize(64 * 64);
    glReadPixels(0, 0, 64, 64, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, r.depth.data());
    r.color = read_all();
    if (multisampled) glBindFramebuffer(GL_FRAMEBUFFER, multisampled);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return r;
  }

  // 600 triangles of about 19 or 3 pixels across, at random depths.
  static std::vector<float> triangles() {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> unit(0.f, 1.f);
    std::vector<float> positions;
    for (int t = 0; t < 600; ++t) {
      const float size = t % 3 == 0 ? 0.6f : 0.1f;
      const float cx = unit(random) * 1.8f - 0.9f, cy = unit(random) * 1.8f - 0.9f;
      for (int v = 0; v < 3; ++v) {
        positions.insert(positions.end(), {cx + (unit(random) - 0.5f) * size, cy + (unit(random) - 0.5f) * size,
                                           unit(random) * 1.8f - 0.9f, 1.f});
      }
    }
    return positions;
  }

  static void expect_same_depths(const Result& depth_only, const Result& with_color) {
    int differing = 0, written = 0;
    for (size_t i = 0; i < with_color.depth.size(); ++i) {
      differing += depth_only.depth[i] != with_color.depth[i];
      written += with_color.depth[i] != 0xFFFFFFFFu;
    }
    EXPECT_EQ(differing, 0);
    EXPECT_GT(written, 2000);  // most of the 4096 pixels
  }
};

TEST_F(DepthOnlyPassTest, DepthAndSamplesAsWithColourWrites) {
  link_in_use(kDepthOnlyVertex, kDepthOnlyFragment, {{0, "position"}});
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  const std::vector<float> positions = triangles();
  const Result with_color = render(positions, true);
  const Result depth_only = render(positions, false);
  EXPECT_EQ(depth_only.samples, with_color.samples);
  EXPECT_GT(with_color.samples, 3000u);
  expect_same_depths(depth_only, with_color);
  // The colour buffer keeps the clear colour where the colour mask is off.
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(depth_only.color, read_all());
  EXPECT_NE(with_color.color, depth_only.color);
}

// The same into a framebuffer object of four samples (shade_sample_quads): the samples counted,
// and each pixel's depth as a blit resolves it.
TEST_F(DepthOnlyPassTest, MultisampledDepthAndSamplesAsWithColourWrites) {
  link_in_use(kDepthOnlyVertex, kDepthOnlyFragment, {{0, "position"}});
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  GLuint framebuffer = 0, renderbuffers[2] = {0, 0};
  glGenFramebuffers(1, &framebuffer);
  glGenRenderbuffers(2, renderbuffers);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  const GLenum formats[2] = {GL_RGBA8, GL_DEPTH_COMPONENT24};
  const GLenum points[2] = {GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT};
  for (int i = 0; i < 2; ++i) {
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[i]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, formats[i], 64, 64);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, points[i], GL_RENDERBUFFER, renderbuffers[i]);
  }
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  ASSERT_EQ(samples, 4);

  const std::vector<float> positions = triangles();
  const Result with_color = render(positions, true, framebuffer);
  const Result depth_only = render(positions, false, framebuffer);
  EXPECT_EQ(depth_only.samples, with_color.samples);
  EXPECT_GT(with_color.samples, 4 * 3000u);
  expect_same_depths(depth_only, with_color);
  // The resolved colour is the clear colour everywhere when the draw writes none.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(depth_only.color, read_all());
  EXPECT_NE(with_color.color, depth_only.color);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteRenderbuffers(2, renderbuffers);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
