// The fuzzed GL 2.x shader and program calls: objects made, sourced from a few fixed GLSL
// 1.10/1.20 shaders (and a broken one), compiled, attached, linked, used, queried and deleted.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <string_view>
#include <vector>

#include "tests/fuzz/gl_calls.h"

namespace pineda::fuzz {
namespace {

// Uniforms of several types (arrays, matrices, samplers) and attributes; the names match
// kUniformNames and kAttribNames so that their locations can be looked up.
constexpr std::string_view kSources[] = {
    // vertex shaders
    "uniform mat4 u_mvp;\n"
    "uniform vec4 u_offsets[3];\n"
    "attribute vec4 a_position;\n"
    "attribute vec2 a_uv;\n"
    "varying vec2 v_uv;\n"
    "void main() {\n"
    "  v_uv = a_uv;\n"
    "  gl_Position = u_mvp * a_position + u_offsets[int(a_uv.x) & 1];\n"
    "}\n",
    "#version 120\n"
    "uniform mat3 u_normal;\n"
    "uniform mat2x3 u_skew;\n"
    "uniform float u_weights[4];\n"
    "attribute vec3 a_normal;\n"
    "attribute float a_weight;\n"
    "varying vec4 v_color;\n"
    "void main() {\n"
    "  vec3 n = u_normal * a_normal + u_skew * vec2(a_weight);\n"
    "  v_color = vec4(n * u_weights[1], u_weights[3]);\n"
    "  gl_Position = ftransform();\n"
    "}\n",
    "void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; gl_FrontColor = gl_Color; }\n",
    // fragment shaders
    "uniform sampler2D u_texture;\n"
    "uniform vec4 u_tint;\n"
    "uniform ivec2 u_mode;\n"
    "varying vec2 v_uv;\n"
    "void main() {\n"
    "  vec4 c = texture2D(u_texture, v_uv) * u_tint;\n"
    "  if (u_mode.x > 0) c.rgb = c.bgr;\n"
    "  gl_FragColor = c;\n"
    "}\n",
    "#version 120\n"
    "uniform bool u_flag;\n"
    "uniform vec3 u_colors[2];\n"
    "uniform mat4x3 u_wide;\n"
    "uniform samplerCube u_cube;\n"
    "varying vec4 v_color;\n"
    "void main() {\n"
    "  vec3 c = u_flag ? u_colors[0] : u_colors[1];\n"
    "  gl_FragColor = vec4(c + u_wide * v_color, 1.0) + textureCube(u_cube, v_color.xyz);\n"
    "}\n",
    "void main() { gl_FragColor = gl_Color; }\n",
    // broken: a compile error
    "uniform vec4 u_tint;\nvoid main() { gl_FragColor = u_tint * undefined_name; }\n",
};

constexpr size_t kVertexSources = 3;  // the first three of kSources

// A GL_FRAGMENT_SHADER given a vertex source fails to compile, which is fine.
GLenum pick_shader_type(FuzzInput& in) { return in.enumeration({GL_VERTEX_SHADER, GL_FRAGMENT_SHADER}); }

constexpr const char* kUniformNames[] = {"u_mvp", "u_offsets", "u_offsets[2]", "u_offsets[3]", "u_normal", "u_skew",
                                         "u_weights[0]", "u_texture", "u_tint", "u_mode", "u_flag", "u_colors[1]",
                                         "u_wide", "u_cube", "gl_ModelViewMatrix", "", "u_offsets[-1]"};
constexpr const char* kAttribNames[] = {"a_position", "a_uv", "a_normal", "a_weight", "gl_Vertex", "", "a_none"};

template <size_t N>
const char* pick(FuzzInput& in, const char* const (&names)[N]) {
  return names[in.byte() % N];
}

// A buffer of `size` bytes (size > 0) so that AddressSanitizer sees any write past it.
std::vector<GLchar> text_buffer(GLsizei size) { return std::vector<GLchar>(size_t(std::max(size, 0)) + (size <= 0)); }

// A log or source into a buffer of bufSize chars, with or without the length written.
void get_text(FuzzInput& in, GLsizei max, void (*get)(GLuint, GLsizei, GLsizei*, GLchar*)) {
  const GLsizei size = in.bounded_size(max);
  std::vector<GLchar> text = text_buffer(size);
  GLsizei length = 0;
  const GLuint object = in.name();
  get(object, size, in.boolean() ? &length : nullptr, text.data());
}

void get_active(FuzzInput& in, void (*get)(GLuint, GLuint, GLsizei, GLsizei*, GLint*, GLenum*, GLchar*)) {
  const GLuint program = in.name(), index = GLuint(in.integer(0, 16));
  const GLsizei size = in.bounded_size(32);
  std::vector<GLchar> name = text_buffer(size);
  GLsizei length = 0;
  GLint elements = 0;
  GLenum type = 0;
  get(program, index, size, in.boolean() ? &length : nullptr, &elements, &type, name.data());
}

void get_attached(FuzzInput& in, void (*get)(GLuint, GLsizei, GLsizei*, GLuint*)) {
  const GLsizei max = in.bounded_size(4);
  std::vector<GLuint> shaders(size_t(std::max(max, 1)));
  GLsizei count = 0;
  get(in.name(), max, in.boolean() ? &count : nullptr, shaders.data());
}

constexpr GLenum kObjectParameters[] = {GL_OBJECT_TYPE_ARB, GL_OBJECT_SUBTYPE_ARB, GL_OBJECT_DELETE_STATUS_ARB,
                                        GL_OBJECT_COMPILE_STATUS_ARB, GL_OBJECT_INFO_LOG_LENGTH_ARB,
                                        GL_OBJECT_ATTACHED_OBJECTS_ARB, GL_OBJECT_ACTIVE_UNIFORMS_ARB};

GLuint compiled_shader(FuzzInput& in, GLenum type, size_t first_source, size_t sources) {
  const GLuint shader = glCreateShader(type);
  const char* source = kSources[first_source + in.byte() % sources].data();
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  return shader;
}

// What an application does to draw with GLSL, in one call: the separate calls rarely meet on
// the same names. The shaders are flagged for deletion or kept, the program used or not.
void program_from_sources(FuzzInput& in, ClientMemory&) {
  const GLuint vertex = compiled_shader(in, GL_VERTEX_SHADER, 0, kVertexSources);
  const GLuint fragment = compiled_shader(in, GL_FRAGMENT_SHADER, kVertexSources, std::size(kSources) - kVertexSources);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  if (in.boolean()) glBindAttribLocation(program, GLuint(in.integer(0, 15)), pick(in, kAttribNames));
  glLinkProgram(program);
  if (in.boolean()) glUseProgram(program);
  if (in.boolean()) {
    glDeleteShader(vertex);
    glDeleteShader(fragment);
  }
}

const GlCall kCalls[] = {
    {"program from sources", program_from_sources},
    {"program from sources", program_from_sources},
    {"glCreateShader", [](FuzzInput& in, ClientMemory&) { glCreateShader(pick_shader_type(in)); }},
    {"glCreateProgram", [](FuzzInput&, ClientMemory&) { glCreateProgram(); }},
    {"glShaderSource",
     [](FuzzInput& in, ClientMemory&) {
       // Up to three pieces with lengths: -1 (to the terminator), exact or short.
       const std::string_view source = kSources[in.byte() % std::size(kSources)];
       const GLuint shader = in.name();
       const GLsizei count = std::min(in.bounded_size(3), 3);
       const char* pieces[3];
       GLint lengths[3];
       size_t start = 0;
       for (GLsizei i = 0; i < std::max(count, 0); ++i) {
         const size_t end = i + 1 == count ? source.size() : std::min(source.size(), start + in.offset(source.size()));
         pieces[i] = source.data() + start;
         lengths[i] = i + 1 == count && in.boolean() ? -1 : GLint(end - start);
         start = end;
       }
       glShaderSource(shader, count, pieces, in.boolean() ? lengths : nullptr);
     }},
    {"glCompileShader", [](FuzzInput& in, ClientMemory&) { glCompileShader(in.name()); }},
    {"glAttachShader", [](FuzzInput& in, ClientMemory&) { glAttachShader(in.name(), in.name()); }},
    {"glDetachShader", [](FuzzInput& in, ClientMemory&) { glDetachShader(in.name(), in.name()); }},
    {"glBindAttribLocation",
     [](FuzzInput& in, ClientMemory&) { glBindAttribLocation(in.name(), GLuint(in.integer(0, 17)), pick(in, kAttribNames)); }},
    {"glLinkProgram", [](FuzzInput& in, ClientMemory&) { glLinkProgram(in.name()); }},
    {"glLinkProgram", [](FuzzInput& in, ClientMemory&) { glLinkProgram(in.name()); }},
    {"glUseProgram", [](FuzzInput& in, ClientMemory&) { glUseProgram(in.name()); }},
    {"glUseProgram", [](FuzzInput& in, ClientMemory&) { glUseProgram(in.name()); }},
    {"glValidateProgram", [](FuzzInput& in, ClientMemory&) { glValidateProgram(in.name()); }},
    {"glDeleteShader", [](FuzzInput& in, ClientMemory&) { glDeleteShader(in.name()); }},
    {"glDeleteProgram", [](FuzzInput& in, ClientMemory&) { glDeleteProgram(in.name()); }},
    {"glIsShader", [](FuzzInput& in, ClientMemory&) { glIsShader(in.name()); }},
    {"glIsProgram", [](FuzzInput& in, ClientMemory&) { glIsProgram(in.name()); }},
    {"glGetAttribLocation", [](FuzzInput& in, ClientMemory&) { glGetAttribLocation(in.name(), pick(in, kAttribNames)); }},
    {"glGetUniformLocation",
     [](FuzzInput& in, ClientMemory&) { glGetUniformLocation(in.name(), pick(in, kUniformNames)); }},
    {"glGetShaderiv",
     [](FuzzInput& in, ClientMemory&) {
       GLint v = 0;
       glGetShaderiv(in.name(),
                     in.enumeration({GL_SHADER_TYPE, GL_DELETE_STATUS, GL_COMPILE_STATUS, GL_INFO_LOG_LENGTH,
                                     GL_SHADER_SOURCE_LENGTH}),
                     &v);
     }},
    {"glGetProgramiv",
     [](FuzzInput& in, ClientMemory&) {
       GLint v = 0;
       glGetProgramiv(in.name(),
                      in.enumeration({GL_DELETE_STATUS, GL_LINK_STATUS, GL_VALIDATE_STATUS, GL_INFO_LOG_LENGTH,
                                      GL_ATTACHED_SHADERS, GL_ACTIVE_ATTRIBUTES, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH,
                                      GL_ACTIVE_UNIFORMS, GL_ACTIVE_UNIFORM_MAX_LENGTH}),
                      &v);
     }},
    {"glGetShaderInfoLog", [](FuzzInput& in, ClientMemory&) { get_text(in, 300, glGetShaderInfoLog); }},
    {"glGetProgramInfoLog", [](FuzzInput& in, ClientMemory&) { get_text(in, 300, glGetProgramInfoLog); }},
    {"glGetShaderSource", [](FuzzInput& in, ClientMemory&) { get_text(in, 600, glGetShaderSource); }},
    {"glGetActiveUniform", [](FuzzInput& in, ClientMemory&) { get_active(in, glGetActiveUniform); }},
    {"glGetActiveAttrib", [](FuzzInput& in, ClientMemory&) { get_active(in, glGetActiveAttrib); }},
    {"glGetAttachedShaders", [](FuzzInput& in, ClientMemory&) { get_attached(in, glGetAttachedShaders); }},
    // The ARB_shader_objects names (GLhandleARB is a GLuint here) and the ES 2.0 shader compiler calls.
    {"glCreateShaderObjectARB", [](FuzzInput& in, ClientMemory&) { glCreateShaderObjectARB(pick_shader_type(in)); }},
    {"glCreateProgramObjectARB", [](FuzzInput&, ClientMemory&) { glCreateProgramObjectARB(); }},
    {"glShaderSourceARB",
     [](FuzzInput& in, ClientMemory&) {
       const char* source = kSources[in.byte() % std::size(kSources)].data();
       const GLuint shader = in.name();
       glShaderSourceARB(shader, std::min(in.bounded_size(1), 1), &source, nullptr);
     }},
    {"glCompileShaderARB", [](FuzzInput& in, ClientMemory&) { glCompileShaderARB(in.name()); }},
    {"glAttachObjectARB", [](FuzzInput& in, ClientMemory&) { glAttachObjectARB(in.name(), in.name()); }},
    {"glDetachObjectARB", [](FuzzInput& in, ClientMemory&) { glDetachObjectARB(in.name(), in.name()); }},
    {"glBindAttribLocationARB",
     [](FuzzInput& in, ClientMemory&) { glBindAttribLocationARB(in.name(), GLuint(in.integer(0, 17)), pick(in, kAttribNames)); }},
    {"glLinkProgramARB", [](FuzzInput& in, ClientMemory&) { glLinkProgramARB(in.name()); }},
    {"glUseProgramObjectARB", [](FuzzInput& in, ClientMemory&) { glUseProgramObjectARB(in.name()); }},
    {"glValidateProgramARB", [](FuzzInput& in, ClientMemory&) { glValidateProgramARB(in.name()); }},
    {"glDeleteObjectARB", [](FuzzInput& in, ClientMemory&) { glDeleteObjectARB(in.name()); }},
    {"glGetHandleARB", [](FuzzInput& in, ClientMemory&) { glGetHandleARB(in.enumeration({GL_PROGRAM_OBJECT_ARB})); }},
    {"glGetObjectParameterivARB",
     [](FuzzInput& in, ClientMemory&) {
       GLint v = 0;
       const GLuint object = in.name();
       glGetObjectParameterivARB(object, in.enumeration(kObjectParameters), &v);
     }},
    {"glGetObjectParameterfvARB",
     [](FuzzInput& in, ClientMemory&) {
       GLfloat v = 0;
       const GLuint object = in.name();
       glGetObjectParameterfvARB(object, in.enumeration(kObjectParameters), &v);
     }},
    {"glGetInfoLogARB", [](FuzzInput& in, ClientMemory&) { get_text(in, 300, glGetInfoLogARB); }},
    {"glGetShaderSourceARB", [](FuzzInput& in, ClientMemory&) { get_text(in, 600, glGetShaderSourceARB); }},
    {"glGetActiveUniformARB", [](FuzzInput& in, ClientMemory&) { get_active(in, glGetActiveUniformARB); }},
    {"glGetActiveAttribARB", [](FuzzInput& in, ClientMemory&) { get_active(in, glGetActiveAttribARB); }},
    {"glGetAttachedObjectsARB", [](FuzzInput& in, ClientMemory&) { get_attached(in, glGetAttachedObjectsARB); }},
    {"glGetAttribLocationARB", [](FuzzInput& in, ClientMemory&) { glGetAttribLocationARB(in.name(), pick(in, kAttribNames)); }},
    {"glGetUniformLocationARB",
     [](FuzzInput& in, ClientMemory&) { glGetUniformLocationARB(in.name(), pick(in, kUniformNames)); }},
    {"glReleaseShaderCompiler", [](FuzzInput&, ClientMemory&) { glReleaseShaderCompiler(); }},
    {"glShaderBinary",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLuint shaders[2] = {in.name(), in.name()};
       const GLsizei length = in.bounded_size(64);
       glShaderBinary(std::min(in.bounded_size(2), 2), shaders, in.enumeration({GL_SHADER_BINARY_FORMAT_SPIR_V}),
                      memory.arrays.data(), length);
     }},
};

}  // namespace

std::span<const GlCall> program_calls() { return kCalls; }

}  // namespace pineda::fuzz
