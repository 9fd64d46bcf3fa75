// OpenGL ES 2.0 (GLES2/gl2.h, GLSL ES 1.00): a textured cube lit per fragment (Blinn-Phong)
// rendered into a texture through a framebuffer object with a depth renderbuffer, then
// composited: the texture on two turning panels in perspective over a gradient background, the
// front panel alpha-blended.
#include <GLES2/gl2.h>

#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <vector>

#include "scene.h"
#include "shader_program.h"
#include "texture_target.h"

namespace pineda::demo {
namespace {

constexpr int kTargetSize = 256;

const char* const kCubeVertex = R"(
attribute vec3 position;
attribute vec3 normal;
attribute vec2 texcoord;
uniform mat4 model_view;
uniform mat4 projection;
uniform mat3 normal_matrix;
varying vec3 v_normal;
varying vec3 v_eye;
varying vec2 v_texcoord;
void main() {
  vec4 eye = model_view * vec4(position, 1.0);
  v_normal = normal_matrix * normal;
  v_eye = eye.xyz;
  v_texcoord = texcoord;
  gl_Position = projection * eye;
})";

const char* const kCubeFragment = R"(
precision mediump float;
uniform sampler2D checker;
uniform vec3 light_direction;  // eye space, unit length
varying vec3 v_normal;
varying vec3 v_eye;
varying vec2 v_texcoord;
void main() {
  vec3 n = normalize(v_normal);
  vec3 h = normalize(light_direction + normalize(-v_eye));
  float diffuse = max(dot(n, light_direction), 0.0);
  float specular = pow(max(dot(n, h), 0.0), 24.0);
  vec3 base = texture2D(checker, v_texcoord).rgb;
  gl_FragColor = vec4(base * (0.2 + 0.8 * diffuse) + vec3(0.45) * specular, 1.0);
})";

const char* const kPanelVertex = R"(
attribute vec2 position;
attribute vec4 color;
uniform mat4 transform;
varying vec2 v_texcoord;
varying vec4 v_color;
void main() {
  v_texcoord = position * 0.5 + 0.5;
  v_color = color;
  gl_Position = transform * vec4(position, 0.0, 1.0);
})";

// textured: the rendered image at `opacity`; otherwise the interpolated vertex colour.
const char* const kPanelFragment = R"(
precision mediump float;
uniform sampler2D image;
uniform bool textured;
uniform float opacity;
varying vec2 v_texcoord;
varying vec4 v_color;
void main() {
  if (textured)
    gl_FragColor = vec4(texture2D(image, v_texcoord).rgb, opacity);
  else
    gl_FragColor = v_color;
})";

struct CubeVertex {
  float position[3], normal[3], texcoord[2];
};

// 24 vertices (4 per face, each face its own normal) and 36 indices.
void buildCube(std::vector<CubeVertex>& vertices, std::vector<GLushort>& indices) {
  const int normals[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const auto& n : normals) {
    // Two axes spanning the face, so that corners run counter-clockwise seen from outside.
    const glm::vec3 normal(n[0], n[1], n[2]);
    const glm::vec3 u = glm::abs(normal.x) > 0 ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 v = glm::cross(normal, u);
    const GLushort base = GLushort(vertices.size());
    const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& c : corners) {
      const glm::vec3 p = normal + u * c[0] + v * c[1];
      vertices.push_back({{p.x, p.y, p.z}, {normal.x, normal.y, normal.z}, {c[0] + 1, c[1] + 1}});
    }
    for (GLushort i : {0, 1, 2, 0, 2, 3}) indices.push_back(GLushort(base + i));
  }
}

class Es2FboLit final : public Scene {
 public:
  Es2FboLit(int width, int height) : width_(width), height_(height) {
    buildCube(cube_, cube_indices_);
    cube_program_ = linkProgram("es2_fbo_lit", kCubeVertex, kCubeFragment, {"position", "normal", "texcoord"});
    panel_program_ = linkProgram("es2_fbo_lit", kPanelVertex, kPanelFragment, {"position", "color"});

    // An 8x8 checker of warm and cool squares, repeated twice across each face.
    std::vector<std::uint8_t> texels(8 * 8 * 4);
    for (int i = 0; i < 64; ++i) {
      const bool warm = ((i & 7) < 4) != (i / 8 < 4);
      const std::uint8_t rgba[4] = {std::uint8_t(warm ? 235 : 70), std::uint8_t(warm ? 150 : 160),
                                    std::uint8_t(warm ? 60 : 210), 255};
      std::copy(rgba, rgba + 4, &texels[i * 4]);
    }
    glGenTextures(1, &checker_);
    glBindTexture(GL_TEXTURE_2D, checker_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

    // The render target: a colour texture and a depth renderbuffer.
    const TextureTarget target = makeTextureTarget("es2_fbo_lit", kTargetSize, GL_DEPTH_COMPONENT16);
    target_ = target.texture;
    depth_ = target.depth;
    framebuffer_ = target.framebuffer;
  }

  void draw(int frame) override {
    drawCubeIntoTarget(frame);
    composite(frame);
  }

 private:
  void drawCubeIntoTarget(int frame) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, kTargetSize, kTargetSize);
    glClearColor(0.08f, 0.1f, 0.18f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glUseProgram(cube_program_);
    const glm::mat4 projection = glm::perspective(glm::radians(45.0f), 1.0f, 1.0f, 20.0f);
    glm::mat4 model_view = glm::translate(glm::mat4(1), glm::vec3(0, 0, -5.5f));
    model_view = glm::rotate(model_view, glm::radians(30.0f + 4.0f * frame), glm::vec3(1, 0.6f, 0.2f));
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(model_view)));
    const glm::vec3 light = glm::normalize(glm::vec3(0.4f, 0.7f, 1.0f));
    glUniformMatrix4fv(glGetUniformLocation(cube_program_, "model_view"), 1, GL_FALSE, glm::value_ptr(model_view));
    glUniformMatrix4fv(glGetUniformLocation(cube_program_, "projection"), 1, GL_FALSE, glm::value_ptr(projection));
    glUniformMatrix3fv(glGetUniformLocation(cube_program_, "normal_matrix"), 1, GL_FALSE,
                       glm::value_ptr(normal_matrix));
    glUniform3fv(glGetUniformLocation(cube_program_, "light_direction"), 1, glm::value_ptr(light));
    glUniform1i(glGetUniformLocation(cube_program_, "checker"), 0);
    glBindTexture(GL_TEXTURE_2D, checker_);
    const GLsizei stride = sizeof(CubeVertex);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, cube_[0].position);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, cube_[0].normal);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, cube_[0].texcoord);
    for (GLuint i = 0; i < 3; ++i) glEnableVertexAttribArray(i);
    glDrawElements(GL_TRIANGLES, GLsizei(cube_indices_.size()), GL_UNSIGNED_SHORT, cube_indices_.data());
    for (GLuint i = 0; i < 3; ++i) glDisableVertexAttribArray(i);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  void composite(int frame) {
    glViewport(0, 0, width_, height_);
    glUseProgram(panel_program_);
    glUniform1i(glGetUniformLocation(panel_program_, "image"), 0);
    const GLint transform = glGetUniformLocation(panel_program_, "transform");
    const GLint textured = glGetUniformLocation(panel_program_, "textured");
    const GLint opacity = glGetUniformLocation(panel_program_, "opacity");
    static const GLfloat square[] = {-1, -1, 1, -1, 1, 1, -1, 1};
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, square);
    glEnableVertexAttribArray(0);

    // The background: a vertical gradient over the whole window.
    static const GLfloat gradient[] = {0.9f, 0.75f, 0.55f, 1, 0.9f, 0.75f, 0.55f, 1,
                                       0.3f, 0.35f, 0.55f, 1, 0.3f, 0.35f, 0.55f, 1};
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 0, gradient);
    glEnableVertexAttribArray(1);
    glUniformMatrix4fv(transform, 1, GL_FALSE, glm::value_ptr(glm::mat4(1)));
    glUniform1i(textured, 0);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    glDisableVertexAttribArray(1);

    // Two panels showing the rendered cube, back one opaque, front one blended.
    glBindTexture(GL_TEXTURE_2D, target_);
    glUniform1i(textured, 1);
    const float aspect = float(width_) / float(height_);
    const glm::mat4 projection = glm::perspective(glm::radians(50.0f), aspect, 0.5f, 20.0f);
    const struct { float x, z, angle, alpha; } panels[] = {{-0.7f, -4.2f, 25.0f - 2.0f * frame, 1.0f},
                                                           {0.8f, -3.4f, -30.0f + 3.0f * frame, 0.75f}};
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (const auto& p : panels) {
      glm::mat4 model = glm::translate(glm::mat4(1), glm::vec3(p.x, 0, p.z));
      model = glm::rotate(model, glm::radians(p.angle), glm::vec3(0, 1, 0));
      const glm::mat4 mvp = projection * model;
      glUniformMatrix4fv(transform, 1, GL_FALSE, glm::value_ptr(mvp));
      glUniform1f(opacity, p.alpha);
      glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    }
    glDisable(GL_BLEND);
    glDisableVertexAttribArray(0);
  }

  int width_, height_;
  std::vector<CubeVertex> cube_;
  std::vector<GLushort> cube_indices_;
  GLuint cube_program_ = 0, panel_program_ = 0;
  GLuint checker_ = 0, target_ = 0, depth_ = 0, framebuffer_ = 0;
};

}  // namespace

std::unique_ptr<Scene> createEs2FboLit(int width, int height) { return std::make_unique<Es2FboLit>(width, height); }

}  // namespace pineda::demo
