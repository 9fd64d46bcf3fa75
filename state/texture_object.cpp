#include "state/texture_object.h"

#include <algorithm>

#include "state/texture_format.h"

namespace pineda {
namespace {

raster::TexFilter to_raster_filter(GLenum f) {
  switch (f) {
    case GL_NEAREST: return raster::TexFilter::Nearest;
    case GL_LINEAR: return raster::TexFilter::Linear;
    case GL_NEAREST_MIPMAP_NEAREST: return raster::TexFilter::NearestMipmapNearest;
    case GL_LINEAR_MIPMAP_NEAREST: return raster::TexFilter::LinearMipmapNearest;
    case GL_NEAREST_MIPMAP_LINEAR: return raster::TexFilter::NearestMipmapLinear;
    default: return raster::TexFilter::LinearMipmapLinear;
  }
}

raster::TexWrap to_raster_wrap(GLenum w) {
  switch (w) {
    case GL_CLAMP: return raster::TexWrap::Clamp;
    case GL_CLAMP_TO_EDGE: return raster::TexWrap::ClampToEdge;
    case GL_CLAMP_TO_BORDER: return raster::TexWrap::ClampToBorder;
    case GL_MIRRORED_REPEAT: return raster::TexWrap::MirroredRepeat;
    default: return raster::TexWrap::Repeat;
  }
}

bool uses_mipmaps(GLenum min_filter) { return min_filter != GL_NEAREST && min_filter != GL_LINEAR; }

// The next smaller level: each texel the rounded average of the 2x2 (or 2x1) texels it
// covers, as Mesa's software mipmap generation computes it, in the level's stored bits.
void downsample_level(const TextureLevelData& src, TextureLevelData& dst) {
  dst.width = std::max(1, src.width / 2);
  dst.height = std::max(1, src.height / 2);
  dst.border = 0;
  dst.internal_format = src.internal_format;
  dst.base = src.base;
  dst.texels.assign(size_t(dst.width) * dst.height, 0u);
  const TextureFormat storage = texture_format(src.internal_format).value_or(TextureFormat{});
  const int dx = src.width > 1 ? 1 : 0, dy = src.height > 1 ? 1 : 0;
  for (int y = 0; y < dst.height; ++y)
    for (int x = 0; x < dst.width; ++x) {
      const int x0 = x * 2, y0 = y * 2;
      const uint32_t* row0 = src.texels.data() + size_t(y0) * src.width;
      const uint32_t* row1 = src.texels.data() + size_t(y0 + dy) * src.width;
      const uint32_t quad[4] = {row0[x0], row0[x0 + dx], row1[x0], row1[x0 + dx]};
      uint32_t out = 0;
      for (int c = 0; c < 32; c += 8) {
        uint32_t sum = 2;
        for (uint32_t t : quad) sum += (t >> c) & 0xffu;
        out |= (sum / 4) << c;
      }
      dst.texels[size_t(y) * dst.width + x] = requantize_texel(out, storage);
    }
}

}  // namespace

raster::Sampler TextureObject::sampler() const {
  raster::Sampler s;
  s.min_filter = to_raster_filter(params.min_filter);
  s.mag_filter = to_raster_filter(params.mag_filter);
  s.wrap_s = to_raster_wrap(params.wrap_s);
  s.wrap_t = to_raster_wrap(params.wrap_t);
  std::copy(params.border_color, params.border_color + 4, s.border_color);
  s.min_lod = params.min_lod;
  s.max_lod = params.max_lod;
  s.lod_bias = params.lod_bias;
  return s;
}

// GL 1.5 3.8.10 completeness: the base level exists with a non-zero size; when the
// minification filter uses mipmaps, every level from the base down to 1x1 (or to MAX_LEVEL)
// exists with halved sizes and the base level's internal format. The snapshot's level 0 is
// the base level.
std::shared_ptr<const raster::TextureImage> TextureObject::snapshot() {
  if (snapshot_valid_) return snapshot_;
  snapshot_valid_ = true;
  snapshot_.reset();
  const size_t base = size_t(params.base_level);
  if (base >= levels.size() || levels[base].width <= 0 || levels[base].height <= 0) return nullptr;
  auto image = std::make_shared<raster::TextureImage>();
  image->base_format = levels[base].base;
  size_t count = 1;
  if (uses_mipmaps(params.min_filter)) {
    if (params.max_level < params.base_level) return nullptr;
    int w = levels[base].width, h = levels[base].height;
    while ((w > 1 || h > 1) && base + count <= size_t(params.max_level)) {
      w = std::max(1, w / 2);
      h = std::max(1, h / 2);
      const size_t l = base + count;
      if (l >= levels.size() || levels[l].width != w || levels[l].height != h ||
          levels[l].internal_format != levels[base].internal_format)
        return nullptr;
      ++count;
    }
  }
  image->levels.resize(count);
  for (size_t l = 0; l < count; ++l) {
    image->levels[l].width = levels[base + l].width;
    image->levels[l].height = levels[base + l].height;
    image->levels[l].texels = levels[base + l].texels;
  }
  snapshot_ = std::move(image);
  return snapshot_;
}

void TextureObject::level_changed(int level) {
  changed();
  if (!params.generate_mipmap || level != params.base_level || size_t(level) >= levels.size()) return;
  for (size_t l = size_t(level); levels[l].width > 1 || levels[l].height > 1; ++l) {
    if (levels.size() <= l + 1) levels.resize(l + 2);
    downsample_level(levels[l], levels[l + 1]);
  }
}

TextureNamespace::TextureNamespace() {
  default_2d_.target = GL_TEXTURE_2D;
  default_1d_.target = GL_TEXTURE_1D;
}

void TextureNamespace::generate(GLsizei n, GLuint* names) {
  for (GLsizei i = 0; i < n; ++i) {
    while (objects_.count(next_name_) || reserved_.count(next_name_) || next_name_ == 0) ++next_name_;
    reserved_[next_name_] = true;
    names[i] = next_name_++;
  }
}

TextureObject& TextureNamespace::get_or_create(GLuint name, GLenum target) {
  if (name == 0) return target == GL_TEXTURE_1D ? default_1d_ : default_2d_;
  auto& slot = objects_[name];
  if (!slot) {
    slot = std::make_unique<TextureObject>();
    reserved_.erase(name);
  }
  return *slot;
}

TextureObject* TextureNamespace::find(GLuint name) {
  auto it = objects_.find(name);
  return it == objects_.end() ? nullptr : it->second.get();
}

void TextureNamespace::remove(GLuint name) {
  objects_.erase(name);
  reserved_.erase(name);
}

bool TextureNamespace::is_texture(GLuint name) const { return name != 0 && objects_.count(name) != 0; }

}  // namespace pineda
