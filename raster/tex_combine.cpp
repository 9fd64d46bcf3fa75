#include "raster/tex_combine.h"

#include <algorithm>

namespace pineda::raster {
namespace {

struct Inputs {
  int index;
  const float* env_color;
  const PixelTexels& texels;
  const float* primary;
  const float* previous;
};

// The RGBA a source names, or null for a unit that is not enabled.
const float* source_rgba(CombineSource source, const Inputs& in) {
  switch (source) {
    case CombineSource::Texture: return in.texels.unit[in.index];
    case CombineSource::Constant: return in.env_color;
    case CombineSource::PrimaryColor: return in.primary;
    case CombineSource::Previous: return in.previous;
    default: break;
  }
  const int unit = int(source) - int(CombineSource::Texture0);
  return unit >= 0 && unit < kMaxTextureUnits ? in.texels.unit[unit] : nullptr;
}

float operand(CombineOperand op, const float* rgba, int channel) {
  switch (op) {
    case CombineOperand::SrcColor: return rgba[channel];
    case CombineOperand::OneMinusSrcColor: return 1.f - rgba[channel];
    case CombineOperand::SrcAlpha: return rgba[3];
    case CombineOperand::OneMinusSrcAlpha: return 1.f - rgba[3];
  }
  return rgba[channel];
}

float combine(CombineFunc f, const float a[3]) {
  switch (f) {
    case CombineFunc::Replace: return a[0];
    case CombineFunc::Modulate: return a[0] * a[1];
    case CombineFunc::Add: return a[0] + a[1];
    case CombineFunc::AddSigned: return a[0] + a[1] - 0.5f;
    case CombineFunc::Interpolate: return a[0] * a[2] + a[1] * (1.f - a[2]);
    case CombineFunc::Subtract: return a[0] - a[1];
    case CombineFunc::Dot3Rgb:
    case CombineFunc::Dot3Rgba: break;  // across channels: see below
  }
  return a[0];
}

float scaled(float v, float scale) { return std::clamp(v * scale, 0.f, 1.f); }

}  // namespace

bool apply_tex_combine(const CombineState& c, int index, const float env_color[4], const PixelTexels& texels,
                       const float primary[4], float color[4]) {
  const float previous[4] = {color[0], color[1], color[2], color[3]};
  const Inputs in{index, env_color, texels, primary, previous};
  const float* rgb_src[3];
  const float* alpha_src[3];
  for (int i = 0; i < 3; ++i) {
    rgb_src[i] = source_rgba(c.rgb_source[i], in);
    alpha_src[i] = source_rgba(c.alpha_source[i], in);
    if (!rgb_src[i] || !alpha_src[i]) return false;
  }
  float out[4];
  if (c.rgb_func == CombineFunc::Dot3Rgb || c.rgb_func == CombineFunc::Dot3Rgba) {
    float dot = 0.f;
    for (int ch = 0; ch < 3; ++ch)
      dot += (operand(c.rgb_operand[0], rgb_src[0], ch) - 0.5f) * (operand(c.rgb_operand[1], rgb_src[1], ch) - 0.5f);
    out[0] = out[1] = out[2] = scaled(4.f * dot, c.rgb_scale);
  } else {
    for (int ch = 0; ch < 3; ++ch) {
      float args[3];
      for (int i = 0; i < 3; ++i) args[i] = operand(c.rgb_operand[i], rgb_src[i], ch);
      out[ch] = scaled(combine(c.rgb_func, args), c.rgb_scale);
    }
  }
  if (c.rgb_func == CombineFunc::Dot3Rgba) {
    out[3] = out[0];  // COMBINE_ALPHA is ignored
  } else {
    float args[3];
    for (int i = 0; i < 3; ++i) args[i] = operand(c.alpha_operand[i], alpha_src[i], 3);
    out[3] = scaled(combine(c.alpha_func, args), c.alpha_scale);
  }
  std::copy(out, out + 4, color);
  return true;
}

}  // namespace pineda::raster
