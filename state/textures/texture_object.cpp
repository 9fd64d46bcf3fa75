#include "state/textures/texture_object.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "raster/srgb.h"
#include "raster/texture_swizzle.h"
#include "state/enum_translate.h"
#include "state/textures/texture_format.h"
#include "state/textures/texture_rectangle.h"
#include "state/textures/sampling_params.h"

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

raster::TexSwizzle raster_swizzle(const GLenum (&swizzle)[4]) {
  raster::TexSwizzle out{};
  for (int c = 0; c < 4; ++c) {
    switch (swizzle[c]) {
      case GL_RED: out[c] = 0; break;
      case GL_GREEN: out[c] = 1; break;
      case GL_BLUE: out[c] = 2; break;
      case GL_ALPHA: out[c] = 3; break;
      case GL_ZERO: out[c] = raster::kSwizzleZero; break;
      default: out[c] = raster::kSwizzleOne; break;
    }
  }
  return out;
}

// A colour snapshot's texels swizzled in place, so that every sampler reads them as they are;
// the texture environment keeps the base format. sRGB levels decode R, G and B after the swizzle
// as before it, unless it moves alpha into them or them into alpha: then they are decoded first,
// to 8 bits.
void swizzle_texels(raster::TextureImage& image, const raster::TexSwizzle& swizzle) {
  const bool mixes_alpha = swizzle[0] == 3 || swizzle[1] == 3 || swizzle[2] == 3 || swizzle[3] < 3;
  const std::array<float, 256>& decode = raster::srgb_decode_table();
  for (raster::TextureLevel& level : image.levels) {
    const bool decode_first = level.srgb && mixes_alpha;
    for (uint32_t& texel : level.texels.edit()) {
      if (decode_first) {
        uint32_t linear = texel & 0xff000000u;
        for (int c = 0; c < 3; ++c)
          linear |= uint32_t(std::lround(decode[(texel >> (8 * c)) & 0xffu] * 255.f)) << (8 * c);
        texel = linear;
      }
      texel = raster::swizzle_texel(swizzle, texel);
    }
    if (decode_first) level.srgb = false;
  }
  image.env_format = image.base_format;
  image.base_format = raster::TexBaseFormat::RGBA;
}

// A rectangle texture sampled through a sampler object: complete only without mipmap filters
// and repeating wrap modes (the values glTexParameter refuses for it).
bool rectangle_sampling(const TexParams& sampling) {
  const auto clamps = [](GLenum wrap) { return wrap != GL_REPEAT && wrap != GL_MIRRORED_REPEAT; };
  return !uses_mipmaps(sampling.min_filter) && clamps(sampling.wrap_s) && clamps(sampling.wrap_t);
}

// The rounded average of n texels per channel.
template <size_t n>
uint32_t average(const uint32_t (&texels)[n]) {
  uint32_t out = 0;
  for (int c = 0; c < 32; c += 8) {
    uint32_t sum = n / 2;
    for (uint32_t t : texels) sum += (t >> c) & 0xffu;
    out |= (sum / n) << c;
  }
  return out;
}

// The next smaller level: each texel the rounded average of the 2x2 (or 2x1) texels it
// covers, as Mesa's software mipmap generation computes it, in the level's stored bits; of
// 2x2x2 texels for a 3D level.
void downsample_level(const TextureLevelData& src, TextureLevelData& level) {
  TextureLevelData dst;  // built aside: running out of memory leaves `level` as it was
  dst.width = std::max(1, src.width / 2);
  dst.height = std::max(1, src.height / 2);
  dst.depth = std::max(1, src.depth / 2);
  dst.border = 0;
  dst.internal_format = src.internal_format;
  dst.base = src.base;
  dst.texels.assign(size_t(dst.width) * dst.height * dst.depth, 0u);
  const TextureFormat storage = texture_format(src.internal_format).value_or(TextureFormat{});
  const int dx = src.width > 1 ? 1 : 0, dy = src.height > 1 ? 1 : 0, dz = src.depth > 1 ? 1 : 0;
  auto at = [&](int x, int y, int z) { return src.texels[(size_t(z) * src.height + y) * src.width + x]; };
  if (!storage.depth && src.depth == 1 && keeps_bytes(storage)) {  // requantize_texel keeps every byte
    for (int y = 0; y < dst.height; ++y) {
      const uint32_t* row0 = &src.texels[size_t(2 * y) * src.width];
      const uint32_t* row1 = row0 + size_t(dy) * src.width;
      uint32_t* out = &dst.texels[size_t(y) * dst.width];
      for (int x = 0; x < dst.width; ++x) {
        const uint32_t quad[4] = {row0[2 * x], row0[2 * x + dx], row1[2 * x], row1[2 * x + dx]};
        out[x] = average(quad);
      }
    }
    level = std::move(dst);
    return;
  }
  for (int z = 0; z < dst.depth; ++z)
    for (int y = 0; y < dst.height; ++y)
      for (int x = 0; x < dst.width; ++x) {
        const int x0 = x * 2, y0 = y * 2, z0 = z * 2;
        uint32_t& out = dst.texels[(size_t(z) * dst.height + y) * dst.width + x];
        const uint32_t quad[4] = {at(x0, y0, z0), at(x0 + dx, y0, z0), at(x0, y0 + dy, z0), at(x0 + dx, y0 + dy, z0)};
        if (storage.depth) {  // depth texels are floats (only 1D and 2D textures have them)
          float sum = 0.f;
          for (uint32_t t : quad) sum += std::bit_cast<float>(t);
          out = depth_texel(sum / 4.f, storage);
          continue;
        }
        if (src.depth == 1) {
          out = requantize_texel(average(quad), storage);
          continue;
        }
        const int z1 = z0 + dz;
        const uint32_t box[8] = {quad[0], quad[1], quad[2], quad[3],
                                 at(x0, y0, z1), at(x0 + dx, y0, z1), at(x0, y0 + dy, z1), at(x0 + dx, y0 + dy, z1)};
        out = requantize_texel(average(box), storage);
      }
  level = std::move(dst);
}

raster::TexKind image_kind(GLenum target) {
  if (target == GL_TEXTURE_3D) return raster::TexKind::Volume;
  if (target == GL_TEXTURE_RECTANGLE_ARB) return raster::TexKind::Rect;
  if (target == GL_TEXTURE_CUBE_MAP) return raster::TexKind::Cube;
  return raster::TexKind::Planar;
}

bool same_size(const TextureLevelData& a, int w, int h, int d, GLint internal_format) {
  return a.width == w && a.height == h && a.depth == d && a.internal_format == internal_format;
}

// How many levels from `base` on form a complete chain (GL 1.5 3.8.10); 0 when incomplete.
size_t complete_levels(const std::vector<TextureLevelData>& levels, size_t base, const TexParams& params) {
  if (base >= levels.size() || levels[base].width <= 0 || levels[base].height <= 0 || levels[base].depth <= 0)
    return 0;
  if (!uses_mipmaps(params.min_filter)) return 1;
  if (params.max_level < params.base_level) return 0;
  int w = levels[base].width, h = levels[base].height, d = levels[base].depth;
  size_t count = 1;
  while ((w > 1 || h > 1 || d > 1) && base + count <= size_t(params.max_level)) {
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    d = std::max(1, d / 2);
    const size_t l = base + count;
    if (l >= levels.size() || !same_size(levels[l], w, h, d, levels[base].internal_format)) return 0;
    ++count;
  }
  return count;
}

}  // namespace

raster::Sampler TextureObject::sampler(const TexParams* sampling) const {
  const TexParams params = sampling ? with_sampling_params(this->params, *sampling) : this->params;
  raster::Sampler s;
  s.min_filter = to_raster_filter(params.min_filter);
  s.mag_filter = to_raster_filter(params.mag_filter);
  s.wrap_s = to_raster_wrap(params.wrap_s);
  s.wrap_t = to_raster_wrap(params.wrap_t);
  s.wrap_r = to_raster_wrap(params.wrap_r);
  // GL 1.5 3.8.8: the border colour is taken as a texel of the texture's internal format.
  std::copy(params.border_color, params.border_color + 4, s.border_color);
  const size_t base = size_t(params.base_level);
  if (base < levels.size()) {
    reduce_to_base_format(s.border_color, levels[base].base);
    // A depth texture's border is a depth: its sampler swizzles what the depth mode makes of it.
    if (!texture_format(levels[base].internal_format).value_or(TextureFormat{}).depth)
      raster::swizzle_rgba(raster_swizzle(params.swizzle), s.border_color);
  }
  // A 1D texture has no t: its one row is read whatever t is (no border above or below).
  if (target == GL_TEXTURE_1D) s.wrap_t = raster::TexWrap::Repeat;
  s.min_lod = params.min_lod;
  s.max_lod = params.max_lod;
  s.lod_bias = params.lod_bias;
  s.compare = params.compare_mode == GL_COMPARE_R_TO_TEXTURE;
  to_compare_func(params.compare_func, s.compare_func);
  return s;
}

// GL 1.5 3.8.10 completeness: the base level exists with a non-zero size; when the
// minification filter uses mipmaps, every level from the base down to 1x1 (or to MAX_LEVEL)
// exists with halved sizes and the base level's internal format. A cube map is complete when
// each face is and the faces' base levels are square, of one size and one internal format
// (GL 1.3 3.8.10, "cube complete"). The snapshot's level 0 is the base level; a cube map level
// holds the six faces as slices.
std::shared_ptr<const raster::TextureImage> TextureObject::snapshot(const TexParams* sampling, bool rendered_into) {
  if (sampling && target == GL_TEXTURE_RECTANGLE_ARB && !rectangle_sampling(*sampling)) return nullptr;
  const SnapshotKey own = snapshot_key(params, rendered_into);
  if (!sampling || snapshot_key(*sampling, rendered_into) == own) {
    if (!snapshot_valid_ || snapshot_key_ != own) {
      snapshot_ = build_snapshot(own);
      snapshot_key_ = own;
      snapshot_valid_ = true;
    }
    return snapshot_;
  }
  // A sampler object's minification filter decides completeness on its own (ARB_sampler_objects),
  // its sRGB decoding what the levels hold.
  const SnapshotKey key = snapshot_key(*sampling, rendered_into);
  if (!other_snapshot_valid_ || other_snapshot_key_ != key) {
    other_snapshot_ = build_snapshot(key);
    other_snapshot_key_ = key;
    other_snapshot_valid_ = true;
  }
  return other_snapshot_;
}

TextureObject::SnapshotKey TextureObject::snapshot_key(const TexParams& sampling, bool copies) {
  return {uses_mipmaps(sampling.min_filter), sampling.srgb_decode == GL_DECODE_EXT, copies};
}

std::shared_ptr<raster::TextureImage> TextureObject::build_snapshot(SnapshotKey key) const {
  // Immutable storage: the levels in use clamped into its levels, whatever glPopAttrib restored.
  TexParams params = this->params;
  params.min_filter = key.mipmapped ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST;
  params.base_level = clamped_level_param(GL_TEXTURE_BASE_LEVEL, params.base_level);
  params.max_level = clamped_level_param(GL_TEXTURE_MAX_LEVEL, params.max_level);
  const size_t base = size_t(params.base_level);
  const raster::TexKind kind = image_kind(target);
  const int faces = kind == raster::TexKind::Cube ? kCubeFaces : 1;
  const size_t count = complete_levels(levels, base, params);
  if (count == 0) return nullptr;
  if (kind == raster::TexKind::Cube) {
    const TextureLevelData& b = levels[base];
    if (b.width != b.height) return nullptr;
    for (int f = 1; f < faces; ++f) {
      const std::vector<TextureLevelData>& face = face_levels(f);
      if (base >= face.size() || !same_size(face[base], b.width, b.height, b.depth, b.internal_format) ||
          complete_levels(face, base, params) != count)
        return nullptr;
    }
  }
  auto image = std::make_shared<raster::TextureImage>();
  image->base_format = levels[base].base;
  image->depth = texture_format(levels[base].internal_format).value_or(TextureFormat{}).depth > 0;
  if (image->depth)
    image->base_format = params.depth_mode == GL_INTENSITY ? raster::TexBaseFormat::Intensity
                         : params.depth_mode == GL_ALPHA   ? raster::TexBaseFormat::Alpha
                                                           : raster::TexBaseFormat::Luminance;
  image->kind = kind;
  image->levels.resize(count);
  for (size_t l = 0; l < count; ++l) {
    raster::TextureLevel& out = image->levels[l];
    const TextureLevelData& in = levels[base + l];
    out.width = in.width;
    out.height = in.height;
    out.depth = faces == 1 ? in.depth : faces;
    out.srgb = key.srgb_decode && texture_format(in.internal_format).value_or(TextureFormat{}).srgb;
    out.texel_coords = kind == raster::TexKind::Rect;
    if (faces == 1 && !key.copies) {
      out.texels = raster::LevelTexels(in.texels.share());
      continue;
    }
    raster::LevelTexels::Storage texels;  // a cube map's faces as the slices of one level
    texels.reserve(size_t(out.width) * out.height * out.depth);
    for (int f = 0; f < faces; ++f) {
      const SharedTexels<uint32_t>& face = face_levels(f)[base + l].texels;
      texels.insert(texels.end(), face.begin(), face.end());
    }
    out.texels = std::move(texels);
  }
  const raster::TexSwizzle swizzle = raster_swizzle(params.swizzle);
  if (swizzle != raster::kIdentitySwizzle) {
    if (image->depth) image->depth_swizzle = swizzle;
    else swizzle_texels(*image, swizzle);
  }
  return image;
}

void TextureObject::level_changed(int level, int face) {
  changed();
  if (params.generate_mipmap && level == params.base_level) generate_levels(level, face);
}

void TextureObject::box_changed(int level, int face, const TexelBox& box) {
  if (params.generate_mipmap && level == params.base_level) return level_changed(level, face);
  if (!patch_snapshot(level, face, box)) {
    snapshot_.reset();
    snapshot_valid_ = false;
  }
  other_snapshot_.reset();
  other_snapshot_valid_ = false;
  ++version;
}

void TextureObject::before_texels_change(int level, int face) {
  std::vector<TextureLevelData>& chain = face_levels(face);
  if (level < 0 || size_t(level) >= chain.size()) return;
  SharedTexels<uint32_t>& texels = chain[size_t(level)].texels;
  long unheld = 0;  // levels of this object's snapshots that read the texels and that no draw holds
  for (const std::shared_ptr<raster::TextureImage>* own : {&snapshot_, &other_snapshot_}) {
    if (!*own || own->use_count() != 1) continue;
    for (const raster::TextureLevel& l : (*own)->levels) unheld += l.texels.data() == texels.data() ? 1 : 0;
  }
  if (texels.snapshot_holders() <= unheld) return;  // they see the change, as a patch would give them
  texels.detach();
  drop_snapshots();  // rebuilt at the next draw, reading the detached texels
}

// Only the context's thread copies snapshot_: held by no one else, no draw can be reading it.
bool TextureObject::patch_snapshot(int level, int face, const TexelBox& box) {
  if (!snapshot_valid_ || !snapshot_ || snapshot_.use_count() != 1) return false;
  if (snapshot_->env_format) return false;  // swizzled texels: rebuilt whole
  const int64_t l = int64_t(level) - clamped_level_param(GL_TEXTURE_BASE_LEVEL, params.base_level);  // as snapshot()
  if (l < 0 || l >= int64_t(snapshot_->levels.size())) return false;
  const TextureLevelData& in = face_levels(face)[size_t(level)];
  raster::TextureLevel& out = snapshot_->levels[size_t(l)];
  if (out.texels.data() == in.texels.data()) return true;  // it reads the level's texels: changed already
  const size_t face_texels = in.texels.size();
  if (out.texels.size() < face_texels * size_t(face + 1)) return false;
  raster::LevelTexels::Storage& texels = out.texels.edit();  // its own (copied), held by no draw
  for (int z = 0; z < box.depth; ++z)
    for (int y = 0; y < box.height; ++y) {
      const size_t at = (size_t(box.z + z) * size_t(in.height) + size_t(box.y + y)) * size_t(in.width) + size_t(box.x);
      std::copy_n(in.texels.begin() + at, box.width, texels.begin() + ptrdiff_t(face_texels * size_t(face) + at));
    }
  return true;
}

void TextureObject::generate_levels(int level, int face) {
  changed();
  std::vector<TextureLevelData>& chain = face_levels(face);
  if (level < 0 || size_t(level) >= chain.size()) return;
  // An image with a zero width, height or depth has no texels to derive levels from.
  if (chain[level].width == 0 || chain[level].height == 0 || chain[level].depth == 0) return;
  for (size_t l = size_t(level); chain[l].width > 1 || chain[l].height > 1 || chain[l].depth > 1; ++l) {
    // Immutable storage keeps its levels: no level is added below the last (the spec's issue 22).
    if (immutable_levels > 0 && l + 1 >= chain.size()) break;
    if (chain.size() <= l + 1) chain.resize(l + 2);
    downsample_level(chain[l], chain[l + 1]);
  }
}

void TextureObject::make_immutable(GLint levels) {
  immutable_levels = levels;
  params.base_level = clamped_level_param(GL_TEXTURE_BASE_LEVEL, params.base_level);
  params.max_level = clamped_level_param(GL_TEXTURE_MAX_LEVEL, params.max_level);
  changed();
}

GLint TextureObject::clamped_level_param(GLenum pname, GLint level) const {
  if (immutable_levels <= 0) return level;
  if (pname == GL_TEXTURE_BASE_LEVEL) return std::clamp(level, 0, immutable_levels - 1);
  return std::clamp(level, std::min(params.base_level, immutable_levels - 1), immutable_levels - 1);
}

TextureNamespace::TextureNamespace() {
  for (int k = 0; k < kTexTargetCount; ++k) {
    defaults_[k].target = binding_enum(TexTarget(k));
    defaults_[k].params = default_tex_params(TexTarget(k));
    proxies_[k].target = binding_enum(TexTarget(k));
    proxies_[k].params = default_tex_params(TexTarget(k));
  }
}

void TextureNamespace::generate(GLsizei n, GLuint* names) {
  for (GLsizei i = 0; i < n; ++i) {
    while (objects_.count(next_name_) || reserved_.count(next_name_) || next_name_ == 0) ++next_name_;
    reserved_[next_name_] = true;
    names[i] = next_name_++;
  }
}

TextureObject& TextureNamespace::get_or_create(GLuint name, GLenum target) {
  TexTarget kind = TexTarget::T2D;
  if (name == 0) return binding_target(target, kind) ? defaults_[size_t(kind)] : defaults_[size_t(TexTarget::T2D)];
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
