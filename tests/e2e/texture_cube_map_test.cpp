// Cube maps (GL 1.3): the face and the face coordinates a direction selects (table 3.19),
// wrap modes applied within a face, mipmaps, cube completeness, per-face images, generated
// mipmaps, NORMAL_MAP and REFLECTION_MAP texture coordinates, and the error codes.
#include <limits>
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/texel_images.h"

namespace pineda::test {
namespace {

constexpr GLenum kFaces[6] = {GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_CUBE_MAP_NEGATIVE_X,
                              GL_TEXTURE_CUBE_MAP_POSITIVE_Y, GL_TEXTURE_CUBE_MAP_NEGATIVE_Y,
                              GL_TEXTURE_CUBE_MAP_POSITIVE_Z, GL_TEXTURE_CUBE_MAP_NEGATIVE_Z};

// Texel (i, j) of face f in a 2x2 cube map.
Rgba face_texel(int f, int i, int j) { return {40 * f + 10, 100 * i + 50, 100 * j + 50, 255}; }

std::vector<uint8_t> face_texels(int f, int n) {
  std::vector<uint8_t> t;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
        for (int c : face_texel(f, i, j)) t.push_back(uint8_t(c));
  return t;
}

struct Direction {
  float x, y, z;
};

// The direction whose face coordinates on face f are (sc, tc) / |ma| = (a, b), inverting
// GL 1.3 table 3.19 (+X: sc = -rz, tc = -ry; -X: sc = rz, tc = -ry; +Y: sc = rx, tc = rz;
// -Y: sc = rx, tc = -rz; +Z: sc = rx, tc = -ry; -Z: sc = -rx, tc = -ry).
Direction toward(int f, float a, float b) {
  switch (f) {
    case 0: return {1, -b, -a};
    case 1: return {-1, -b, a};
    case 2: return {a, 1, b};
    case 3: return {a, -1, -b};
    case 4: return {a, -b, 1};
    default: return {-a, -b, -1};
  }
}

class CubeMapTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 1);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  }
  void load_faces(int n) {
    for (int f = 0; f < 6; ++f) {
      const std::vector<uint8_t> t = face_texels(f, n);
      glTexImage2D(kFaces[f], 0, GL_RGBA, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
    }
  }
  // A 2x2 pixel square at (x, y) with one direction at every corner.
  void square(float x, float y, Direction d) {
    glTexCoord3f(d.x, d.y, d.z);
    glBegin(GL_QUADS);
    glVertex2f(x, y);
    glVertex2f(x + 2, y);
    glVertex2f(x + 2, y + 2);
    glVertex2f(x, y + 2);
    glEnd();
  }
  // A w x w square whose direction sweeps face f from a = -1 to 1 (left to right), b fixed.
  void sweep(float x, float y, float w, int f, float b) {
    const Direction left = toward(f, -1, b), right = toward(f, 1, b);
    glBegin(GL_QUADS);
    glTexCoord3f(left.x, left.y, left.z);
    glVertex2f(x, y);
    glTexCoord3f(right.x, right.y, right.z);
    glVertex2f(x + w, y);
    glVertex2f(x + w, y + w);
    glTexCoord3f(left.x, left.y, left.z);
    glVertex2f(x, y + w);
    glEnd();
  }
};

TEST_F(CubeMapTest, EachFaceAndTexelSelectedByDirection) {
  load_faces(2);
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        // Texel centres sit at face coordinates -0.5 and 0.5; scale the direction by 3 to
        // show that only the ratio to the major axis counts.
        const Direction d = toward(f, i ? 0.5f : -0.5f, j ? 0.5f : -0.5f);
        const float x = float(5 * f), y = float(5 * (2 * j + i));
        square(x, y, {3 * d.x, 3 * d.y, 3 * d.z});
        EXPECT_TRUE(near_rgba(pixel(int(x), int(y)), face_texel(f, i, j))) << "face " << f << " " << i << "," << j;
      }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A zero, NaN or infinite direction still samples a defined texel: each reads as the +X
// face's centre, s = t = 0.5 (NEAREST: texel (1, 1) of the 2x2 face).
TEST_F(CubeMapTest, DegenerateDirectionsReadADefinedTexel) {
  load_faces(2);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const Direction cases[] = {{0, 0, 0}, {nan, nan, nan}, {inf, 0, 0}, {nan, 0, 0}};
  int i = 0;
  for (const Direction& d : cases) {
    square(float(3 * i), 0, d);
    EXPECT_TRUE(near_rgba(pixel(3 * i, 0), face_texel(0, 1, 1))) << "case " << i;
    ++i;
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(CubeMapTest, WrapModesApplyWithinTheFace) {
  load_faces(2);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  // Face coordinate a = -0.9: s = 0.05, u = 0.05 * 2 - 0.5 = -0.4; b = -0.5: t on row 0's centre.
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  square(0, 0, toward(4, -0.9f, -0.5f));
  EXPECT_TRUE(near_rgba(pixel(0, 0), face_texel(4, 0, 0), 1));
  // REPEAT wraps to the same face's other column (0.4 of it), not to the neighbouring face.
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_REPEAT);
  square(4, 0, toward(4, -0.9f, -0.5f));
  EXPECT_TRUE(near_rgba(pixel(4, 0), {170, 90, 50, 255}, 1));  // green 0.6 * 50 + 0.4 * 150
}

TEST_F(CubeMapTest, MipLevelChosenOnTheFace) {
  const Rgba colours[4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
  for (int level = 0, n = 8; level < 4; ++level, n /= 2)
    for (GLenum face : kFaces) {
      const std::vector<uint8_t> t = solid_texels(n * n, colours[level]);
      glTexImage2D(face, level, GL_RGBA, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
    }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  sweep(0, 0, 8, 4, 0.f);   // 8 texels over 8 pixels: level 0
  sweep(10, 0, 2, 1, 0.f);  // 8 texels over 2 pixels: level 2
  sweep(0, 10, 4, 2, 0.f);  // 8 texels over 4 pixels: level 1
  EXPECT_TRUE(near_rgba(pixel(4, 4), colours[0]));
  EXPECT_TRUE(near_rgba(pixel(11, 1), colours[2]));
  EXPECT_TRUE(near_rgba(pixel(2, 12), colours[1]));
}

// A face drawn at its level's size, 3x3 pixels at an odd position: the 2x2 quads reach past
// the face's edges, where their outer pixels' directions select other faces; every pixel
// still reads level 1 of the 6x6 / 3x3 / 1x1 chain (piglit cubemap npot).
TEST_F(CubeMapTest, QuadsReachingPastAFaceEdgeKeepTheLevel) {
  const Rgba colours[3] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}};
  for (int level = 0, n = 6; level < 3; ++level, n = n == 6 ? 3 : 1)
    for (GLenum face : kFaces) {
      const std::vector<uint8_t> t = solid_texels(n * n, colours[level]);
      glTexImage2D(face, level, GL_RGBA, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
    }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  for (int f = 0; f < 6; ++f) {
    const float x = float(1 + 5 * f), y = 5;
    const Direction corner[4] = {toward(f, -1, -1), toward(f, 1, -1), toward(f, 1, 1), toward(f, -1, 1)};
    const float vx[4] = {x, x + 3, x + 3, x}, vy[4] = {y, y, y + 3, y + 3};
    glBegin(GL_QUADS);
    for (int v = 0; v < 4; ++v) {
      glTexCoord3f(corner[v].x, corner[v].y, corner[v].z);
      glVertex2f(vx[v], vy[v]);
    }
    glEnd();
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(near_rgba(pixel(int(x) + i, int(y) + j), colours[1])) << "face " << f << " " << i << "," << j;
  }
}

TEST_F(CubeMapTest, IncompleteCubeDisablesTheUnit) {
  glColor4ub(7, 8, 9, 255);
  for (int f = 0; f < 5; ++f) {  // -Z missing
    const std::vector<uint8_t> t = face_texels(f, 2);
    glTexImage2D(kFaces[f], 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  }
  square(0, 0, toward(0, 0.5f, 0.5f));
  EXPECT_TRUE(near_rgba(pixel(0, 0), {7, 8, 9, 255}));
  const std::vector<uint8_t> big = face_texels(5, 4);
  glTexImage2D(kFaces[5], 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, big.data());  // another size
  square(0, 0, toward(0, 0.5f, 0.5f));
  EXPECT_TRUE(near_rgba(pixel(0, 0), {7, 8, 9, 255}));
  glTexImage2D(kFaces[5], 0, GL_LUMINANCE, 2, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, big.data());  // another format
  square(0, 0, toward(0, 0.5f, 0.5f));
  EXPECT_TRUE(near_rgba(pixel(0, 0), {7, 8, 9, 255}));
  const std::vector<uint8_t> t = face_texels(5, 2);
  glTexImage2D(kFaces[5], 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  square(0, 0, toward(0, 0.5f, 0.5f));
  EXPECT_TRUE(near_rgba(pixel(0, 0), face_texel(0, 1, 1)));
  // Mipmapped filtering needs every face's chain.
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  for (int f = 0; f < 5; ++f) glTexImage2D(kFaces[f], 1, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  square(0, 0, toward(0, 0.5f, 0.5f));
  EXPECT_TRUE(near_rgba(pixel(0, 0), {7, 8, 9, 255}));
  glTexImage2D(kFaces[5], 1, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  square(0, 0, toward(0, 0.5f, 0.5f));
  EXPECT_TRUE(near_rgba(pixel(0, 0), face_texel(0, 1, 1)));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(CubeMapTest, GetTexImageReadsEachFace) {
  load_faces(2);
  for (int f = 0; f < 6; ++f) {
    std::vector<uint8_t> out(16);
    glGetTexImage(kFaces[f], 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    EXPECT_EQ(out, face_texels(f, 2)) << f;
  }
  GLint size = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, GL_TEXTURE_WIDTH, &size);
  EXPECT_EQ(size, 2);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(CubeMapTest, SubImageAndCopiesAddressOneFace) {
  load_faces(2);
  const std::vector<uint8_t> white = solid_texels(1, {255, 255, 255, 255});
  glTexSubImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, 1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white.data());
  glDisable(GL_TEXTURE_CUBE_MAP);
  glColor4ub(30, 60, 90, 255);
  square(0, 0, {0, 0, 1});
  glCopyTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, 0, 1, 0, 0, 1, 1);
  glCopyTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_X, 1, GL_RGBA, 0, 0, 1, 1, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  std::vector<uint8_t> out(16);
  glGetTexImage(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(Rgba({out[4], out[5], out[6], out[7]}), Rgba({255, 255, 255, 255}));
  EXPECT_EQ(Rgba({out[0], out[1], out[2], out[3]}), face_texel(5, 0, 0));
  glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(Rgba({out[8], out[9], out[10], out[11]}), Rgba({30, 60, 90, 255}));
  EXPECT_EQ(Rgba({out[0], out[1], out[2], out[3]}), face_texel(2, 0, 0));
  glGetTexImage(GL_TEXTURE_CUBE_MAP_NEGATIVE_X, 1, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(Rgba({out[0], out[1], out[2], out[3]}), Rgba({30, 60, 90, 255}));
}

TEST_F(CubeMapTest, GenerateMipmapPerFace) {
  load_faces(2);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_GENERATE_MIPMAP, GL_TRUE);
  const std::vector<uint8_t> t = face_texels(3, 2);
  glTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  uint8_t out[4] = {};
  glGetTexImage(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(Rgba({out[0], out[1], out[2], out[3]}), Rgba({130, 100, 100, 255}));  // the 2x2 average
  GLint w = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 1, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 0);  // the other faces are untouched
}

TEST_F(CubeMapTest, ErrorCodes) {
  const std::vector<uint8_t> t = face_texels(0, 4);
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));  // not square
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));  // the cube, not a face
  glTexImage1D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexImage3D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 2, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint max = 0;
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &max);
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Z, 0, GL_RGBA, max * 2, max * 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Z, -1, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGBA, 0, 0, 4, 2, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 0, 0, 4, 4, 0);  // copies take no proxy
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCopyTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCopyTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_RGBA, 0, 0, 4, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCopyTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 0, 0, 4, 4, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // the face has no image
  uint8_t out[16];
  glGetTexImage(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint v = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  // A proxy that fits takes the size; one that does not is zeroed without an error.
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(v, 16);
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, max * 2, max * 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(v, 0);
}

TEST_F(CubeMapTest, CubeMapWinsOverThreeDimensions) {
  load_faces(2);
  const std::vector<uint8_t> green = solid_texels(8, {0, 255, 0, 255});
  glBindTexture(GL_TEXTURE_3D, 2);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, green.data());
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_3D);
  square(0, 0, toward(4, 0.5f, 0.5f));
  EXPECT_TRUE(near_rgba(pixel(0, 0), face_texel(4, 1, 1)));
  glDisable(GL_TEXTURE_CUBE_MAP);
  square(0, 0, {0.25f, 0.25f, 0.25f});
  EXPECT_TRUE(near_rgba(pixel(0, 0), {0, 255, 0, 255}));
}

// NORMAL_MAP and REFLECTION_MAP generate s, t, r from the eye-space normal and the
// reflection of the eye-to-vertex vector about it.
class CubeMapTexGenTest : public CubeMapTest {
 protected:
  void SetUp() override {
    CubeMapTest::SetUp();
    load_faces(2);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, 1, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
  }
  void set_mode(GLenum mode) {
    for (GLenum coord : {GL_S, GL_T, GL_R}) glTexGeni(coord, GL_TEXTURE_GEN_MODE, GLint(mode));
  }
  // The whole viewport at eye z = -10 with one normal; the centre pixel looks straight down -z.
  void draw(float nx, float ny, float nz) {
    glNormal3f(nx, ny, nz);
    glBegin(GL_QUADS);
    glVertex3f(-1, -1, -10);
    glVertex3f(1, -1, -10);
    glVertex3f(1, 1, -10);
    glVertex3f(-1, 1, -10);
    glEnd();
  }
};

TEST_F(CubeMapTexGenTest, NormalMapUsesTheNormal) {
  set_mode(GL_NORMAL_MAP);
  int mode = 0;
  glGetTexGeniv(GL_R, GL_TEXTURE_GEN_MODE, &mode);
  EXPECT_EQ(mode, GL_NORMAL_MAP);
  // n = (0.6, -0.3, 0.2) points at +X with face coordinates sc = -0.2 / 0.6, tc = 0.3 / 0.6:
  // s = 0.33 (texel 0), t = 0.75 (texel 1).
  draw(0.6f, -0.3f, 0.2f);
  EXPECT_TRUE(near_rgba(pixel(16, 16), face_texel(0, 0, 1)));
  draw(0.2f, 0.3f, -0.9f);  // -Z: sc = -0.2 / 0.9 (texel 0), tc = -0.3 / 0.9 (texel 0)
  EXPECT_TRUE(near_rgba(pixel(16, 16), face_texel(5, 0, 0)));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(CubeMapTexGenTest, ReflectionMapReflectsTheViewVector) {
  set_mode(GL_REFLECTION_MAP);
  // Looking down -z at a surface facing the eye: the reflection points back at +Z.
  draw(0, 0, 1);
  EXPECT_EQ(count_pixels(face_texel(4, 0, 0)) + count_pixels(face_texel(4, 1, 0)) +
                count_pixels(face_texel(4, 0, 1)) + count_pixels(face_texel(4, 1, 1)),
            width() * height());
  // A normal across the view: the view vector passes on to -Z. At the centre pixel (eye x, y
  // = 1/32) r = (+, -, -1): sc = -rx < 0 (texel 0), tc = -ry > 0 (texel 1).
  draw(0, 1, 0);
  EXPECT_TRUE(near_rgba(pixel(16, 16), face_texel(5, 0, 1)));
  // Tilted 45 degrees about x: -z reflects to +y.
  draw(0, 0.70710678f, 0.70710678f);
  EXPECT_EQ(pixel(16, 16)[0], 40 * 2 + 10);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
