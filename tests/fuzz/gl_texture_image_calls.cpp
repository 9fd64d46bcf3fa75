// The fuzzed texture image calls the GL 1.x table leaves out: compressed images (Pineda
// supports no compressed format, so every one must be rejected without reading its data),
// one-dimensional and three-dimensional copies and updates, residency and priorities.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <vector>

#include "tests/fuzz/gl_calls.h"

namespace pineda::fuzz {
namespace {

// The paletted ones: an OpenGL ES 1.1 context's (EGL calls make one current).
constexpr GLenum kCompressedFormats[] = {GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, GL_COMPRESSED_RGB, GL_COMPRESSED_RGBA,
                                         GL_COMPRESSED_RGB_FXT1_3DFX, GL_RGBA, GL_COMPRESSED_LUMINANCE,
                                         GL_PALETTE4_RGB8_OES, GL_PALETTE8_RGBA4_OES};
constexpr GLenum kTargets1D[] = {GL_TEXTURE_1D, GL_PROXY_TEXTURE_1D};
constexpr GLenum kTargets2D[] = {GL_TEXTURE_2D, GL_PROXY_TEXTURE_2D, GL_TEXTURE_CUBE_MAP_NEGATIVE_X,
                                 GL_PROXY_TEXTURE_CUBE_MAP, GL_TEXTURE_RECTANGLE_ARB, GL_PROXY_TEXTURE_RECTANGLE_ARB};
constexpr GLenum kTargets3D[] = {GL_TEXTURE_3D, GL_PROXY_TEXTURE_3D};
constexpr GLenum kFormats[] = {GL_RGBA, GL_RGB, GL_LUMINANCE, GL_DEPTH_COMPONENT, GL_BGRA, GL_COLOR_INDEX};
constexpr GLenum kTypes[] = {GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_INT_8_8_8_8_REV,
                             GL_BITMAP, GL_SHORT};

// The data of a compressed image: imageSize bytes, in ClientMemory or a pixel unpack buffer.
struct CompressedData {
  GLsizei size;
  const void* data;
};

CompressedData compressed_data(FuzzInput& in, const ClientMemory& memory) {
  const GLsizei size = in.bounded_size(4096);
  return {size, memory.image_source(size_t(std::max(size, 0)), size < 0)};
}

template <typename Call>
void compressed_image_1d(FuzzInput& in, ClientMemory& memory, Call call) {
  const GLenum target = in.enumeration(kTargets1D), format = in.enumeration(kCompressedFormats);
  const GLint level = in.integer(0, 4), border = in.integer(0, 1);
  const CheckedSize w = in.checked_size(17);
  const CompressedData data = compressed_data(in, memory);
  call(target, level, format, w.value, border, data.size, data.data);
}

template <typename Call>
void compressed_image_2d(FuzzInput& in, ClientMemory& memory, Call call) {
  const GLenum target = in.enumeration(kTargets2D), format = in.enumeration(kCompressedFormats);
  const GLint level = in.integer(-3, 4), border = in.integer(0, 1);  // (a paletted image's levels: 0 or negative)
  const CheckedSize w = in.checked_size(17), h = in.checked_size(17);
  const CompressedData data = compressed_data(in, memory);
  call(target, level, format, w.value, h.value, border, data.size, data.data);
}

template <typename Call>
void compressed_image_3d(FuzzInput& in, ClientMemory& memory, Call call) {
  const GLenum target = in.enumeration(kTargets3D), format = in.enumeration(kCompressedFormats);
  const GLint level = in.integer(0, 4), border = in.integer(0, 1);
  const CheckedSize w = in.checked_size(9), h = in.checked_size(9), d = in.checked_size(9);
  const CompressedData data = compressed_data(in, memory);
  call(target, level, format, w.value, h.value, d.value, border, data.size, data.data);
}

template <typename Call>
void compressed_sub_image_1d(FuzzInput& in, ClientMemory& memory, Call call) {
  const GLenum target = in.enumeration(kTargets1D);
  const GLint level = in.integer(0, 4), x = in.integer(-1, 8);
  const GLsizei w = in.bounded_size(17);
  const GLenum format = in.enumeration(kCompressedFormats);
  const CompressedData data = compressed_data(in, memory);
  call(target, level, x, w, format, data.size, data.data);
}

template <typename Call>
void compressed_sub_image_2d(FuzzInput& in, ClientMemory& memory, Call call) {
  const GLenum target = in.enumeration(kTargets2D);
  const GLint level = in.integer(0, 4), x = in.integer(-1, 8), y = in.integer(-1, 8);
  const GLsizei w = in.bounded_size(17), h = in.bounded_size(17);
  const GLenum format = in.enumeration(kCompressedFormats);
  const CompressedData data = compressed_data(in, memory);
  call(target, level, x, y, w, h, format, data.size, data.data);
}

template <typename Call>
void compressed_sub_image_3d(FuzzInput& in, ClientMemory& memory, Call call) {
  const GLenum target = in.enumeration(kTargets3D);
  const GLint level = in.integer(0, 4), x = in.integer(-1, 8), y = in.integer(-1, 8), z = in.integer(-1, 8);
  const GLsizei w = in.bounded_size(9), h = in.bounded_size(9), d = in.bounded_size(9);
  const GLenum format = in.enumeration(kCompressedFormats);
  const CompressedData data = compressed_data(in, memory);
  call(target, level, x, y, z, w, h, d, format, data.size, data.data);
}

// No compressed image can exist, so nothing may be written: a byte is enough to see a write.
template <typename Call>
void get_compressed_image(FuzzInput& in, ClientMemory& memory, Call call) {
  std::vector<uint8_t> out(1);
  const GLenum target = in.enumeration({GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP_POSITIVE_Y});
  call(target, in.integer(0, 4), memory.image_destination(out));
}

void copy_tex_sub_image_3d(FuzzInput& in, void (*copy)(GLenum, GLint, GLint, GLint, GLint, GLint, GLint, GLsizei,
                                                       GLsizei)) {
  const GLint level = in.integer(0, 3), x = in.integer(-1, 8), y = in.integer(-1, 8), z = in.integer(-1, 8);
  copy(in.enumeration(kTargets3D), level, x, y, z, in.integer(-8, 40), in.integer(-8, 40), in.bounded_size(40),
       in.bounded_size(40));
}

const GlCall kCalls[] = {
    {"glCompressedTexImage1D", [](FuzzInput& in, ClientMemory& m) { compressed_image_1d(in, m, glCompressedTexImage1D); }},
    {"glCompressedTexImage1DARB",
     [](FuzzInput& in, ClientMemory& m) { compressed_image_1d(in, m, glCompressedTexImage1DARB); }},
    {"glCompressedTexImage2D", [](FuzzInput& in, ClientMemory& m) { compressed_image_2d(in, m, glCompressedTexImage2D); }},
    {"glCompressedTexImage2DARB",
     [](FuzzInput& in, ClientMemory& m) { compressed_image_2d(in, m, glCompressedTexImage2DARB); }},
    {"glCompressedTexImage3D", [](FuzzInput& in, ClientMemory& m) { compressed_image_3d(in, m, glCompressedTexImage3D); }},
    {"glCompressedTexImage3DARB",
     [](FuzzInput& in, ClientMemory& m) { compressed_image_3d(in, m, glCompressedTexImage3DARB); }},
    {"glCompressedTexSubImage1D",
     [](FuzzInput& in, ClientMemory& m) { compressed_sub_image_1d(in, m, glCompressedTexSubImage1D); }},
    {"glCompressedTexSubImage1DARB",
     [](FuzzInput& in, ClientMemory& m) { compressed_sub_image_1d(in, m, glCompressedTexSubImage1DARB); }},
    {"glCompressedTexSubImage2D",
     [](FuzzInput& in, ClientMemory& m) { compressed_sub_image_2d(in, m, glCompressedTexSubImage2D); }},
    {"glCompressedTexSubImage2DARB",
     [](FuzzInput& in, ClientMemory& m) { compressed_sub_image_2d(in, m, glCompressedTexSubImage2DARB); }},
    {"glCompressedTexSubImage3D",
     [](FuzzInput& in, ClientMemory& m) { compressed_sub_image_3d(in, m, glCompressedTexSubImage3D); }},
    {"glCompressedTexSubImage3DARB",
     [](FuzzInput& in, ClientMemory& m) { compressed_sub_image_3d(in, m, glCompressedTexSubImage3DARB); }},
    {"glGetCompressedTexImage",
     [](FuzzInput& in, ClientMemory& m) { get_compressed_image(in, m, glGetCompressedTexImage); }},
    {"glGetCompressedTexImageARB",
     [](FuzzInput& in, ClientMemory& m) { get_compressed_image(in, m, glGetCompressedTexImageARB); }},
    {"glCopyTexImage1D",
     [](FuzzInput& in, ClientMemory&) {
       const CheckedSize w = in.checked_size(40);
       glCopyTexImage1D(in.enumeration(kTargets1D), in.integer(0, 4), in.enumeration({GL_RGBA, GL_LUMINANCE, GL_DEPTH_COMPONENT}),
                        in.integer(-8, 40), in.integer(-8, 40), w.value, in.integer(0, 1));
     }},
    {"glCopyTexSubImage1D",
     [](FuzzInput& in, ClientMemory&) {
       const GLint level = in.integer(0, 4), x = in.integer(-1, 8);
       glCopyTexSubImage1D(in.enumeration(kTargets1D), level, x, in.integer(-8, 40), in.integer(-8, 40),
                           in.bounded_size(40));
     }},
    {"glCopyTexSubImage3D", [](FuzzInput& in, ClientMemory&) { copy_tex_sub_image_3d(in, glCopyTexSubImage3D); }},
    {"glCopyTexSubImage3DEXT", [](FuzzInput& in, ClientMemory&) { copy_tex_sub_image_3d(in, glCopyTexSubImage3DEXT); }},
    {"glTexSubImage1D",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLint level = in.integer(0, 4), x = in.integer(-1, 8);
       const CheckedSize w = in.checked_size(17);
       const GLenum format = in.enumeration(kFormats), type = in.enumeration(kTypes);
       glTexSubImage1D(in.enumeration(kTargets1D), level, x, w.value, format, type,
                       memory.image_source(image_footprint(false, w.value, 1, 1), w.huge));
     }},
    {"glTexImage3DEXT",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLint level = in.integer(0, 3);
       const CheckedSize w = in.checked_size(9), h = in.checked_size(9), d = in.checked_size(9);
       const GLenum format = in.enumeration(kFormats), type = in.enumeration(kTypes);
       const void* pixels = memory.image_source(image_footprint(false, w.value, h.value, d.value), w.huge || h.huge || d.huge);
       glTexImage3DEXT(in.enumeration(kTargets3D), level, in.enumeration({GL_RGBA, GL_RGB8, GL_LUMINANCE_ALPHA}),
                       w.value, h.value, d.value, in.integer(0, 1), format, type, pixels);
     }},
    {"glTexSubImage3DEXT",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLint level = in.integer(0, 3), x = in.integer(-1, 4), y = in.integer(-1, 4), z = in.integer(-1, 4);
       const CheckedSize w = in.checked_size(9), h = in.checked_size(9), d = in.checked_size(9);
       const GLenum format = in.enumeration(kFormats), type = in.enumeration(kTypes);
       const void* pixels = memory.image_source(image_footprint(false, w.value, h.value, d.value), w.huge || h.huge || d.huge);
       glTexSubImage3DEXT(in.enumeration(kTargets3D), level, x, y, z, w.value, h.value, d.value, format, type, pixels);
     }},
    {"glAreTexturesResident",
     [](FuzzInput& in, ClientMemory&) {
       const GLuint names[3] = {in.name(), in.name(), in.name()};
       GLboolean resident[3];
       glAreTexturesResident(std::min(in.bounded_size(3), 3), names, resident);
     }},
    {"glPrioritizeTextures",
     [](FuzzInput& in, ClientMemory&) {
       const GLuint names[3] = {in.name(), in.name(), in.name()};
       const GLclampf priorities[3] = {in.unit(), in.unit(), in.real()};
       glPrioritizeTextures(std::min(in.bounded_size(3), 3), names, priorities);
     }},
};

}  // namespace

std::span<const GlCall> texture_image_calls() { return kCalls; }

}  // namespace pineda::fuzz
