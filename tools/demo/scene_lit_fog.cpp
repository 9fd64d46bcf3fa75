// A textured, lit, fogged, multitextured scene: a tessellated floor and a ring of spheres.
// Unit 0: a mipmapped brick texture (LINEAR_MIPMAP_LINEAR, REPEAT) MODULATE'd with the
// lighting; unit 1: a light-map (LINEAR, CLAMP_TO_EDGE) through COMBINE (MODULATE, RGB
// scale 2). Three lights: a directional light with specular, a moving point light with
// attenuation and a spotlight, all with specular; EXP2 fog. (Not SEPARATE_SPECULAR_COLOR:
// the spec clamps the colour sum before fog, llvmpipe fogs the unclamped sum, so highlights
// under fog differ by design; FogTest.ColorSumIsClampedBeforeFog pins Pineda's choice.)
// Multitexture entry points come from eglGetProcAddress (ARB_multitexture), the rest is GL 1.1.
#include <EGL/egl.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "box_filter.h"
#include "scene.h"

namespace pineda::demo {
namespace {

constexpr float kPi = 3.14159265f;

// Red bricks in pale mortar, 8 rows of 4 bricks, odd rows offset by half a brick.
Texels bricks(int size) {
  Texels texels(std::size_t(size) * size * 3);
  int rowHeight = size / 8, brickWidth = size / 4;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      int row = y / rowHeight;
      int shifted = x + (row % 2) * brickWidth / 2;
      bool mortar = y % rowHeight < 2 || shifted % brickWidth < 2;
      int grain = ((x * 7 + y * 13) % 17) * 3;  // a little texture inside each brick
      std::uint8_t* t = &texels[(std::size_t(y) * size + x) * 3];
      t[0] = std::uint8_t(mortar ? 210 : 150 + grain);
      t[1] = std::uint8_t(mortar ? 205 : 60 + grain / 2);
      t[2] = std::uint8_t(mortar ? 190 : 40 + grain / 3);
    }
  return texels;
}

// A light-map: three soft pools of coloured light on a dim (mid-grey = unlit) ground.
Texels lightMap(int size) {
  struct Pool { float x, y, radius, r, g, b; };
  const Pool pools[] = {{0.3f, 0.3f, 0.25f, 1.0f, 0.8f, 0.5f},
                        {0.7f, 0.6f, 0.3f, 0.4f, 0.6f, 1.0f},
                        {0.4f, 0.8f, 0.15f, 0.9f, 0.4f, 0.9f}};
  Texels texels(std::size_t(size) * size * 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      float rgb[3] = {0.35f, 0.35f, 0.4f};
      for (const Pool& p : pools) {
        float dx = (x + 0.5f) / size - p.x, dy = (y + 0.5f) / size - p.y;
        float fall = std::fmax(0.0f, 1.0f - std::sqrt(dx * dx + dy * dy) / p.radius);
        rgb[0] += fall * p.r * 0.6f, rgb[1] += fall * p.g * 0.6f, rgb[2] += fall * p.b * 0.6f;
      }
      for (int c = 0; c < 3; ++c)
        texels[(std::size_t(y) * size + x) * 3 + c] = std::uint8_t(std::lround(std::fmin(rgb[c], 1.0f) * 255));
    }
  return texels;
}

class LitFog final : public Scene {
 public:
  LitFog(int width, int height)
      : activeTexture_(reinterpret_cast<PFNGLACTIVETEXTUREARBPROC>(eglGetProcAddress("glActiveTextureARB"))),
        multiTexCoord2f_(reinterpret_cast<PFNGLMULTITEXCOORD2FARBPROC>(eglGetProcAddress("glMultiTexCoord2fARB"))) {
    const float fog[4] = {0.55f, 0.6f, 0.7f, 1.0f};
    glClearColor(fog[0], fog[1], fog[2], fog[3]);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glShadeModel(GL_SMOOTH);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(2, textures_);
    if (!activeTexture_ || !multiTexCoord2f_) return;  // draw() then reports nothing drawn

    activeTexture_(GL_TEXTURE0_ARB);
    glBindTexture(GL_TEXTURE_2D, textures_[0]);
    int size = 64;
    Texels level = bricks(size);
    for (int lod = 0; size >= 1; ++lod, size /= 2) {
      glTexImage2D(GL_TEXTURE_2D, lod, GL_RGB, size, size, 0, GL_RGB, GL_UNSIGNED_BYTE, level.data());
      if (size > 1) level = halve(level, size, 3);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);

    activeTexture_(GL_TEXTURE1_ARB);
    glBindTexture(GL_TEXTURE_2D, textures_[1]);
    Texels map = lightMap(32);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 32, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, map.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE_ARB);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB_ARB, GL_MODULATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB_ARB, GL_PREVIOUS_ARB);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB_ARB, GL_TEXTURE);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE_ARB, 2.0f);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA_ARB, GL_REPLACE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA_ARB, GL_PREVIOUS_ARB);
    glEnable(GL_TEXTURE_2D);
    activeTexture_(GL_TEXTURE0_ARB);

    glEnable(GL_LIGHTING);
    glEnable(GL_NORMALIZE);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    const float ambient[4] = {0.15f, 0.15f, 0.2f, 1.0f};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    const float specular[4] = {0.8f, 0.8f, 0.7f, 1.0f};
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);

    const float sunDiffuse[4] = {0.7f, 0.65f, 0.55f, 1.0f}, sunSpecular[4] = {1.0f, 0.95f, 0.8f, 1.0f};
    glLightfv(GL_LIGHT0, GL_DIFFUSE, sunDiffuse);
    glLightfv(GL_LIGHT0, GL_SPECULAR, sunSpecular);
    const float lampDiffuse[4] = {0.3f, 0.6f, 1.0f, 1.0f}, lampSpecular[4] = {0.5f, 0.7f, 1.0f, 1.0f};
    glLightfv(GL_LIGHT1, GL_DIFFUSE, lampDiffuse);
    glLightfv(GL_LIGHT1, GL_SPECULAR, lampSpecular);
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.3f);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.05f);
    const float spotDiffuse[4] = {1.0f, 0.5f, 0.3f, 1.0f};
    glLightfv(GL_LIGHT2, GL_DIFFUSE, spotDiffuse);
    glLightfv(GL_LIGHT2, GL_SPECULAR, spotDiffuse);
    glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 25.0f);
    glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 8.0f);
    glLightf(GL_LIGHT2, GL_LINEAR_ATTENUATION, 0.05f);
    for (GLenum light : {GL_LIGHT0, GL_LIGHT1, GL_LIGHT2}) glEnable(light);

    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogf(GL_FOG_DENSITY, 0.09f);
    glFogfv(GL_FOG_COLOR, fog);

    glMatrixMode(GL_PROJECTION);
    double aspect = double(width) / height;
    glFrustum(-0.1 * aspect, 0.1 * aspect, -0.1, 0.1, 0.2, 60.0);
    glMatrixMode(GL_MODELVIEW);
  }

  ~LitFog() override { glDeleteTextures(2, textures_); }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!activeTexture_ || !multiTexCoord2f_) return;
    glLoadIdentity();
    glTranslatef(0.0f, -1.5f, -7.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(frame * 2.0f, 0.0f, 1.0f, 0.0f);
    placeLights(frame);

    glColor3f(0.9f, 0.9f, 0.85f);
    floor();
    for (int i = 0; i < 5; ++i) {
      float angle = 2 * kPi * i / 5 + frame * 0.03f;
      glPushMatrix();
      glTranslatef(3.0f * std::cos(angle), 0.8f + 0.3f * std::sin(frame * 0.2f + i), 3.0f * std::sin(angle));
      glRotatef(frame * 5.0f + i * 40.0f, 0.3f, 1.0f, 0.0f);
      glColor3f(0.6f + 0.08f * i, 0.9f - 0.1f * i, 0.5f + 0.1f * i);
      sphere(0.8f, 24, 16);
      glPopMatrix();
    }
  }

 private:
  // Positions are taken through the current modelview matrix, so they move with the world.
  void placeLights(int frame) {
    const float sun[4] = {-0.4f, 1.0f, 0.6f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, sun);
    float a = frame * 0.1f;
    const float lamp[4] = {2.0f * std::cos(a), 1.2f, 2.0f * std::sin(a), 1.0f};
    glLightfv(GL_LIGHT1, GL_POSITION, lamp);
    const float spot[4] = {0.0f, 5.0f, 0.0f, 1.0f};
    const float spotDirection[3] = {0.4f * std::cos(-a), -1.0f, 0.4f * std::sin(-a)};
    glLightfv(GL_LIGHT2, GL_POSITION, spot);
    glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, spotDirection);
  }

  // A 20x20 floor in 32x32 quads (lighting is per vertex): bricks repeat 6 times, the
  // light-map spans it once.
  void floor() {
    constexpr int kCells = 32;
    constexpr float kHalf = 10.0f;
    glNormal3f(0.0f, 1.0f, 0.0f);
    for (int z = 0; z < kCells; ++z) {
      glBegin(GL_QUAD_STRIP);
      for (int x = 0; x <= kCells; ++x)
        for (int dz : {0, 1}) {  // counter-clockwise seen from above
          float u = float(x) / kCells, v = float(z + dz) / kCells;
          multiTexCoord2f_(GL_TEXTURE0_ARB, u * 6, v * 6);
          multiTexCoord2f_(GL_TEXTURE1_ARB, u, v);
          glVertex3f(-kHalf + 2 * kHalf * u, 0.0f, -kHalf + 2 * kHalf * v);
        }
      glEnd();
    }
  }

  // A UV sphere: bricks wrap twice around it, the light-map once.
  void sphere(float radius, int slices, int stacks) {
    for (int j = 0; j < stacks; ++j) {
      glBegin(GL_QUAD_STRIP);
      for (int i = 0; i <= slices; ++i)
        for (int dj : {0, 1}) {
          float u = float(i) / slices, v = float(j + dj) / stacks;
          float theta = 2 * kPi * u, phi = kPi * v;
          float nx = std::sin(phi) * std::cos(theta), ny = std::cos(phi), nz = -std::sin(phi) * std::sin(theta);
          glNormal3f(nx, ny, nz);
          multiTexCoord2f_(GL_TEXTURE0_ARB, u * 2, v);
          multiTexCoord2f_(GL_TEXTURE1_ARB, u, v);
          glVertex3f(radius * nx, radius * ny, radius * nz);
        }
      glEnd();
    }
  }

  PFNGLACTIVETEXTUREARBPROC activeTexture_;
  PFNGLMULTITEXCOORD2FARBPROC multiTexCoord2f_;
  GLuint textures_[2] = {};
};

}  // namespace

std::unique_ptr<Scene> createLitFog(int width, int height) { return std::make_unique<LitFog>(width, height); }

}  // namespace pineda::demo
