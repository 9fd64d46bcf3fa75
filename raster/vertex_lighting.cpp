#include "raster/vertex_lighting.h"

#include <algorithm>
#include <cmath>

namespace pineda::raster {
namespace {

// glm::clamp(x, 0, 1) and std::clamp agree on every float (NaN and -0 included).
float clamp01(float x) { return x < 0.f ? 0.f : (1.f < x ? 1.f : x); }

void fill(Lanes& lanes, float value, int n) {
  for (int i = 0; i < n; ++i) lanes[i] = value;
}

void fill(LaneVec3& v, const glm::vec4& value, int n) {
  fill(v.x, value.x, n);
  fill(v.y, value.y, n);
  fill(v.z, value.z, n);
}

void fill_from_colors(LaneVec3& v, const float* const* colors, int n) {
  for (int i = 0; i < n; ++i) {
    v.x[i] = colors[i][0];
    v.y[i] = colors[i][1];
    v.z[i] = colors[i][2];
  }
}

}  // namespace

PreparedLights prepare_lights(const Lighting& l) {
  PreparedLights out;
  for (const Light& light : l.lights) {
    if (!light.enabled) continue;
    PreparedLight& p = out.lights[size_t(out.count++)];
    p.light = &light;
    p.local = light.position.w != 0.f;
    p.point = p.local ? glm::vec3(light.position) / light.position.w : glm::vec3(0.f);
    p.direction = p.local ? glm::vec3(0.f) : glm::normalize(glm::vec3(light.position));
    p.spot = light.spot_cutoff != 180.f;
    p.spot_direction = p.spot ? glm::normalize(light.spot_direction) : glm::vec3(0.f);
    p.cos_cutoff = p.spot ? std::cos(glm::radians(light.spot_cutoff)) : 0.f;
    p.fixed_half = !p.local && !l.local_viewer;
    p.half_unit = glm::vec3(0.f);
    p.half_nonzero = false;
    if (p.fixed_half) {
      const glm::vec3 half = p.direction + glm::vec3(0, 0, 1);
      const float half_len = glm::length(half);
      p.half_nonzero = half_len > 0.f;
      if (p.half_nonzero) p.half_unit = half / half_len;
    }
  }
  return out;
}

void lane_material(const Lighting& l, bool front, const float* const* colors, int n, LaneMaterial& out) {
  const Material& m = front ? l.front : l.back;
  const ColorMaterial& cm = l.color_material;
  const bool follows = cm.enabled && (front ? cm.front : cm.back);
  auto component = [&](LaneVec3& v, const glm::vec4& value, bool tracked) {
    if (follows && tracked) fill_from_colors(v, colors, n);
    else fill(v, value, n);
  };
  component(out.ambient, m.ambient, cm.ambient);
  component(out.diffuse, m.diffuse, cm.diffuse);
  component(out.specular, m.specular, cm.specular);
  component(out.emission, m.emission, cm.emission);
  if (follows && cm.diffuse) {
    for (int i = 0; i < n; ++i) out.alpha[i] = colors[i][3];
  } else {
    fill(out.alpha, m.diffuse.a, n);
  }
  out.shininess = m.shininess;
}

void light_lanes(const Lighting& l, const PreparedLights& lights, const LaneMaterial& m, const LaneVec3& eye,
                 const LaneVec3& normal, int n, LaneVec4& color, LaneVec3& specular) {
  const glm::vec4 model = l.model_ambient;
  for (int i = 0; i < n; ++i) {
    color.x[i] = m.emission.x[i] + m.ambient.x[i] * model.x;
    color.y[i] = m.emission.y[i] + m.ambient.y[i] * model.y;
    color.z[i] = m.emission.z[i] + m.ambient.z[i] * model.z;
    specular.x[i] = specular.y[i] = specular.z[i] = 0.f;
  }
  // Per light, lane by lane: the direction to the light (tx, ty, tz), the attenuation times the
  // spotlight effect (factor), n.l and the half vector.
  Lanes tx, ty, tz, factor, n_dot_l, hx, hy, hz, n_dot_h, spec;
  for (int k = 0; k < lights.count; ++k) {
    const PreparedLight& p = lights.lights[size_t(k)];
    const Light& light = *p.light;
    if (p.local) {
      const float c = light.constant_attenuation, lin = light.linear_attenuation, q = light.quadratic_attenuation;
      for (int i = 0; i < n; ++i) {
        const float x = p.point.x - eye.x[i], y = p.point.y - eye.y[i], z = p.point.z - eye.z[i];
        const float d = std::sqrt(x * x + y * y + z * z);
        const float denom = c + lin * d + q * d * d;
        // Selects rather than branches, so that the loop vectorizes: x / 1 is x.
        factor[i] = 1.f / (denom > 0.f ? denom : 1.f);
        const float divisor = d > 0.f ? d : 1.f;
        tx[i] = x / divisor;
        ty[i] = y / divisor;
        tz[i] = z / divisor;
      }
    } else {
      fill(tx, p.direction.x, n);
      fill(ty, p.direction.y, n);
      fill(tz, p.direction.z, n);
      fill(factor, 1.f, n);
    }
    if (p.spot) {
      const glm::vec3 s = p.spot_direction;
      Lanes& cos_angle = spec;  // free until the specular powers
      for (int i = 0; i < n; ++i) cos_angle[i] = -tx[i] * s.x + -ty[i] * s.y + -tz[i] * s.z;
      for (int i = 0; i < n; ++i) {
        const float effect =
            cos_angle[i] >= p.cos_cutoff ? std::pow(std::max(cos_angle[i], 0.f), light.spot_exponent) : 0.f;
        factor[i] = factor[i] * effect;
      }
    }
    for (int i = 0; i < n; ++i) n_dot_l[i] = normal.x[i] * tx[i] + normal.y[i] * ty[i] + normal.z[i] * tz[i];
    if (p.fixed_half) {
      fill(hx, p.half_unit.x, n);
      fill(hy, p.half_unit.y, n);
      fill(hz, p.half_unit.z, n);
    } else {
      for (int i = 0; i < n; ++i) {
        float ex = 0.f, ey = 0.f, ez = 1.f;
        if (l.local_viewer) {  // glm::normalize(-eye): -eye times 1 / its length
          const float inv = 1.f / std::sqrt(eye.x[i] * eye.x[i] + eye.y[i] * eye.y[i] + eye.z[i] * eye.z[i]);
          ex = -eye.x[i] * inv;
          ey = -eye.y[i] * inv;
          ez = -eye.z[i] * inv;
        }
        const float x = tx[i] + ex, y = ty[i] + ey, z = tz[i] + ez;
        const float len = std::sqrt(x * x + y * y + z * z);
        // A zero half vector gives no specular term: NaN here fails n.h > 0 below.
        const float unit = len > 0.f ? 1.f : NAN;
        hx[i] = x / len * unit;
        hy[i] = y / len * unit;
        hz[i] = z / len * unit;
      }
    }
    for (int i = 0; i < n; ++i) n_dot_h[i] = normal.x[i] * hx[i] + normal.y[i] * hy[i] + normal.z[i] * hz[i];
    if (p.fixed_half && !p.half_nonzero) fill(n_dot_h, 0.f, n);
    // The specular power, only where it is used.
    for (int i = 0; i < n; ++i) {
      spec[i] = 0.f;
      if (n_dot_l[i] > 0.f && n_dot_h[i] > 0.f) spec[i] = m.shininess == 0.f ? 1.f : std::pow(n_dot_h[i], m.shininess);
    }
    const glm::vec4 la = light.ambient, ld = light.diffuse, ls = light.specular;
    const bool separate = l.separate_specular;
    auto accumulate = [&](Lanes& out, Lanes& out_specular, const Lanes& ma, const Lanes& md, const Lanes& ms, float a,
                          float d, float s) {
      // Every value is computed and the lane's own picked (selects, no branches: the loops
      // vectorize). A light whose factor is 0 adds nothing (not even -0 + 0).
      Lanes contribution, spec_contribution;
      for (int i = 0; i < n; ++i) {
        const bool lit = n_dot_l[i] > 0.f;
        const float ambient = ma[i] * a;
        const float with_diffuse = ambient + n_dot_l[i] * md[i] * d;
        const float shine = spec[i] * ms[i] * s;
        contribution[i] = lit ? with_diffuse : ambient;
        spec_contribution[i] = lit & (n_dot_h[i] > 0.f) ? shine : 0.f;
      }
      if (separate) {
        for (int i = 0; i < n; ++i) {
          const bool adds = factor[i] != 0.f;
          const float sum = out[i] + factor[i] * contribution[i];
          const float spec_sum = out_specular[i] + factor[i] * spec_contribution[i];
          out[i] = adds ? sum : out[i];
          out_specular[i] = adds ? spec_sum : out_specular[i];
        }
      } else {
        for (int i = 0; i < n; ++i) {
          const float sum = out[i] + factor[i] * (contribution[i] + spec_contribution[i]);
          out[i] = factor[i] != 0.f ? sum : out[i];
        }
      }
    };
    accumulate(color.x, specular.x, m.ambient.x, m.diffuse.x, m.specular.x, la.x, ld.x, ls.x);
    accumulate(color.y, specular.y, m.ambient.y, m.diffuse.y, m.specular.y, la.y, ld.y, ls.y);
    accumulate(color.z, specular.z, m.ambient.z, m.diffuse.z, m.specular.z, la.z, ld.z, ls.z);
  }
  for (int i = 0; i < n; ++i) {
    color.x[i] = clamp01(color.x[i]);
    color.y[i] = clamp01(color.y[i]);
    color.z[i] = clamp01(color.z[i]);
    color.w[i] = clamp01(m.alpha[i]);
    specular.x[i] = clamp01(specular.x[i]);
    specular.y[i] = clamp01(specular.y[i]);
    specular.z[i] = clamp01(specular.z[i]);
  }
}

}  // namespace pineda::raster
