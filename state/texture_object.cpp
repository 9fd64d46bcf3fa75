#include "state/texture_object.h"

#include <algorithm>

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

}  // namespace

raster::Sampler TextureObject::sampler() const {
  raster::Sampler s;
  s.min_filter = to_raster_filter(min_filter);
  s.mag_filter = to_raster_filter(mag_filter);
  s.wrap_s = to_raster_wrap(wrap_s);
  s.wrap_t = to_raster_wrap(wrap_t);
  std::copy(border_color, border_color + 4, s.border_color);
  return s;
}

// GL 1.1 completeness: level 0 exists with a non-zero size; when the minification filter
// uses mipmaps, every level down to 1x1 exists with halved sizes and the same format.
std::shared_ptr<const raster::TextureImage> TextureObject::snapshot() {
  if (snapshot_valid_) return snapshot_;
  snapshot_valid_ = true;
  snapshot_.reset();
  if (levels.empty() || levels[0].width <= 0 || levels[0].height <= 0) return nullptr;
  auto image = std::make_shared<raster::TextureImage>();
  image->base_format = base_format;
  size_t count = 1;
  if (uses_mipmaps(min_filter)) {
    int w = levels[0].width, h = levels[0].height;
    while (w > 1 || h > 1) {
      w = std::max(1, w / 2);
      h = std::max(1, h / 2);
      const size_t l = count;
      if (l >= levels.size() || levels[l].width != w || levels[l].height != h ||
          levels[l].internal_format != levels[0].internal_format)
        return nullptr;
      ++count;
    }
  }
  image->levels.resize(count);
  for (size_t l = 0; l < count; ++l) {
    image->levels[l].width = levels[l].width;
    image->levels[l].height = levels[l].height;
    image->levels[l].texels = levels[l].texels;
  }
  snapshot_ = std::move(image);
  return snapshot_;
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
