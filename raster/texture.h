// Texture images as the sampler sees them: immutable once handed to a draw, so a scene
// that is still queued keeps reading the image it was recorded with.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "raster/compare_func.h"
#include "raster/level_texels.h"
#include "raster/texture_swizzle.h"

namespace pineda::raster {

// Fixed-function texture units (environments, texgen, matrices, coordinate sets)...
constexpr int kMaxTextureUnits = 4;
// ...and the texture image units shaders sample (GL 2.0 MAX_TEXTURE_IMAGE_UNITS and
// MAX_COMBINED_TEXTURE_IMAGE_UNITS; ES 2.0 requires 8): the first kMaxTextureUnits are both.
constexpr int kMaxTextureImageUnits = 8;

// Which components a texture really has; decides how TexEnv combines it.
enum class TexBaseFormat : uint8_t { Alpha, Luminance, LuminanceAlpha, Intensity, RGB, RGBA };

struct TextureLevel {
  int width = 0;
  int height = 0;
  // RGBA8, R in the lowest byte; row 0 first (t = 0), slice 0 first (r = 0, or the +X face).
  // Shared with the texture's state where the snapshot's level is the state's as it is (one
  // face, no swizzle): level_texels.h.
  LevelTexels texels;
  int depth = 1;  // slices of a 3D level; the six faces of a cube map level
  bool srgb = false;  // R, G, B are sRGB-encoded: decoded per texel before filtering (raster/srgb.h)
  // A rectangle's level: s and t are in texels already, so the factor that turns them into texel
  // units is 1, not the size (texel centres i + 0.5 land exactly).
  bool texel_coords = false;
};

// How the sampler addresses the image: 1D and 2D textures are Planar (s, t), 3D textures
// Volume (s, t, r), cube maps Cube (the direction s, t, r selects a face), rectangle textures
// Rect (s, t in texels: [0, width] x [0, height], one level, only the clamping wrap modes).
enum class TexKind : uint8_t { Planar, Volume, Cube, Rect };

struct TextureImage {
  // For a depth texture (`depth`) the texels are float depths in [0, 1] and the base format
  // (Luminance, Intensity or Alpha: DEPTH_TEXTURE_MODE) says where the sampled value goes.
  TexBaseFormat base_format = TexBaseFormat::RGBA;
  // A colour texture with a swizzle (texture_swizzle.h) has it applied to its texels already:
  // they are RGBA (base_format) and env_format keeps the base format that the texture
  // environment applies. A depth texture's swizzle follows DEPTH_TEXTURE_MODE in its sampler.
  std::optional<TexBaseFormat> env_format;
  TexSwizzle depth_swizzle = kIdentitySwizzle;
  TexBaseFormat texenv_format() const { return env_format.value_or(base_format); }
  bool depth = false;
  TexKind kind = TexKind::Planar;
  std::vector<TextureLevel> levels;  // level 0 first; a complete chain when mipmapped
};

enum class TexFilter : uint8_t {
  Nearest, Linear,
  NearestMipmapNearest, LinearMipmapNearest, NearestMipmapLinear, LinearMipmapLinear
};
enum class TexWrap : uint8_t { Repeat, Clamp, ClampToEdge, ClampToBorder, MirroredRepeat };
enum class TexEnvMode : uint8_t { Modulate, Replace, Decal, Blend, Add, Combine };

// GL_COMBINE (GL 1.3 3.8.13, ARB_texture_env_combine/_crossbar/_dot3).
enum class CombineFunc : uint8_t { Replace, Modulate, Add, AddSigned, Interpolate, Subtract, Dot3Rgb, Dot3Rgba };
enum class CombineSource : uint8_t { Texture, Constant, PrimaryColor, Previous, Texture0 };  // Texture0 + i: unit i
enum class CombineOperand : uint8_t { SrcColor, OneMinusSrcColor, SrcAlpha, OneMinusSrcAlpha };

struct CombineState {
  CombineFunc rgb_func = CombineFunc::Modulate, alpha_func = CombineFunc::Modulate;
  CombineSource rgb_source[3] = {CombineSource::Texture, CombineSource::Previous, CombineSource::Constant};
  CombineSource alpha_source[3] = {CombineSource::Texture, CombineSource::Previous, CombineSource::Constant};
  CombineOperand rgb_operand[3] = {CombineOperand::SrcColor, CombineOperand::SrcColor, CombineOperand::SrcAlpha};
  CombineOperand alpha_operand[3] = {CombineOperand::SrcAlpha, CombineOperand::SrcAlpha, CombineOperand::SrcAlpha};
  float rgb_scale = 1.f, alpha_scale = 1.f;
};

struct Sampler {
  TexFilter min_filter = TexFilter::NearestMipmapLinear;
  TexFilter mag_filter = TexFilter::Linear;
  TexWrap wrap_s = TexWrap::Repeat;
  TexWrap wrap_t = TexWrap::Repeat;
  TexWrap wrap_r = TexWrap::Repeat;
  float border_color[4] = {0, 0, 0, 0};
  float min_lod = -1000.f, max_lod = 1000.f;
  float lod_bias = 0.f;  // the texture's and the unit's, added to lambda before the clamp
  // GL 1.4 3.8.14 (ARB_shadow): a depth texture's texels are compared with r / q, each
  // before filtering, and give 0 or 1.
  bool compare = false;
  CompareFunc compare_func = CompareFunc::LessEqual;
};

struct TextureUnit {
  std::shared_ptr<const TextureImage> image;  // null: unit disabled or texture incomplete
  Sampler sampler;
  TexEnvMode env_mode = TexEnvMode::Modulate;
  float env_color[4] = {0, 0, 0, 0};
  CombineState combine;  // read when env_mode is Combine

  // Whether sampling reads the r coordinate, so that the draw interpolates it.
  bool reads_r() const {
    return image && (image->kind == TexKind::Volume || image->kind == TexKind::Cube || (image->depth && sampler.compare));
  }
};

}  // namespace pineda::raster
