// The fuzzed framebuffer object calls (GL 3.0 / ARB_framebuffer_object as GL 2.1 exports them,
// and by their EXT_framebuffer_object names) and the other GL 1.4-2.0 state calls the
// fixed-function table leaves out, with their ARB, ATI and EXT names.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <vector>

#include "tests/fuzz/es_prototypes.h"
#include "tests/fuzz/gl_calls.h"
#include "tests/fuzz/object_names.h"

namespace pineda::fuzz {
namespace {

constexpr GLenum kFramebufferTargets[] = {GL_FRAMEBUFFER, GL_DRAW_FRAMEBUFFER, GL_READ_FRAMEBUFFER};
constexpr GLenum kAttachments[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT7,
                                   GL_DEPTH_ATTACHMENT,  GL_STENCIL_ATTACHMENT, GL_DEPTH_STENCIL_ATTACHMENT,
                                   GL_COLOR_ATTACHMENT8};
constexpr GLenum kRenderbufferFormats[] = {GL_RGBA8,           GL_RGB,          GL_RGBA4,          GL_RGB565,
                                           GL_RGB5_A1,         GL_ALPHA8,       GL_LUMINANCE8,     GL_RGBA16F,
                                           GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24,
                                           GL_DEPTH_COMPONENT32, GL_STENCIL_INDEX8, GL_STENCIL_INDEX,
                                           GL_DEPTH_STENCIL,   GL_DEPTH24_STENCIL8, GL_RGBA, GL_RGB10_A2};
constexpr GLenum kTextureTargets2D[] = {GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_CUBE_MAP_NEGATIVE_Y,
                                        GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP,
                                        GL_TEXTURE_RECTANGLE_ARB};
constexpr GLenum kColorBuffers[] = {GL_NONE,  GL_FRONT, GL_BACK, GL_FRONT_AND_BACK, GL_LEFT, GL_FRONT_LEFT,
                                    GL_AUX0,  GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT7,
                                    GL_COLOR_ATTACHMENT8};
constexpr GLenum kBlendFactors[] = {GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA,
                                    GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_SRC_ALPHA_SATURATE,
                                    GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA};
constexpr GLenum kBlendEquations[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};

// A blit coordinate: mostly around the 32x32 surfaces, sometimes an extreme (INT_MIN, INT_MAX...).
GLint blit_coordinate(FuzzInput& in) { return in.integer(-40, 80); }

GLbitfield blit_mask(FuzzInput& in) {
  const uint8_t pick = in.byte();
  if (pick % 8 == 7) return GLbitfield(in.integer(0, 0xffff));
  GLbitfield mask = 0;
  if (pick & 8) mask |= GL_COLOR_BUFFER_BIT;
  if (pick & 16) mask |= GL_DEPTH_BUFFER_BIT;
  if (pick & 32) mask |= GL_STENCIL_BUFFER_BIT;
  return mask;
}

constexpr GLenum kTexEnvTargets[] = {GL_TEXTURE_ENV, GL_TEXTURE_FILTER_CONTROL, GL_POINT_SPRITE};
constexpr GLenum kTexEnvNames[] = {GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR, GL_COMBINE_RGB, GL_SOURCE2_ALPHA,
                                   GL_RGB_SCALE, GL_TEXTURE_LOD_BIAS, GL_COORD_REPLACE};

template <typename T>
void get_tex_env(FuzzInput& in, void (*get)(GLenum, GLenum, T*)) {
  std::vector<T> out(4);  // GL_TEXTURE_ENV_COLOR, the largest
  const GLenum target = in.enumeration(kTexEnvTargets);
  get(target, in.enumeration(kTexEnvNames), out.data());
}

// Each helper takes the call as a template argument: the GL 3.0 and the EXT names share it.
template <auto Bind>
void bind_framebuffer(FuzzInput& in, ClientMemory&) {
  Bind(in.enumeration(kFramebufferTargets), in.name());
}

template <auto Bind>
void bind_renderbuffer(FuzzInput& in, ClientMemory&) {
  Bind(in.enumeration({GL_RENDERBUFFER}), in.name());
}

template <auto Storage>
void renderbuffer_storage(FuzzInput& in, ClientMemory&) {
  const GLenum format = in.enumeration(kRenderbufferFormats);
  const CheckedSize w = in.checked_size(40), h = in.checked_size(40);
  Storage(in.enumeration({GL_RENDERBUFFER}), format, w.value, h.value);
}

template <auto Storage>
void renderbuffer_storage_multisample(FuzzInput& in, ClientMemory&) {
  const GLenum format = in.enumeration(kRenderbufferFormats);
  const CheckedSize w = in.checked_size(40), h = in.checked_size(40);
  Storage(in.enumeration({GL_RENDERBUFFER}), in.integer(0, 8), format, w.value, h.value);
}

template <auto Attach>
void framebuffer_renderbuffer(FuzzInput& in, ClientMemory&) {
  const GLenum target = in.enumeration(kFramebufferTargets), attachment = in.enumeration(kAttachments);
  Attach(target, attachment, in.enumeration({GL_RENDERBUFFER}), in.name());
}

template <auto Attach>
void framebuffer_texture_1d(FuzzInput& in, ClientMemory&) {
  const GLenum target = in.enumeration(kFramebufferTargets), attachment = in.enumeration(kAttachments);
  const GLuint texture = in.name();
  Attach(target, attachment, in.enumeration({GL_TEXTURE_1D, GL_TEXTURE_2D}), texture, in.integer(0, 4));
}

template <auto Attach>
void framebuffer_texture_2d(FuzzInput& in, ClientMemory&) {
  const GLenum target = in.enumeration(kFramebufferTargets), attachment = in.enumeration(kAttachments);
  const GLenum textarget = in.enumeration(kTextureTargets2D);
  const GLuint texture = in.name();
  Attach(target, attachment, textarget, texture, in.integer(0, 4));
}

template <auto Attach>
void framebuffer_texture_3d(FuzzInput& in, ClientMemory&) {
  const GLenum target = in.enumeration(kFramebufferTargets), attachment = in.enumeration(kAttachments);
  const GLuint texture = in.name();
  const GLint level = in.integer(0, 3);
  Attach(target, attachment, in.enumeration({GL_TEXTURE_3D, GL_TEXTURE_2D}), texture, level, in.integer(-1, 9));
}

template <auto Check>
void check_framebuffer_status(FuzzInput& in, ClientMemory&) {
  Check(in.enumeration(kFramebufferTargets));
}

template <auto Blit>
void blit_framebuffer(FuzzInput& in, ClientMemory&) {
  const GLint sx0 = blit_coordinate(in), sy0 = blit_coordinate(in), sx1 = blit_coordinate(in),
              sy1 = blit_coordinate(in);
  const GLint dx0 = blit_coordinate(in), dy0 = blit_coordinate(in), dx1 = blit_coordinate(in),
              dy1 = blit_coordinate(in);
  const GLbitfield mask = blit_mask(in);
  Blit(sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, mask, in.enumeration({GL_NEAREST, GL_LINEAR}));
}

template <auto Generate>
void generate_mipmap(FuzzInput& in, ClientMemory&) {
  Generate(in.enumeration({GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_RECTANGLE_ARB}));
}

template <auto Get>
void get_attachment_parameter(FuzzInput& in, ClientMemory&) {
  GLint v = 0;
  const GLenum target = in.enumeration(kFramebufferTargets);
  const GLenum attachment =
      in.enumeration({GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT, GL_STENCIL_ATTACHMENT, GL_DEPTH_STENCIL_ATTACHMENT,
                      GL_FRONT_LEFT, GL_BACK, GL_DEPTH, GL_STENCIL, GL_COLOR_ATTACHMENT8});
  Get(target, attachment,
      in.enumeration({GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                      GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE,
                      GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE,
                      GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
                      GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING}),
      &v);
}

template <auto Get>
void get_renderbuffer_parameter(FuzzInput& in, ClientMemory&) {
  GLint v = 0;
  Get(in.enumeration({GL_RENDERBUFFER}),
      in.enumeration({GL_RENDERBUFFER_WIDTH, GL_RENDERBUFFER_HEIGHT, GL_RENDERBUFFER_INTERNAL_FORMAT,
                      GL_RENDERBUFFER_SAMPLES, GL_RENDERBUFFER_STENCIL_SIZE, GL_RENDERBUFFER_ALPHA_SIZE}),
      &v);
}

template <auto Set>
void draw_buffers(FuzzInput& in, ClientMemory&) {
  GLenum bufs[9];
  for (GLenum& b : bufs) b = in.enumeration(kColorBuffers);
  Set(in.integer(-1, 9), bufs);
}

template <auto Set>
void blend_equation_separate(FuzzInput& in, ClientMemory&) {
  Set(in.enumeration(kBlendEquations), in.enumeration(kBlendEquations));
}

template <auto Set>
void blend_func_separate(FuzzInput& in, ClientMemory&) {
  Set(in.enumeration(kBlendFactors), in.enumeration(kBlendFactors), in.enumeration(kBlendFactors),
      in.enumeration(kBlendFactors));
}

const GlCall kCalls[] = {
    {"glGenFramebuffers", gen_names<glGenFramebuffers, 4>},
    {"glGenFramebuffersEXT", gen_names<glGenFramebuffersEXT, 4>},
    {"glGenFramebuffersOES", gen_names<glGenFramebuffersOES, 4>},
    {"glBindFramebuffer", bind_framebuffer<glBindFramebuffer>},
    {"glBindFramebuffer", bind_framebuffer<glBindFramebuffer>},
    {"glBindFramebufferEXT", bind_framebuffer<glBindFramebufferEXT>},
    {"glBindFramebufferOES", bind_framebuffer<glBindFramebufferOES>},
    {"glDeleteFramebuffers", delete_names<glDeleteFramebuffers>},
    {"glDeleteFramebuffersEXT", delete_names<glDeleteFramebuffersEXT>},
    {"glDeleteFramebuffersOES", delete_names<glDeleteFramebuffersOES>},
    {"glIsFramebuffer", [](FuzzInput& in, ClientMemory&) { glIsFramebuffer(in.name()); }},
    {"glGenRenderbuffers", gen_names<glGenRenderbuffers, 4>},
    {"glGenRenderbuffersEXT", gen_names<glGenRenderbuffersEXT, 4>},
    {"glGenRenderbuffersOES", gen_names<glGenRenderbuffersOES, 4>},
    {"glBindRenderbuffer", bind_renderbuffer<glBindRenderbuffer>},
    {"glBindRenderbufferEXT", bind_renderbuffer<glBindRenderbufferEXT>},
    {"glBindRenderbufferOES", bind_renderbuffer<glBindRenderbufferOES>},
    {"glDeleteRenderbuffers", delete_names<glDeleteRenderbuffers>},
    {"glDeleteRenderbuffersEXT", delete_names<glDeleteRenderbuffersEXT>},
    {"glDeleteRenderbuffersOES", delete_names<glDeleteRenderbuffersOES>},
    {"glIsRenderbuffer", [](FuzzInput& in, ClientMemory&) { glIsRenderbuffer(in.name()); }},
    {"glIsRenderbufferOES", [](FuzzInput& in, ClientMemory&) { glIsRenderbufferOES(in.name()); }},
    {"glIsFramebufferOES", [](FuzzInput& in, ClientMemory&) { glIsFramebufferOES(in.name()); }},
    {"glRenderbufferStorage", renderbuffer_storage<glRenderbufferStorage>},
    {"glRenderbufferStorageEXT", renderbuffer_storage<glRenderbufferStorageEXT>},
    {"glRenderbufferStorageOES", renderbuffer_storage<glRenderbufferStorageOES>},
    {"glRenderbufferStorageMultisample", renderbuffer_storage_multisample<glRenderbufferStorageMultisample>},
    {"glRenderbufferStorageMultisampleEXT", renderbuffer_storage_multisample<glRenderbufferStorageMultisampleEXT>},
    {"glFramebufferRenderbuffer", framebuffer_renderbuffer<glFramebufferRenderbuffer>},
    {"glFramebufferRenderbufferEXT", framebuffer_renderbuffer<glFramebufferRenderbufferEXT>},
    {"glFramebufferRenderbufferOES", framebuffer_renderbuffer<glFramebufferRenderbufferOES>},
    {"glFramebufferTexture2D", framebuffer_texture_2d<glFramebufferTexture2D>},
    {"glFramebufferTexture2D", framebuffer_texture_2d<glFramebufferTexture2D>},
    {"glFramebufferTexture2DEXT", framebuffer_texture_2d<glFramebufferTexture2DEXT>},
    {"glFramebufferTexture2DOES", framebuffer_texture_2d<glFramebufferTexture2DOES>},
    {"glFramebufferTexture1D", framebuffer_texture_1d<glFramebufferTexture1D>},
    {"glFramebufferTexture1DEXT", framebuffer_texture_1d<glFramebufferTexture1DEXT>},
    {"glFramebufferTexture3D", framebuffer_texture_3d<glFramebufferTexture3D>},
    {"glFramebufferTexture3DEXT", framebuffer_texture_3d<glFramebufferTexture3DEXT>},
    {"glFramebufferTextureLayer",
     [](FuzzInput& in, ClientMemory&) {
       const GLenum target = in.enumeration(kFramebufferTargets), attachment = in.enumeration(kAttachments);
       const GLuint texture = in.name();
       const GLint level = in.integer(0, 3);
       glFramebufferTextureLayer(target, attachment, texture, level, in.integer(-1, 9));
     }},
    {"glCheckFramebufferStatus", check_framebuffer_status<glCheckFramebufferStatus>},
    {"glCheckFramebufferStatusEXT", check_framebuffer_status<glCheckFramebufferStatusEXT>},
    {"glCheckFramebufferStatusOES", check_framebuffer_status<glCheckFramebufferStatusOES>},
    {"glBlitFramebuffer", blit_framebuffer<glBlitFramebuffer>},
    {"glBlitFramebufferEXT", blit_framebuffer<glBlitFramebufferEXT>},
    {"glGenerateMipmap", generate_mipmap<glGenerateMipmap>},
    {"glGenerateMipmapEXT", generate_mipmap<glGenerateMipmapEXT>},
    {"glGenerateMipmapOES", generate_mipmap<glGenerateMipmapOES>},
    {"glGetFramebufferAttachmentParameteriv", get_attachment_parameter<glGetFramebufferAttachmentParameteriv>},
    {"glGetFramebufferAttachmentParameterivEXT", get_attachment_parameter<glGetFramebufferAttachmentParameterivEXT>},
    {"glGetFramebufferAttachmentParameterivOES", get_attachment_parameter<glGetFramebufferAttachmentParameterivOES>},
    {"glGetRenderbufferParameteriv", get_renderbuffer_parameter<glGetRenderbufferParameteriv>},
    {"glGetRenderbufferParameterivEXT", get_renderbuffer_parameter<glGetRenderbufferParameterivEXT>},
    {"glGetRenderbufferParameterivOES", get_renderbuffer_parameter<glGetRenderbufferParameterivOES>},
    {"glDrawBuffer", [](FuzzInput& in, ClientMemory&) { glDrawBuffer(in.enumeration(kColorBuffers)); }},
    {"glReadBuffer", [](FuzzInput& in, ClientMemory&) { glReadBuffer(in.enumeration(kColorBuffers)); }},
    {"glDrawBuffers(attachments)", draw_buffers<glDrawBuffers>},
    {"glDrawBuffersARB", draw_buffers<glDrawBuffersARB>},
    {"glDrawBuffersATI", draw_buffers<glDrawBuffersATI>},
    {"glDrawBuffersEXT", draw_buffers<glDrawBuffersEXT>},
    {"glBlendEquationSeparate", blend_equation_separate<glBlendEquationSeparate>},
    {"glBlendEquationSeparateEXT", blend_equation_separate<glBlendEquationSeparateEXT>},
    {"glBlendFuncSeparate", blend_func_separate<glBlendFuncSeparate>},
    {"glBlendFuncSeparateEXT", blend_func_separate<glBlendFuncSeparateEXT>},
    {"glBlendColor", [](FuzzInput& in, ClientMemory&) { glBlendColor(in.unit(), in.unit(), in.unit(), in.unit()); }},
    {"glSampleCoverage", [](FuzzInput& in, ClientMemory&) { glSampleCoverage(in.unit(), in.boolean()); }},
    {"glSampleCoverageARB", [](FuzzInput& in, ClientMemory&) { glSampleCoverageARB(in.unit(), in.boolean()); }},
    {"glColorMaskIndexedEXT",
     [](FuzzInput& in, ClientMemory&) {
       glColorMaskIndexedEXT(GLuint(in.integer(0, 8)), in.boolean(), in.boolean(), in.boolean(), in.boolean());
     }},
    {"glStencilFuncSeparateATI",
     [](FuzzInput& in, ClientMemory&) {
       const GLenum front = in.enumeration({GL_NEVER, GL_LESS, GL_EQUAL, GL_ALWAYS});
       glStencilFuncSeparateATI(front, in.enumeration({GL_GEQUAL, GL_NOTEQUAL, GL_ALWAYS}), in.integer(-2, 300),
                                GLuint(in.integer(0, 255)));
     }},
    {"glDiscardFramebufferEXT",
     [](FuzzInput& in, ClientMemory&) {
       GLenum attachments[3];
       // GL_COLOR, GL_DEPTH and GL_STENCIL are the values of GL_COLOR_EXT, GL_DEPTH_EXT and GL_STENCIL_EXT.
       for (GLenum& a : attachments) a = in.enumeration({GL_COLOR, GL_DEPTH, GL_STENCIL, GL_COLOR_ATTACHMENT0});
       glDiscardFramebufferEXT(in.enumeration(kFramebufferTargets), std::min(in.integer(-1, 3), 3), attachments);
     }},
    {"glPointParameterfv",
     [](FuzzInput& in, ClientMemory& memory) {
       glPointParameterfv(in.enumeration({GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX, GL_POINT_FADE_THRESHOLD_SIZE,
                                          GL_POINT_DISTANCE_ATTENUATION, GL_POINT_SPRITE_COORD_ORIGIN}),
                          reinterpret_cast<const GLfloat*>(memory.arrays.data() + in.offset(64) * 4));
     }},
    {"glGetBufferParameteriv",
     [](FuzzInput& in, ClientMemory&) {
       GLint v = 0;
       glGetBufferParameteriv(
           in.enumeration({GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER, GL_PIXEL_PACK_BUFFER, GL_PIXEL_UNPACK_BUFFER}),
           in.enumeration({GL_BUFFER_SIZE, GL_BUFFER_USAGE, GL_BUFFER_ACCESS, GL_BUFFER_MAPPED}), &v);
     }},
    {"glGetTexParameteriv",
     [](FuzzInput& in, ClientMemory&) {
       std::vector<GLint> out(4);  // GL_TEXTURE_BORDER_COLOR, the largest
       glGetTexParameteriv(in.enumeration({GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP}),
                           in.enumeration({GL_TEXTURE_MIN_FILTER, GL_TEXTURE_WRAP_R, GL_TEXTURE_BORDER_COLOR,
                                           GL_TEXTURE_MAX_LEVEL, GL_GENERATE_MIPMAP, GL_TEXTURE_COMPARE_FUNC,
                                           GL_TEXTURE_RESIDENT, GL_TEXTURE_PRIORITY}),
                           out.data());
     }},
    {"glTexEnvfv",
     [](FuzzInput& in, ClientMemory&) {
       const GLenum target = in.enumeration(kTexEnvTargets), pname = in.enumeration(kTexEnvNames);
       const GLfloat v[4] = {in.real(), in.unit(), in.unit(), in.unit()};
       glTexEnvfv(target, pname, v);
     }},
    {"glGetTexEnvfv", [](FuzzInput& in, ClientMemory&) { get_tex_env(in, glGetTexEnvfv); }},
    {"glGetTexEnviv", [](FuzzInput& in, ClientMemory&) { get_tex_env(in, glGetTexEnviv); }},
};

}  // namespace

std::span<const GlCall> framebuffer_calls() { return kCalls; }

}  // namespace pineda::fuzz
