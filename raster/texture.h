// Texture images as the sampler sees them: immutable once handed to a draw, so a scene
// that is still queued keeps reading the image it was recorded with.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

namespace pineda::raster {

constexpr int kMaxTextureUnits = 4;

// Which components a texture really has; decides how TexEnv combines it.
enum class TexBaseFormat : uint8_t { Alpha, Luminance, LuminanceAlpha, Intensity, RGB, RGBA };

struct TextureLevel {
  int width = 0;
  int height = 0;
  std::vector<uint32_t> texels;  // RGBA8, R in the lowest byte; row 0 first (t = 0)
};

struct TextureImage {
  TexBaseFormat base_format = TexBaseFormat::RGBA;
  std::vector<TextureLevel> levels;  // level 0 first; a complete chain when mipmapped
};

enum class TexFilter : uint8_t {
  Nearest, Linear,
  NearestMipmapNearest, LinearMipmapNearest, NearestMipmapLinear, LinearMipmapLinear
};
enum class TexWrap : uint8_t { Repeat, Clamp, ClampToEdge, ClampToBorder, MirroredRepeat };
enum class TexEnvMode : uint8_t { Modulate, Replace, Decal, Blend, Add };

struct Sampler {
  TexFilter min_filter = TexFilter::NearestMipmapLinear;
  TexFilter mag_filter = TexFilter::Linear;
  TexWrap wrap_s = TexWrap::Repeat;
  TexWrap wrap_t = TexWrap::Repeat;
  float border_color[4] = {0, 0, 0, 0};
  float min_lod = -1000.f, max_lod = 1000.f;
};

struct TextureUnit {
  std::shared_ptr<const TextureImage> image;  // null: unit disabled or texture incomplete
  Sampler sampler;
  TexEnvMode env_mode = TexEnvMode::Modulate;
  float env_color[4] = {0, 0, 0, 0};
};

}  // namespace pineda::raster
