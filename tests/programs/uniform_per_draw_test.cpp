// Draws that each change a uniform take their ShaderDraw from the context's pool
// (state/programs/shader_draw_pool.h), which hands one out again only once no queued draw holds
// it. Many more one-pixel draws than the pool keeps, and than two scenes hold, each with its own
// uniforms (read by both stages, and folded into each stage's uniform values), give every pixel
// its own draw's colour: frame after frame, with one thread and with two.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

constexpr int kSide = 128;  // one draw per pixel: 16384 draws

class UniformPerDrawTest : public ProgramTest, public ::testing::WithParamInterface<const char*> {
 protected:
  SurfaceSpec spec() const override { return {kSide, kSide}; }
  void SetUp() override {
    {  // the context's rasterizer threads (read when it is made)
      const char* old = std::getenv("PINEDA_THREADS");
      const std::string kept = old ? old : "";
      setenv("PINEDA_THREADS", GetParam(), 1);
      ProgramTest::SetUp();
      if (old) setenv("PINEDA_THREADS", kept.c_str(), 1);
      else unsetenv("PINEDA_THREADS");
    }
    // The pixel's place and colour: uniforms alone, `place * 2.0 - 1.0` and `shade * scale` are
    // each stage's uniform values.
    link_in_use("attribute vec2 corner; uniform vec2 place;\n"
                "void main() { gl_Position = vec4(place * 2.0 - 1.0 + corner, 0.0, 1.0); }\n",
                "uniform vec4 shade; uniform float scale;\n"
                "void main() { gl_FragColor = shade * scale; }\n",
                {{0, "corner"}});
    place_ = glGetUniformLocation(current_program(), "place");
    shade_ = glGetUniformLocation(current_program(), "shade");
    scale_ = glGetUniformLocation(current_program(), "scale");
    glUniform1f(scale_, 0.5f);
    // A point at the pixel's centre: place (x + 1/2, y + 1/2) / side.
    static const GLfloat kCorner[2] = {0.f, 0.f};
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, kCorner);
    glEnableVertexAttribArray(0);
  }
  GLuint current_program() const {
    GLint p = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &p);
    return GLuint(p);
  }
  // Byte channel c of pixel i's colour in frame `frame` (even, so that halving is exact).
  static uint8_t channel(int i, int c, int frame) { return uint8_t(2 * ((i * (c + 3) + 17 * frame + 41 * c) % 128)); }

  // Every pixel drawn by a draw of its own, its uniforms set just before.
  void draw_frame(int frame) {
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    for (int i = 0; i < kSide * kSide; ++i) {
      const int x = i % kSide, y = i / kSide;
      glUniform2f(place_, (float(x) + 0.5f) / kSide, (float(y) + 0.5f) / kSide);
      glUniform4f(shade_, channel(i, 0, frame) * 2.f / 255.f, channel(i, 1, frame) * 2.f / 255.f,
                  channel(i, 2, frame) * 2.f / 255.f, 1.f);
      glDrawArrays(GL_POINTS, 0, 1);
    }
  }
  // The pixels whose colour is not their draw's.
  int wrong_pixels(int frame) {
    const std::vector<uint8_t> all = read_all();
    int wrong = 0;
    for (int i = 0; i < kSide * kSide; ++i) {
      const uint8_t* p = &all[size_t(i) * 4];
      wrong += p[0] != channel(i, 0, frame) || p[1] != channel(i, 1, frame) || p[2] != channel(i, 2, frame) ||
               p[3] != 128;
    }
    return wrong;
  }

  GLint place_ = -1, shade_ = -1, scale_ = -1;
};

TEST_P(UniformPerDrawTest, EveryDrawKeepsItsOwnUniforms) {
  for (int frame = 0; frame < 3; ++frame) {
    draw_frame(frame);
    EXPECT_EQ(wrong_pixels(frame), 0) << "frame " << frame;
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A draw queued while later draws change the uniforms: the queued ones keep theirs until they run.
TEST_P(UniformPerDrawTest, QueuedDrawsKeepTheirUniformsWhileLaterDrawsChangeThem) {
  draw_frame(0);
  glFlush();  // some draws may run now, the rest stay queued
  for (int frame = 1; frame < 3; ++frame) {
    glFinish();
    draw_frame(frame);
  }
  EXPECT_EQ(wrong_pixels(2), 0);
}

INSTANTIATE_TEST_SUITE_P(Threads, UniformPerDrawTest, ::testing::Values("1", "2"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return std::string("Threads") + info.param; });

}  // namespace
}  // namespace pineda::test
