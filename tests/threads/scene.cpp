#include "tests/threads/scene.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>

namespace pineda::threads_test {
namespace {

// The vertex stage reads the fixed-function matrices, so that each context turns the
// geometry through its own state while the program object itself may be shared.
const char* const kVertexShader = R"(
#version 110
attribute vec2 position;
attribute vec3 color;
varying vec3 v_color;
varying vec2 v_uv;
void main() {
  v_color = color;
  v_uv = position * 0.5 + 0.5;
  gl_Position = gl_ModelViewProjectionMatrix * vec4(position, position.x * 0.5, 1.0);
}
)";

const char* const kFragmentShader = R"(
#version 110
uniform sampler2D tex;
varying vec3 v_color;
varying vec2 v_uv;
void main() {
  vec4 t = texture2D(tex, v_uv * 2.0);
  gl_FragColor = vec4(t.rgb * v_color + vec3(0.1, 0.0, 0.05) * sin(v_uv.x * 9.0), 0.7);
}
)";

unsigned compile(GLenum type, const char* source) {
  GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  return ok ? shader : 0;
}

// A fan of coloured triangles around the centre: position xy, colour rgb.
std::vector<float> fan_vertices() {
  std::vector<float> v;
  const int kSides = 12;
  for (int i = 0; i < kSides; ++i) {
    for (int k = 0; k < 2; ++k) {
      const double a = (i + k) * 2 * M_PI / kSides;
      if (k == 0) v.insert(v.end(), {0.0f, 0.0f, 1.0f, 1.0f, 1.0f});
      v.insert(v.end(), {float(0.9 * std::cos(a)), float(0.9 * std::sin(a)), float(0.5 + 0.5 * std::cos(a)),
                         float(0.5 + 0.5 * std::sin(a * 2)), float(i % 3) / 2.0f});
    }
  }
  return v;
}

}  // namespace

SceneObjects create_scene_objects() {
  SceneObjects o;
  // An 8x8 texture of smoothly varying colours, filtered linearly and repeated.
  std::vector<uint8_t> texels(8 * 8 * 4);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      uint8_t* t = &texels[(y * 8 + x) * 4];
      t[0] = uint8_t(x * 32 + 16);
      t[1] = uint8_t(y * 32 + 16);
      t[2] = uint8_t(((x ^ y) & 1) * 200 + 30);
      t[3] = uint8_t(128 + x * 16);
    }
  glGenTextures(1, &o.texture);
  glBindTexture(GL_TEXTURE_2D, o.texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());

  const std::vector<float> vertices = fan_vertices();
  glGenBuffers(1, &o.buffer);
  glBindBuffer(GL_ARRAY_BUFFER, o.buffer);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);

  const unsigned vs = compile(GL_VERTEX_SHADER, kVertexShader);
  const unsigned fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
  if (vs && fs) {
    o.program = glCreateProgram();
    glAttachShader(o.program, vs);
    glAttachShader(o.program, fs);
    glBindAttribLocation(o.program, 1, "position");
    glBindAttribLocation(o.program, 2, "color");
    glLinkProgram(o.program);
    GLint linked = 0;
    glGetProgramiv(o.program, GL_LINK_STATUS, &linked);
    if (linked) {
      glUseProgram(o.program);
      glUniform1i(glGetUniformLocation(o.program, "tex"), 0);
      glUseProgram(0);
    } else {
      glDeleteProgram(o.program);
      o.program = 0;
    }
  }
  glDeleteShader(vs);
  glDeleteShader(fs);
  return o;
}

void delete_scene_objects(const SceneObjects& objects) {
  glDeleteTextures(1, &objects.texture);
  glDeleteBuffers(1, &objects.buffer);
  glDeleteProgram(objects.program);
}

std::vector<uint8_t> render_frame(const SceneObjects& objects, int frame) {
  glViewport(0, 0, kWidth, kHeight);
  glClearColor(0.05f * (frame % 5), 0.1f, 0.2f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.5, 0.5, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -2.5f);
  glRotatef(frame * 7.0f, 0.3f, 1.0f, 0.2f);

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glBindTexture(GL_TEXTURE_2D, objects.texture);

  // Fixed function: textured, modulated, depth-tested triangles crossing each other.
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 6; ++i) {
    const float z = -0.8f + 0.3f * i, s = 0.3f + 0.1f * ((i + frame) % 4);
    glColor3f(1.0f - 0.15f * i, 0.4f + 0.1f * i, 0.7f);
    glTexCoord2f(0, 0); glVertex3f(-1.0f + s, -0.9f, z);
    glColor3f(0.2f, 1.0f, 0.5f + 0.08f * i);
    glTexCoord2f(2, 0); glVertex3f(1.0f, -0.6f + s, -z);
    glColor3f(0.9f, 0.3f * i, 1.0f);
    glTexCoord2f(1, 2); glVertex3f(-0.2f * i, 0.95f, 0.1f * i);
  }
  glEnd();
  glDisable(GL_TEXTURE_2D);

  // Blended, untextured quads over it.
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBegin(GL_QUADS);
  for (int i = 0; i < 3; ++i) {
    const float o = 0.25f * i - 0.5f;
    glColor4f(0.9f, 0.2f * i, 0.1f, 0.35f + 0.2f * i);
    glVertex3f(o, o, 0.3f); glVertex3f(o + 0.7f, o, 0.3f);
    glVertex3f(o + 0.7f, o + 0.5f, -0.2f); glVertex3f(o, o + 0.5f, -0.2f);
  }
  glEnd();

  // The GLSL program, from the buffer object, blended too.
  if (objects.program) {
    glUseProgram(objects.program);
    glBindBuffer(GL_ARRAY_BUFFER, objects.buffer);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), nullptr);
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), reinterpret_cast<void*>(2 * sizeof(float)));
    glEnableVertexAttribArray(1);
    glEnableVertexAttribArray(2);
    glScalef(0.8f, 0.8f, 0.8f);
    glDrawArrays(GL_TRIANGLES, 0, 36);
    glDisableVertexAttribArray(1);
    glDisableVertexAttribArray(2);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glUseProgram(0);
  }
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);

  std::vector<uint8_t> image(size_t(kWidth) * kHeight * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  return image;
}

uint64_t image_hash(const std::vector<uint8_t>& image) {
  uint64_t h = 1469598103934665603ull;
  for (uint8_t b : image) h = (h ^ b) * 1099511628211ull;
  return h;
}

std::vector<uint64_t> render_frames(const SceneObjects& objects, int frames) {
  std::vector<uint64_t> hashes;
  for (int f = 0; f < frames; ++f) hashes.push_back(image_hash(render_frame(objects, f)));
  return hashes;
}

}  // namespace pineda::threads_test
