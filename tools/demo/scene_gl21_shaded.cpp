// OpenGL 2.1 and GLSL 1.20: a torus lit per fragment from the fixed-function light and material
// state (gl_LightSource, gl_FrontMaterial, gl_NormalMatrix, ftransform), two-sided, textured with
// an sRGB texture (SRGB8) uploaded through a pixel unpack buffer, its coordinates transformed by
// a non-square mat3x2 uniform.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "scene.h"
#include "shader_program.h"

namespace pineda::demo {
namespace {

constexpr float kPi = 3.14159265f;
constexpr int kRings = 48, kSides = 24, kTextureSize = 64;

const char* const kVertex = R"(#version 120
uniform mat3x2 texture_transform;
varying vec3 v_normal;
varying vec3 v_eye;
varying vec2 v_texcoord;
void main() {
  v_normal = gl_NormalMatrix * gl_Normal;
  v_eye = vec3(gl_ModelViewMatrix * gl_Vertex);
  v_texcoord = texture_transform * vec3(gl_MultiTexCoord0.st, 1.0);
  gl_Position = ftransform();
})";

const char* const kFragment = R"(#version 120
uniform sampler2D stripes;
varying vec3 v_normal;
varying vec3 v_eye;
varying vec2 v_texcoord;
void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 l = normalize(gl_LightSource[0].position.xyz);
  vec3 h = normalize(l + normalize(-v_eye));
  float diffuse = max(dot(n, l), 0.0);
  float specular = pow(max(dot(n, h), 0.0), gl_FrontMaterial.shininess);
  vec3 base = texture2D(stripes, v_texcoord).rgb;
  vec3 color = gl_FrontLightModelProduct.sceneColor.rgb * base +
               gl_LightSource[0].diffuse.rgb * base * diffuse +
               gl_FrontLightProduct[0].specular.rgb * specular;
  gl_FragColor = vec4(color, 1.0);
})";

struct TorusVertex {
  float position[3], normal[3], texcoord[2];
};

class Gl21Shaded final : public Scene {
 public:
  Gl21Shaded(int width, int height) {
    buildTorus();
    program_ = linkProgram("gl21_shaded", kVertex, kFragment);
    glUseProgram(program_);
    glUniform1i(glGetUniformLocation(program_, "stripes"), 0);
    // Columns: s scaled by 4 (around the ring), t by 2 (around the tube), a slant of s into t.
    const GLfloat transform[6] = {4, 0.5f, 0, 2, 0, 0};
    glUniformMatrix3x2fv(glGetUniformLocation(program_, "texture_transform"), 1, GL_FALSE, transform);

    // Diagonal stripes in sRGB, handed over through a pixel unpack buffer.
    std::vector<std::uint8_t> texels(kTextureSize * kTextureSize * 3);
    for (int y = 0; y < kTextureSize; ++y)
      for (int x = 0; x < kTextureSize; ++x) {
        const int band = ((x + y) / 8) % 3;
        const std::uint8_t colors[3][3] = {{230, 200, 90}, {60, 130, 200}, {240, 240, 235}};
        std::copy(colors[band], colors[band] + 3, &texels[(y * kTextureSize + x) * 3]);
      }
    glGenBuffers(1, &unpack_);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, unpack_);
    glBufferData(GL_PIXEL_UNPACK_BUFFER, GLsizeiptr(texels.size()), texels.data(), GL_STATIC_DRAW);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8, kTextureSize, kTextureSize, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

    const GLfloat light_position[] = {0.5f, 0.8f, 1.0f, 0};
    const GLfloat light_diffuse[] = {0.95f, 0.9f, 0.85f, 1};
    const GLfloat light_specular[] = {0.7f, 0.7f, 0.7f, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, light_position);  // eye space: the modelview is the identity
    glLightfv(GL_LIGHT0, GL_DIFFUSE, light_diffuse);
    glLightfv(GL_LIGHT0, GL_SPECULAR, light_specular);
    const GLfloat ambient[] = {0.25f, 0.25f, 0.3f, 1};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    const GLfloat material_ambient[] = {1, 1, 1, 1};
    const GLfloat material_specular[] = {0.8f, 0.8f, 0.8f, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, material_ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, material_specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40);

    glMatrixMode(GL_PROJECTION);
    const double aspect = double(width) / height;
    glFrustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.12f, 0.12f, 0.16f, 1);
    glEnable(GL_DEPTH_TEST);

    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(3, GL_FLOAT, sizeof(TorusVertex), vertices_[0].position);
    glNormalPointer(GL_FLOAT, sizeof(TorusVertex), vertices_[0].normal);
    glTexCoordPointer(2, GL_FLOAT, sizeof(TorusVertex), vertices_[0].texcoord);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0, 0, -4.2f);
    glRotatef(35.0f + 3.0f * frame, 1, 0.3f, 0);
    glRotatef(20.0f + 2.0f * frame, 0, 1, 0);
    glDrawElements(GL_TRIANGLES, GLsizei(indices_.size()), GL_UNSIGNED_INT, indices_.data());
  }

 private:
  void buildTorus() {
    const float major = 1.0f, minor = 0.42f;
    for (int ring = 0; ring <= kRings; ++ring)
      for (int side = 0; side <= kSides; ++side) {
        const float u = 2 * kPi * ring / kRings, v = 2 * kPi * side / kSides;
        const float nx = std::cos(v) * std::cos(u), ny = std::cos(v) * std::sin(u), nz = std::sin(v);
        vertices_.push_back({{(major + minor * std::cos(v)) * std::cos(u), (major + minor * std::cos(v)) * std::sin(u),
                              minor * nz},
                             {nx, ny, nz},
                             {float(ring) / kRings, float(side) / kSides}});
      }
    for (int ring = 0; ring < kRings; ++ring)
      for (int side = 0; side < kSides; ++side) {
        const GLuint a = GLuint(ring * (kSides + 1) + side), b = a + kSides + 1;
        for (GLuint i : {a, b, a + 1, a + 1, b, b + 1}) indices_.push_back(i);
      }
  }

  std::vector<TorusVertex> vertices_;
  std::vector<GLuint> indices_;
  GLuint program_ = 0, texture_ = 0, unpack_ = 0;
};

}  // namespace

std::unique_ptr<Scene> createGl21Shaded(int width, int height) { return std::make_unique<Gl21Shaded>(width, height); }

}  // namespace pineda::demo
