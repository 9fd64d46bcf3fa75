#include "raster/clip.h"

namespace pineda::raster {
namespace {

constexpr int kFixedPlanes = 7;
constexpr int kPlaneCount = kFixedPlanes + kMaxClipPlanes;

double plane_distance(const ClipVert& v, const ClipVolume& vol, int plane) {
  const double x = v.pos[0], y = v.pos[1], z = v.pos[2], w = v.pos[3];
  switch (plane) {
    case 0: return z + w;               // near
    case 1: return w - z;               // far
    case 2: return w - kMinW;           // in front of the eye
    case 3: return x - vol.x_min * w;   // guard band, left
    case 4: return vol.x_max * w - x;   // right
    case 5: return y - vol.y_min * w;   // bottom
    case 6: return vol.y_max * w - y;   // top
    default: return v.user[plane - kFixedPlanes];
  }
}

// Puts the coordinate that plane `plane` constrains exactly onto the plane. Interpolating it
// instead loses everything at huge coordinates (1e30 - 1e30 + ...), leaving the new vertex
// far from the plane and two triangles sharing an edge with different cut vertices.
void snap_onto_plane(ClipVert& v, const ClipVolume& vol, int plane) {
  double* p = v.pos;
  switch (plane) {
    case 0: p[2] = -p[3]; break;
    case 1: p[2] = p[3]; break;
    case 2: p[3] = kMinW; break;
    case 3: p[0] = vol.x_min * p[3]; break;
    case 4: p[0] = vol.x_max * p[3]; break;
    case 5: p[1] = vol.y_min * p[3]; break;
    case 6: p[1] = vol.y_max * p[3]; break;
    default: v.user[plane - kFixedPlanes] = 0.0; break;
  }
}

// The point where the segment from `in` (inside) to `out` (outside) meets the plane.
ClipVert intersect(const ClipVert& in, const ClipVert& out, double d_in, double d_out, const ClipVolume& vol,
                   int plane) {
  const double t = d_in / (d_in - d_out);
  ClipVert r;
  for (int i = 0; i < 4; ++i) r.pos[i] = in.pos[i] + t * (out.pos[i] - in.pos[i]);
  for (int i = 0; i < kMaxClipPlanes; ++i) r.user[i] = in.user[i] + t * (out.user[i] - in.user[i]);
  snap_onto_plane(r, vol, plane);
  const float tf = static_cast<float>(t);
  for (int i = 0; i < vol.attrs; ++i) r.attr[i] = in.attr[i] + tf * (out.attr[i] - in.attr[i]);
  return r;
}

}  // namespace

uint32_t clip_outcode(const ClipVert& v, const ClipVolume& vol) {
  uint32_t code = 0;
  for (int p = 0; p < kFixedPlanes; ++p)
    if (!(plane_distance(v, vol, p) >= 0.0)) code |= 1u << p;
  for (uint32_t planes = vol.user_planes; planes; planes &= planes - 1) {
    const int i = __builtin_ctz(planes);
    if (!(v.user[i] >= 0.0)) code |= 1u << (kFixedPlanes + i);
  }
  return code;
}

void clip_polygon(const std::vector<ClipVert>& in, const ClipVolume& vol, std::vector<ClipVert>& out,
                  std::vector<ClipVert>& scratch) {
  out = in;
  uint32_t any = 0, all = ~0u;
  for (const ClipVert& v : in) {
    const uint32_t c = clip_outcode(v, vol);
    any |= c;
    all &= c;
  }
  if (all) {
    out.clear();
    return;
  }
  for (int p = 0; p < kPlaneCount && !out.empty(); ++p) {
    if (!(any & (1u << p))) continue;
    scratch.clear();
    const size_t n = out.size();
    for (size_t i = 0; i < n; ++i) {
      const ClipVert& a = out[i];
      const ClipVert& b = out[(i + 1) % n];
      const double da = plane_distance(a, vol, p), db = plane_distance(b, vol, p);
      const bool a_in = da >= 0.0, b_in = db >= 0.0;
      if (a_in) scratch.push_back(a);
      if (a_in && !b_in) scratch.push_back(intersect(a, b, da, db, vol, p));
      if (!a_in && b_in) scratch.push_back(intersect(b, a, db, da, vol, p));
    }
    out.swap(scratch);
    if (out.size() < 3) out.clear();
  }
}

bool clip_line(ClipVert& a, ClipVert& b, const ClipVolume& vol) {
  const uint32_t ca = clip_outcode(a, vol), cb = clip_outcode(b, vol);
  if (ca & cb) return false;
  const uint32_t any = ca | cb;
  for (int p = 0; p < kPlaneCount; ++p) {
    if (!(any & (1u << p))) continue;
    const double da = plane_distance(a, vol, p), db = plane_distance(b, vol, p);
    const bool a_in = da >= 0.0, b_in = db >= 0.0;
    if (!a_in && !b_in) return false;
    if (a_in && !b_in) b = intersect(a, b, da, db, vol, p);
    else if (!a_in && b_in) a = intersect(b, a, db, da, vol, p);
  }
  return true;
}

}  // namespace pineda::raster
