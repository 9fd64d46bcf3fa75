#include "raster/window_transform.h"

#include <algorithm>
#include <cmath>

#include "raster/raster_limits.h"

namespace pineda::raster {

WindowTransform::WindowTransform(const Viewport& vp, uint32_t clip_planes, double depth_max) {
  p_.depth_max = depth_max;
  p_.half_w = vp.width * 0.5;
  p_.half_h = vp.height * 0.5;
  p_.x = vp.x;
  p_.y = vp.y;
  p_.depth_near = std::clamp(vp.near_z, 0.0, 1.0);
  p_.depth_far = std::clamp(vp.far_z, 0.0, 1.0);
  // The guard band in window pixels, as NDC multiples of w.
  ClipVolume& volume = p_.volume;
  volume.x_min = (-kGuardBand - p_.x) / p_.half_w - 1.0;
  volume.x_max = (kGuardBand - p_.x) / p_.half_w - 1.0;
  volume.y_min = (-kGuardBand - p_.y) / p_.half_h - 1.0;
  volume.y_max = (kGuardBand - p_.y) / p_.half_h - 1.0;
  volume.user_planes = clip_planes & ((1u << kMaxClipPlanes) - 1);
}

// window_lanes_body.inc does the same operations on vectors of vertices: change both together.
void WindowTransform::position(const ClipVert& v, WinPosition& w) const {
  w.inv_w = 1.0 / v.pos[3];
  w.fx = std::clamp<double>((v.pos[0] * w.inv_w + 1.0) * p_.half_w + p_.x, -4.0 * kGuardBand, 4.0 * kGuardBand);
  w.fy = std::clamp<double>((v.pos[1] * w.inv_w + 1.0) * p_.half_h + p_.y, -4.0 * kGuardBand, 4.0 * kGuardBand);
  w.x = snap(w.fx);
  w.y = snap(w.fy);
  double z = p_.depth_near + (p_.depth_far - p_.depth_near) * (v.pos[2] * w.inv_w + 1.0) * 0.5;
  z = z > 0.0 ? (z < 1.0 ? z : 1.0) : 0.0;
  w.z = z * p_.depth_max;
}

void WindowTransform::prepare(const ClipVertex& v, const float* varyings, PreparedWindow& out) const {
  out.usable = false;
  if (!finite_position(v)) return;
  ClipVert clip;  // position and clip distances only
  clip_position(v, clip);
  if (clip_outcode(clip, p_.volume) != 0) return;
  position(clip, out.position);
  out.position.varyings = varyings;
  out.usable = has_window_position(out.position);
}

bool finite_position(const ClipVertex& v) {
  return std::isfinite(v.clip[0]) && std::isfinite(v.clip[1]) && std::isfinite(v.clip[2]) && std::isfinite(v.clip[3]);
}

void clip_position(const ClipVertex& v, ClipVert& c) {
  for (int i = 0; i < 4; ++i) c.pos[i] = v.clip[i];
  for (int i = 0; i < kMaxClipPlanes; ++i) c.user[i] = v.clip_distance[i];
}

int64_t snap(double window) {
  // Beyond the guard band only by clipping's rounding; the clamp keeps the conversion defined.
  if (std::isnan(window)) return 0;
  const double v = std::clamp(window, -4.0 * kGuardBand, 4.0 * kGuardBand) * kSubpixelOne;
  // std::llround (halves away from zero) without its library call: |v| < 2^26, so the
  // truncation and the remainder are exact.
  const int64_t r = static_cast<int64_t>(v);
  const double rest = v - static_cast<double>(r);
  // Without branches: which way a position rounds is as random as the positions are.
  return r + static_cast<int64_t>(rest >= 0.5) - static_cast<int64_t>(rest <= -0.5);
}

// Clipping keeps w >= 1e-30, but cancellation in an intersection can still produce w = 0;
// such a vertex has no window position and drops its primitive.
bool has_window_position(const WinPosition& v) { return std::isfinite(v.inv_w) && std::isfinite(v.fx) && std::isfinite(v.fy); }

}  // namespace pineda::raster
