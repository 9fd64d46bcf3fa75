// OpenGL 2.1, 4x multisampled: a framebuffer object with a 4-sample colour and depth
// renderbuffer (GL_EXT_framebuffer_multisample) takes a fan of thin smooth-shaded triangles, a
// ring of depth-tested crossing blades and blended fixed-function squares, then a GLSL disc whose
// colour the shader computes; glBlitFramebuffer resolves it into the window. Nearly every edge
// splits pixels' samples, so the image shows the sample positions and the resolve.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <vector>

#include "multisample_target.h"
#include "scene.h"
#include "shader_program.h"

namespace pineda::demo {
namespace {

constexpr float kPi = 3.14159265f;
constexpr int kFanBlades = 60, kRingBlades = 12, kDiscSides = 40;

const char* const kDiscVertex = R"(#version 120
varying vec2 v_local;
void main() {
  v_local = gl_Vertex.xy;
  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
})";

// Concentric bands whose colour depends on the distance from the centre.
const char* const kDiscFragment = R"(#version 120
uniform float phase;
varying vec2 v_local;
void main() {
  float r = length(v_local);
  float band = 0.5 + 0.5 * cos(r * 18.0 - phase);
  gl_FragColor = vec4(mix(vec3(0.95, 0.8, 0.2), vec3(0.2, 0.5, 0.95), band), 1.0);
})";

class Msaa final : public Scene {
 public:
  Msaa(int width, int height) : width_(width), height_(height) {
    framebuffer_ = makeMultisampleTarget("msaa", width, height, 4).framebuffer;
    disc_program_ = linkProgram("msaa", kDiscVertex, kDiscFragment);
  }

  void draw(int frame) override {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, width_, height_);
    glClearColor(0.06f, 0.07f, 0.12f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    const float aspect = float(width_) / float(height_);
    glOrtho(-aspect, aspect, -1, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    drawFan(frame);
    drawRing(frame);
    drawSquares(frame);
    drawDisc(frame);
    // The resolve: every pixel's samples averaged into the window's single-sampled buffer.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

 private:
  // Thin triangles from a point left of centre, each spanning a fraction of a degree.
  void drawFan(int frame) {
    const float turn = 0.01f * float(frame);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < kFanBlades; ++i) {
      const float a = turn + 2.0f * kPi * float(i) / kFanBlades, width = 0.012f;
      glColor3f(0.5f + 0.5f * std::cos(a), 0.5f + 0.5f * std::sin(a), 0.6f);
      glVertex2f(-0.55f, 0.0f);
      glColor3f(0.9f, 0.9f, 0.95f);
      glVertex2f(-0.55f + 1.3f * std::cos(a - width), 1.3f * std::sin(a - width));
      glVertex2f(-0.55f + 1.3f * std::cos(a + width), 1.3f * std::sin(a + width));
    }
    glEnd();
  }

  // Blades at two depths that cross each other: the depth test decides per sample.
  void drawRing(int frame) {
    glEnable(GL_DEPTH_TEST);
    glPushMatrix();
    glTranslatef(0.6f, 0.1f, 0);
    glRotatef(1.5f * float(frame), 0, 0, 1);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < kRingBlades; ++i) {
      const float a = 2.0f * kPi * float(i) / kRingBlades, b = a + 2.0f * kPi / kRingBlades * 1.6f;
      const float z = (i & 1) ? 0.4f : -0.4f;
      glColor3f((i & 1) ? 0.95f : 0.3f, 0.35f, (i & 1) ? 0.3f : 0.9f);
      glVertex3f(0.12f * std::cos(a), 0.12f * std::sin(a), z);
      glVertex3f(0.55f * std::cos(b), 0.55f * std::sin(b), -z);
      glVertex3f(0.5f * std::cos(a + 0.2f), 0.5f * std::sin(a + 0.2f), z);
    }
    glEnd();
    glPopMatrix();
    glDisable(GL_DEPTH_TEST);
  }

  // Half-transparent squares turned at odd angles.
  void drawSquares(int frame) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (int i = 0; i < 5; ++i) {
      glPushMatrix();
      glTranslatef(-0.9f + 0.42f * float(i), -0.65f, 0);
      glRotatef(17.0f * float(i) + 2.0f * float(frame), 0, 0, 1);
      glColor4f(0.2f + 0.15f * float(i), 0.85f, 0.4f, 0.55f);
      glBegin(GL_QUADS);
      glVertex2f(-0.15f, -0.15f);
      glVertex2f(0.15f, -0.15f);
      glVertex2f(0.15f, 0.15f);
      glVertex2f(-0.15f, 0.15f);
      glEnd();
      glPopMatrix();
    }
    glDisable(GL_BLEND);
  }

  void drawDisc(int frame) {
    glUseProgram(disc_program_);
    glUniform1f(glGetUniformLocation(disc_program_, "phase"), 0.3f * float(frame));
    glPushMatrix();
    glTranslatef(0.95f, 0.62f, 0);
    glScalef(0.3f, 0.3f, 1);
    glBegin(GL_TRIANGLE_FAN);
    glVertex2f(0, 0);
    for (int i = 0; i <= kDiscSides; ++i) {
      const float a = 2.0f * kPi * float(i) / kDiscSides;
      glVertex2f(std::cos(a), std::sin(a));
    }
    glEnd();
    glPopMatrix();
    glUseProgram(0);
  }

  int width_, height_;
  GLuint framebuffer_ = 0, disc_program_ = 0;
};

}  // namespace

std::unique_ptr<Scene> createMsaa(int width, int height) { return std::make_unique<Msaa>(width, height); }

}  // namespace pineda::demo
