// Rectangle textures (ARB_texture_rectangle) through the fixed-function pipeline: coordinates
// in texels ([0, width] x [0, height]), nearest and linear filtering, the clamping wrap modes,
// depth comparison, and the target's place between cube maps and 3D textures.
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/texel_images.h"
#include "tests/e2e/support/window_quad.h"

namespace pineda::test {
namespace {

constexpr int kWidth = kRectWidth, kHeight = kRectHeight;
Rgba texel(int i, int j) { return rect_texel(i, j); }

class TextureRectangleTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 1);
    load_rect_image();
    glEnable(GL_TEXTURE_RECTANGLE_ARB);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  }
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
  void filter(GLenum f) {
    glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, f);
    glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAG_FILTER, f);
  }
  void wrap(GLenum w) {
    glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, w);
    glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_T, w);
  }
  // Window pixels [x0, x0 + w] x [y0, y0 + h] with texture coordinates [s0, s1] x [t0, t1].
  void textured_rect(float x0, float y0, float w, float h, float s0, float t0, float s1, float t1) {
    draw_textured_rect(x0, y0, x0 + w, y0 + h, s0, t0, s1, t1);
  }
  // One pixel at (x, y) whose texture coordinates are (s, t) at every corner.
  Rgba sample_at(float s, float t, int x = 1, int y = 1) {
    textured_rect(float(x), float(y), 1, 1, s, t, s, t);
    return pixel(x, y);
  }
};

TEST_F(TextureRectangleTest, OneToOneMappingReadsEveryTexelWithEitherFilter) {
  for (GLenum f : {GL_NEAREST, GL_LINEAR}) {
    filter(f);
    textured_rect(2, 4, kWidth, kHeight, 0, 0, kWidth, kHeight);
    for (int j = 0; j < kHeight; ++j)
      for (int i = 0; i < kWidth; ++i) EXPECT_EQ(pixel(2 + i, 4 + j), texel(i, j)) << f << " " << i << "," << j;
  }
}

TEST_F(TextureRectangleTest, NearestMagnificationByTwo) {
  filter(GL_NEAREST);
  textured_rect(0, 0, 2 * kWidth, 2 * kHeight, 0, 0, kWidth, kHeight);
  for (int y = 0; y < 2 * kHeight; ++y)
    for (int x = 0; x < 2 * kWidth; ++x) EXPECT_EQ(pixel(x, y), texel(x / 2, y / 2)) << x << "," << y;
}

TEST_F(TextureRectangleTest, LinearHalfwayBetweenTexels) {
  filter(GL_LINEAR);
  // s = 2 lies halfway between the centres of texels 1 and 2; t = 0.5 is row 0's centre.
  const Rgba a = texel(1, 0), b = texel(2, 0);
  EXPECT_EQ(sample_at(2.f, 0.5f), (Rgba{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2, 255}));
  // A quarter of the way: s = 1.75 weighs texel 1 by 3/4 and texel 2 by 1/4 (exact in 8 bits).
  const Rgba q = sample_at(1.75f, 0.5f, 3, 3);
  EXPECT_EQ(q[0], (3 * a[0] + b[0]) / 4);  // 70: exact
  EXPECT_EQ(q[1], a[1]);
}

TEST_F(TextureRectangleTest, ClampToEdgeAndClampOutsideTheImage) {
  for (GLenum f : {GL_NEAREST, GL_LINEAR}) {
    filter(f);
    wrap(GL_CLAMP_TO_EDGE);
    EXPECT_EQ(sample_at(-7.f, 1.5f), texel(0, 1)) << f;
    EXPECT_EQ(sample_at(kWidth + 9.f, kHeight + 1.f), texel(kWidth - 1, kHeight - 1)) << f;
  }
  // GL_CLAMP with nearest filtering reads the edge texels too.
  filter(GL_NEAREST);
  wrap(GL_CLAMP);
  EXPECT_EQ(sample_at(-7.f, 100.f), texel(0, kHeight - 1));
}

TEST_F(TextureRectangleTest, ClampToBorderAndClampBlendTheBorderColour) {
  const float border[4] = {1.f, 1.f, 1.f, 1.f};
  glTexParameterfv(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_BORDER_COLOR, border);
  filter(GL_NEAREST);
  wrap(GL_CLAMP_TO_BORDER);
  EXPECT_EQ(sample_at(-0.25f, 0.5f), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(sample_at(kWidth + 0.25f, 0.5f, 3, 3), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(sample_at(0.25f, 0.5f, 5, 5), texel(0, 0));
  // GL_CLAMP, linear, at the image's corner (0, 0): a quarter texel (0, 0), three quarters border.
  filter(GL_LINEAR);
  wrap(GL_CLAMP);
  const Rgba c = sample_at(0.f, 0.f, 7, 7);
  const Rgba t = texel(0, 0);
  EXPECT_EQ(c[0], (t[0] + 3 * 255 + 2) / 4);
  EXPECT_EQ(c[1], (t[1] + 3 * 255 + 2) / 4);
}

TEST_F(TextureRectangleTest, DepthComparison) {
  const float depths[4] = {0.25f, 0.75f, 0.25f, 0.75f};
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 2);
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  filter(GL_NEAREST);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  auto compared = [&](float s, float r, int x) {
    glBegin(GL_QUADS);
    glTexCoord3f(s, 0.5f, r);
    glVertex2f(float(x), 1);
    glVertex2f(float(x + 1), 1);
    glVertex2f(float(x + 1), 2);
    glVertex2f(float(x), 2);
    glEnd();
    return pixel(x, 1);
  };
  EXPECT_EQ(compared(0.5f, 0.5f, 1), (Rgba{0, 0, 0, 255}));  // 0.5 <= 0.25 fails
  EXPECT_EQ(compared(1.5f, 0.5f, 2), (Rgba{255, 255, 255, 255}));  // 0.5 <= 0.75 passes
  EXPECT_EQ(compared(0.5f, 0.f, 3), (Rgba{255, 255, 255, 255}));
}

TEST_F(TextureRectangleTest, GetTexImageAndCopyTexSubImage) {
  std::vector<uint8_t> out(size_t(kWidth) * kHeight * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  for (int j = 0; j < kHeight; ++j)
    for (int i = 0; i < kWidth; ++i)
      for (int c = 0; c < 4; ++c) EXPECT_EQ(out[4 * (j * kWidth + i) + c], texel(i, j)[c]) << i << "," << j;
  // Window pixels (3, 2) and (4, 2) into texels (1, 1) and (2, 1).
  glDisable(GL_TEXTURE_RECTANGLE_ARB);
  glColor4ub(7, 77, 177, 255);
  draw_rect(3, 2, 5, 3);
  glCopyTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, 1, 1, 3, 2, 2, 1);
  glGetTexImage(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  for (int i = 0; i < kWidth; ++i) {
    const Rgba want = i == 1 || i == 2 ? Rgba{7, 77, 177, 255} : texel(i, 1);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(out[4 * (kWidth + i) + c], want[c]) << i;
  }
  glCopyTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 3, 2, 7, 1, 0);
  GLint width = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_RECTANGLE_ARB, 0, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 7);
  glGetTexImage(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  // Texels 0 and 1 are window pixels (3, 2) and (4, 2), drawn; texel 2 is (5, 2), cleared.
  for (int c = 0; c < 4; ++c) EXPECT_EQ(out[c], (Rgba{7, 77, 177, 255})[c]);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(out[4 + c], (Rgba{7, 77, 177, 255})[c]);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(out[8 + c], 0);
}

TEST_F(TextureRectangleTest, TargetPriorityBetweenCubeMapAnd3D) {
  filter(GL_NEAREST);
  const uint8_t green[4] = {0, 255, 0, 255}, blue[4] = {0, 0, 255, 255};
  glBindTexture(GL_TEXTURE_2D, 3);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_3D, 4);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
  glEnable(GL_TEXTURE_3D);
  EXPECT_EQ(sample_at(0.5f, 0.5f), texel(0, 0));  // the rectangle over 3D and 2D
  glBindTexture(GL_TEXTURE_CUBE_MAP, 5);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  for (GLenum face = GL_TEXTURE_CUBE_MAP_POSITIVE_X; face <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z; ++face)
    glTexImage2D(face, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, blue);
  glEnable(GL_TEXTURE_CUBE_MAP);
  EXPECT_EQ(sample_at(0.5f, 0.5f, 3, 3), (Rgba{0, 0, 255, 255}));  // the cube map over the rectangle
  glDisable(GL_TEXTURE_CUBE_MAP);
  glDisable(GL_TEXTURE_RECTANGLE_ARB);
  EXPECT_EQ(sample_at(0.5f, 0.5f, 5, 5), (Rgba{0, 255, 0, 255}));
}

}  // namespace
}  // namespace pineda::test
