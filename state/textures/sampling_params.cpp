#include "state/textures/sampling_params.h"

#include <algorithm>

#include "state/enum_translate.h"

namespace pineda {

bool is_sampling_param(GLenum pname) {
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER: case GL_TEXTURE_MAG_FILTER:
    case GL_TEXTURE_WRAP_S: case GL_TEXTURE_WRAP_T: case GL_TEXTURE_WRAP_R:
    case GL_TEXTURE_BORDER_COLOR:
    case GL_TEXTURE_MIN_LOD: case GL_TEXTURE_MAX_LOD: case GL_TEXTURE_LOD_BIAS:
    case GL_TEXTURE_COMPARE_MODE: case GL_TEXTURE_COMPARE_FUNC:
    case GL_TEXTURE_SRGB_DECODE_EXT:
      return true;
    default:
      return false;
  }
}

GlError set_sampling_param(TexParams& p, GLenum pname, const GLfloat* v) {
  const GLenum e = enum_from_float(v[0]);
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR && e != GL_NEAREST_MIPMAP_NEAREST && e != GL_LINEAR_MIPMAP_NEAREST &&
          e != GL_NEAREST_MIPMAP_LINEAR && e != GL_LINEAR_MIPMAP_LINEAR)
        return {GL_INVALID_ENUM, "param is not a minifying filter"};
      p.min_filter = e;
      return GL_NO_ERROR;
    case GL_TEXTURE_MAG_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR) return {GL_INVALID_ENUM, "param is not GL_NEAREST or GL_LINEAR"};
      p.mag_filter = e;
      return GL_NO_ERROR;
    case GL_TEXTURE_WRAP_S:
    case GL_TEXTURE_WRAP_T:
    case GL_TEXTURE_WRAP_R:
      if (e != GL_REPEAT && e != GL_CLAMP && e != GL_CLAMP_TO_EDGE && e != GL_CLAMP_TO_BORDER && e != GL_MIRRORED_REPEAT)
        return {GL_INVALID_ENUM, "param is not a wrap mode"};
      (pname == GL_TEXTURE_WRAP_S ? p.wrap_s : pname == GL_TEXTURE_WRAP_T ? p.wrap_t : p.wrap_r) = e;
      return GL_NO_ERROR;
    case GL_TEXTURE_BORDER_COLOR:
      for (int i = 0; i < 4; ++i) p.border_color[i] = std::clamp(v[i], 0.f, 1.f);
      return GL_NO_ERROR;
    case GL_TEXTURE_MIN_LOD: p.min_lod = v[0]; return GL_NO_ERROR;
    case GL_TEXTURE_MAX_LOD: p.max_lod = v[0]; return GL_NO_ERROR;
    case GL_TEXTURE_LOD_BIAS: p.lod_bias = v[0]; return GL_NO_ERROR;
    case GL_TEXTURE_COMPARE_MODE:
      if (e != GL_NONE && e != GL_COMPARE_R_TO_TEXTURE)
        return {GL_INVALID_ENUM, "param is not GL_NONE or GL_COMPARE_R_TO_TEXTURE"};
      p.compare_mode = e;
      return GL_NO_ERROR;
    case GL_TEXTURE_COMPARE_FUNC: {
      raster::CompareFunc f;
      if (!to_compare_func(e, f)) return {GL_INVALID_ENUM, "param is not a comparison function"};
      p.compare_func = e;
      return GL_NO_ERROR;
    }
    case GL_TEXTURE_SRGB_DECODE_EXT:
      if (e != GL_DECODE_EXT && e != GL_SKIP_DECODE_EXT)
        return {GL_INVALID_ENUM, "param is not GL_DECODE_EXT or GL_SKIP_DECODE_EXT"};
      p.srgb_decode = e;
      return GL_NO_ERROR;
    default:
      return {GL_INVALID_ENUM, "pname is not a sampling parameter"};
  }
}

bool get_sampling_param(const TexParams& p, GLenum pname, float out[4], int& count, bool& colour) {
  count = 1;
  colour = false;
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER: out[0] = float(p.min_filter); return true;
    case GL_TEXTURE_MAG_FILTER: out[0] = float(p.mag_filter); return true;
    case GL_TEXTURE_WRAP_S: out[0] = float(p.wrap_s); return true;
    case GL_TEXTURE_WRAP_T: out[0] = float(p.wrap_t); return true;
    case GL_TEXTURE_WRAP_R: out[0] = float(p.wrap_r); return true;
    case GL_TEXTURE_MIN_LOD: out[0] = p.min_lod; return true;
    case GL_TEXTURE_MAX_LOD: out[0] = p.max_lod; return true;
    case GL_TEXTURE_LOD_BIAS: out[0] = p.lod_bias; return true;
    case GL_TEXTURE_COMPARE_MODE: out[0] = float(p.compare_mode); return true;
    case GL_TEXTURE_COMPARE_FUNC: out[0] = float(p.compare_func); return true;
    case GL_TEXTURE_SRGB_DECODE_EXT: out[0] = float(p.srgb_decode); return true;
    case GL_TEXTURE_BORDER_COLOR:
      std::copy(p.border_color, p.border_color + 4, out);
      count = 4;
      colour = true;
      return true;
    default: return false;
  }
}

TexParams with_sampling_params(const TexParams& texture, const TexParams& sampler) {
  TexParams out = texture;
  out.min_filter = sampler.min_filter;
  out.mag_filter = sampler.mag_filter;
  out.wrap_s = sampler.wrap_s;
  out.wrap_t = sampler.wrap_t;
  out.wrap_r = sampler.wrap_r;
  std::copy(sampler.border_color, sampler.border_color + 4, out.border_color);
  out.min_lod = sampler.min_lod;
  out.max_lod = sampler.max_lod;
  out.lod_bias = sampler.lod_bias;
  out.compare_mode = sampler.compare_mode;
  out.compare_func = sampler.compare_func;
  out.srgb_decode = sampler.srgb_decode;
  return out;
}

}  // namespace pineda
