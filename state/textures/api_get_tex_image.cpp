// glGetTexImage: a texture level read back through the pack pixel store.
#include <bit>
#include <cstring>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/framebuffers/packed_depth_stencil.h"
#include "state/buffers/pixel_buffer.h"
#include "state/pixels/color_byte_reads.h"
#include "state/pixels/pixel_format.h"
#include "state/textures/texture_format.h"
#include "state/textures/texture_target.h"

namespace pineda::gl {
namespace {

// GL 1.1 spec 6.1.4: the texel as RGBA before packing; luminance and intensity land in R only,
// and a luminance result is R alone (not R + G + B as glReadPixels sums).
void texel_rgba(uint32_t texel, raster::TexBaseFormat base, GLenum format, double rgba[4]) {
  for (int c = 0; c < 4; ++c) rgba[c] = double((texel >> (8 * c)) & 0xff) / 255.0;
  if (format == GL_LUMINANCE || format == GL_LUMINANCE_ALPHA) rgba[1] = rgba[2] = 0.0;
  using raster::TexBaseFormat;
  switch (base) {
    case TexBaseFormat::Luminance: case TexBaseFormat::LuminanceAlpha: rgba[1] = rgba[2] = 0.0; break;
    case TexBaseFormat::Intensity: rgba[1] = rgba[2] = 0.0; rgba[3] = 1.0; break;
    default: break;
  }
}

// A luminance, luminance-alpha or intensity level's texels as texel_rgba gives them, in `out` as
// RGBA8 words (stored bytes k read as k / 255 and packed back as bytes are k); false, with
// nothing written, for the other formats, whose stored texels are what texel_rgba gives.
bool rgba8_texel_row(const uint32_t* texels, int n, raster::TexBaseFormat base, uint32_t* out) {
  using raster::TexBaseFormat;
  if (base != TexBaseFormat::Luminance && base != TexBaseFormat::LuminanceAlpha && base != TexBaseFormat::Intensity)
    return false;
  const uint32_t set = base == TexBaseFormat::Intensity ? 0xff000000u : 0u;
  for (int i = 0; i < n; ++i) out[i] = (texels[i] & 0xff0000ffu) | set;
  return true;
}

bool is_depth_level(const TextureLevelData& l) {
  return texture_format(l.internal_format).value_or(TextureFormat{}).depth > 0;
}

// A 1D, 2D or 3D texture or one cube map face; no proxies. `client_bytes`: how much client
// memory `pixels` holds (glGetnTexImageARB), when no pack buffer is bound.
void get_tex_image(Context& ctx, GLenum target, GLint level, GLenum format, GLenum type, void* pixels,
                   size_t client_bytes) {
  ImageTarget t;
  if (!image_target(target, t) || t.proxy)
    return ctx.record_error(GL_INVALID_ENUM, "target is not a texture image target");
  GlError error;
  const bool packed_ds = packed_depth_stencil_pixels(format, type, error);
  if (!packed_ds)
    error = format == GL_DEPTH_COMPONENT ? pixel_rect_format_type_error(format, type) : color_format_type_error(format, type);
  if (error != GL_NO_ERROR) return ctx.record_error(error);
  if (level < 0 || level > max_texture_level(t.kind))
    return ctx.record_error(GL_INVALID_VALUE, "level is negative or above log2 of the maximum texture size");
  resolve_rendered_textures(ctx);
  const GLuint name = bound_name(ctx.texture_units[ctx.active_texture], t.kind);
  const std::vector<TextureLevelData>& levels =
      ctx.textures.get_or_create(name, binding_enum(t.kind)).face_levels(t.face);
  if (size_t(level) >= levels.size() || levels[level].width == 0) return;  // nothing defined
  const bool depth_texture = is_depth_level(levels[level]);
  const TextureLevelData& l = levels[level];
  const bool volume = t.kind == TexTarget::T3D;
  auto writes = [&] {
    const size_t bytes = client_image_extent(ctx.pack, l.width, l.height, l.depth, volume, format, type);
    return pack_pixels(ctx, pixels, bytes, client_bytes) && pixels;
  };
  if (packed_ds) {  // a DEPTH_STENCIL level only
    if (l.stencil.empty()) return ctx.record_error(GL_INVALID_OPERATION, "the level is not a depth-stencil image");
    if (!writes()) return;
    const ImageLayout layout = packed_depth_stencil_layout(ctx.pack, l.width, type);
    auto* out = static_cast<uint8_t*>(pixels) + layout.offset;
    for (int y = 0; y < l.height; ++y)
      for (int x = 0; x < l.width; ++x) {
        const size_t k = size_t(y) * l.width + x;
        uint8_t* dst = out + layout.row_stride * size_t(y) + layout.pixel_bytes * size_t(x);
        store_depth_stencil(std::bit_cast<float>(l.texels[k]), l.stencil[k], type, ctx.pack.swap_bytes, dst);
      }
    return;
  }
  if (depth_texture != (format == GL_DEPTH_COMPONENT))  // as Mesa
    return ctx.record_error(GL_INVALID_OPERATION,
                            "format is GL_DEPTH_COMPONENT and the texture is not depth, or the reverse");
  if (!writes()) return;
  // The border texels of a bordered level are not kept: only the inner image is written.
  const ImageLayout layout = image_layout(ctx.pack, l.width, format, type);
  const size_t image_rows = ctx.pack.image_height > 0 ? size_t(ctx.pack.image_height) : size_t(l.height);
  const size_t image_stride = layout.row_stride * image_rows;
  auto* out = static_cast<uint8_t*>(pixels) + layout.offset + (volume ? size_t(ctx.pack.skip_images) * image_stride : 0);
  if (!depth_texture && packs_rgba8_bytes(format, type)) {  // bytes moved as stored (color_byte_reads.h)
    std::vector<uint32_t> row(size_t(l.width));
    for (int z = 0; z < l.depth; ++z)
      for (int y = 0; y < l.height; ++y) {
        const uint32_t* texels = &l.texels[(size_t(z) * l.height + y) * l.width];
        if (rgba8_texel_row(texels, l.width, l.base, row.data())) texels = row.data();
        pack_rgba8_row(reinterpret_cast<const uint8_t*>(texels), false, format, 0,
                       out + image_stride * size_t(z) + layout.row_stride * size_t(y), l.width,
                       reverses_rgba8_words(type, ctx.pack.swap_bytes));
      }
    return;
  }
  for (int z = 0; z < l.depth; ++z)
    for (int y = 0; y < l.height; ++y)
      for (int x = 0; x < l.width; ++x) {
        double rgba[4];
        const uint32_t texel = l.texels[(size_t(z) * l.height + y) * l.width + x];
        uint8_t* dst = out + image_stride * size_t(z) + layout.row_stride * size_t(y) + layout.pixel_bytes * size_t(x);
        if (depth_texture) {  // one component, converted as RED is
          rgba[0] = std::bit_cast<float>(texel);
          store_color(rgba, GL_RED, type, dst);
        } else {
          texel_rgba(texel, l.base, format, rgba);
          store_color(rgba, format, type, dst);
        }
        if (ctx.pack.swap_bytes) swap_pixel_bytes(dst, depth_texture ? GL_RED : format, type);
      }
}

}  // namespace

void GetTexImage(Context& ctx, GLenum target, GLint level, GLenum format, GLenum type, void* pixels) {
  get_tex_image(ctx, target, level, format, type, pixels, SIZE_MAX);
}

void GetnTexImageARB(Context& ctx, GLenum target, GLint level, GLenum format, GLenum type, GLsizei buf_size,
                     void* img) {
  get_tex_image(ctx, target, level, format, type, img, client_buffer_bytes(buf_size));
}

}  // namespace pineda::gl
