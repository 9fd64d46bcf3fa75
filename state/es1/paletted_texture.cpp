// OES_compressed_paletted_texture: decoding a palette and its indices into ordinary levels.
// A 4-bit index's first texel is the high nibble of its byte; a level's indices start on a byte
// and rows are not padded (what llvmpipe reads). Errors in Mesa's order: level, border, width and
// height, then an imageSize other than the palette and every level's indices (all GL_INVALID_VALUE).
#include "state/es1/paletted_texture.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/textures/texture_target.h"

namespace pineda {
namespace {

struct PaletteLayout {
  int index_bits;     // 4 or 8
  int entry_bytes;    // bytes per palette entry
  GLenum format;      // of the decoded texels and the stored level
  GLenum type;
  int entries() const { return 1 << index_bits; }
  int64_t palette_bytes() const { return int64_t(entries()) * entry_bytes; }
  int64_t index_bytes(int64_t texels) const { return index_bits == 4 ? (texels + 1) / 2 : texels; }
};

PaletteLayout layout_of(GLenum format) {
  const int bits = format <= GL_PALETTE4_RGB5_A1_OES ? 4 : 8;
  switch ((format - GL_PALETTE4_RGB8_OES) % 5) {
    case 0: return {bits, 3, GL_RGB, GL_UNSIGNED_BYTE};
    case 1: return {bits, 4, GL_RGBA, GL_UNSIGNED_BYTE};
    case 2: return {bits, 2, GL_RGB, GL_UNSIGNED_SHORT_5_6_5};
    case 3: return {bits, 2, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4};
    default: return {bits, 2, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1};
  }
}

int level_extent(int size, int level) { return std::max(size >> level, 1); }

// Palette entries of the level's texels, tightly packed in the palette's own format and type.
std::vector<uint8_t> decode_level(const PaletteLayout& layout, const uint8_t* palette, const uint8_t* indices,
                                  int64_t texels) {
  std::vector<uint8_t> out(size_t(texels) * layout.entry_bytes);
  for (int64_t i = 0; i < texels; ++i) {
    const int index = layout.index_bits == 8 ? indices[i] : (i % 2 ? indices[i / 2] & 0xf : indices[i / 2] >> 4);
    std::memcpy(&out[size_t(i) * layout.entry_bytes], palette + index * layout.entry_bytes, layout.entry_bytes);
  }
  return out;
}

}  // namespace

bool paletted_format(GLenum format) { return format >= GL_PALETTE4_RGB8_OES && format <= GL_PALETTE8_RGB5_A1_OES; }

GLenum paletted_format_at(int i) { return GL_PALETTE4_RGB8_OES + GLenum(i); }

void paletted_tex_image(Context& ctx, GLenum target, GLint level, GLenum format, GLsizei width, GLsizei height,
                        GLint border, GLsizei image_size, const void* data) {
  if (target != GL_TEXTURE_2D) return ctx.record_error(GL_INVALID_ENUM, "target is not GL_TEXTURE_2D");
  if (level > 0 || -int64_t(level) > max_texture_level(TexTarget::T2D))
    return ctx.record_error(GL_INVALID_VALUE, "level is positive, or minus level is above the last mipmap level");
  if (border != 0) return ctx.record_error(GL_INVALID_VALUE, "border is not 0");
  const int max_size = max_texture_size(TexTarget::T2D);
  if (width < 0 || height < 0 || width > max_size || height > max_size)
    return ctx.record_error(GL_INVALID_VALUE, "width or height is negative or above GL_MAX_TEXTURE_SIZE");
  const PaletteLayout layout = layout_of(format);
  const int levels = 1 - level;
  int64_t expected = layout.palette_bytes();
  for (int l = 0; l < levels; ++l)
    expected += layout.index_bytes(int64_t(level_extent(width, l)) * level_extent(height, l));
  if (image_size != expected)
    return ctx.record_error(GL_INVALID_VALUE, "imageSize is not the size of the palette and every level's indices");

  // The decoded levels are tightly packed: read them with the default unpack state (restored
  // also when an allocation throws).
  struct TightUnpack {
    Context& ctx;
    const PixelStore application_unpack;
    explicit TightUnpack(Context& c) : ctx(c), application_unpack(c.unpack) {
      ctx.unpack = PixelStore{};
      ctx.unpack.alignment = 1;
    }
    ~TightUnpack() { ctx.unpack = application_unpack; }
  } tight_unpack(ctx);
  const auto* palette = static_cast<const uint8_t*>(data);
  const uint8_t* indices = palette ? palette + layout.palette_bytes() : nullptr;
  for (int l = 0; l < levels; ++l) {
    const int w = level_extent(width, l), h = level_extent(height, l);
    const int64_t texels = width == 0 || height == 0 ? 0 : int64_t(w) * h;
    const std::vector<uint8_t> texels_of_level =
        indices ? decode_level(layout, palette, indices, texels) : std::vector<uint8_t>{};
    gl::TexImage2D(ctx, target, l, GLint(layout.format), width == 0 ? 0 : w, height == 0 ? 0 : h, 0,
                   layout.format, layout.type, indices ? texels_of_level.data() : nullptr);
    if (indices) indices += layout.index_bytes(int64_t(w) * h);
  }
}

}  // namespace pineda
