#include "raster/tex_env.h"

#include <algorithm>

#include "raster/tex_combine.h"

namespace pineda::raster {
namespace {

struct TexelParts {
  bool has_color, has_alpha;
  float c[3], a;
};

TexelParts split(TexBaseFormat format, const float t[4]) {
  switch (format) {
    case TexBaseFormat::Alpha: return {false, true, {0, 0, 0}, t[3]};
    case TexBaseFormat::Luminance: return {true, false, {t[0], t[0], t[0]}, 1.f};
    case TexBaseFormat::LuminanceAlpha: return {true, true, {t[0], t[0], t[0]}, t[3]};
    case TexBaseFormat::Intensity: return {true, true, {t[0], t[0], t[0]}, t[0]};
    case TexBaseFormat::RGB: return {true, false, {t[0], t[1], t[2]}, 1.f};
    case TexBaseFormat::RGBA: break;
  }
  return {true, true, {t[0], t[1], t[2]}, t[3]};
}

}  // namespace

void apply_tex_env(TexEnvMode mode, TexBaseFormat format, const float env[4], const float texel[4],
                   float color[4]) {
  const TexelParts t = split(format, texel);
  const bool intensity = format == TexBaseFormat::Intensity;
  switch (mode) {
    case TexEnvMode::Replace:
      if (t.has_color)
        for (int i = 0; i < 3; ++i) color[i] = t.c[i];
      if (t.has_alpha) color[3] = t.a;
      break;
    case TexEnvMode::Modulate:
      if (t.has_color)
        for (int i = 0; i < 3; ++i) color[i] *= t.c[i];
      if (t.has_alpha) color[3] *= t.a;
      break;
    case TexEnvMode::Decal:
      // Defined for RGB and RGBA only; the other formats leave the fragment unchanged.
      if (format == TexBaseFormat::RGB) {
        for (int i = 0; i < 3; ++i) color[i] = t.c[i];
      } else if (format == TexBaseFormat::RGBA) {
        for (int i = 0; i < 3; ++i) color[i] = color[i] * (1.f - t.a) + t.c[i] * t.a;
      }
      break;
    case TexEnvMode::Blend:
      if (t.has_color)
        for (int i = 0; i < 3; ++i) color[i] = color[i] * (1.f - t.c[i]) + env[i] * t.c[i];
      if (intensity) color[3] = color[3] * (1.f - t.a) + env[3] * t.a;
      else if (t.has_alpha) color[3] *= t.a;
      break;
    case TexEnvMode::Add:
      if (t.has_color)
        for (int i = 0; i < 3; ++i) color[i] = std::min(color[i] + t.c[i], 1.f);
      if (intensity) color[3] = std::min(color[3] + t.a, 1.f);
      else if (t.has_alpha) color[3] *= t.a;
      break;
    case TexEnvMode::Combine:  // apply_tex_combine
      break;
  }
}

void apply_unit_env(const TextureUnit& unit, int index, const PixelTexels& texels, const float primary[4],
                    float color[4]) {
  if (unit.env_mode == TexEnvMode::Combine) {
    apply_tex_combine(unit.combine, index, unit.env_color, texels, primary, color);
    return;
  }
  apply_tex_env(unit.env_mode, unit.image->texenv_format(), unit.env_color, texels.unit[index], color);
}

}  // namespace pineda::raster
