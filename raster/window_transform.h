// A draw's viewport transform: clip coordinates to snapped window positions, and the clip
// volume inside which a vertex's window position is used as it is (outside, clipping makes
// new vertices). GeometryStage transforms with it, vertex by vertex or a large programmable
// draw's vertices ahead of assembly (PreparedWindow).
#pragma once
#include <cstddef>
#include <cstdint>

#include "raster/clip.h"
#include "raster/draw_state.h"
#include "raster/setup.h"
#include "raster/simd_path.h"
#include "raster/vertex.h"

namespace pineda::raster {

// A vertex taken to the window ahead of assembly: usable when it lies inside the clip volume
// (the window position GeometryStage would give it then).
struct PreparedWindow {
  WinPosition position;
  bool usable = false;
};

// What the transform computes with (window_transform.cpp and its lanes copies).
struct WindowParams {
  double x = 0, y = 0, half_w = 0, half_h = 0, depth_near = 0, depth_far = 1;
  double depth_max = 0;
  ClipVolume volume;
};

class WindowTransform {
 public:
  WindowTransform() = default;
  // `clip_planes`: DrawState::clip_planes; `depth_max`: DrawRecord::depth_max.
  WindowTransform(const Viewport& viewport, uint32_t clip_planes, double depth_max);

  // The clip volume: the guard band and the enabled user planes (all its attributes).
  const ClipVolume& volume() const { return p_.volume; }
  void position(const ClipVert& v, WinPosition& w) const;
  // Vertex v, whose varyings are at `varyings`, into `out`.
  void prepare(const ClipVertex& v, const float* varyings, PreparedWindow& out) const;
  // prepare() for v[0, count), vertex i's varyings at varyings + i * varying_count, into
  // out[0, count): several vertices at a time in vector lanes where `path` allows (the same
  // operations, so the same windows; window_lanes.cpp). Where prepare() leaves a vertex's
  // position as it was (not usable), this may write any position.
  void prepare_many(const ClipVertex* v, const float* varyings, size_t varying_count, size_t count, PreparedWindow* out,
                    SimdPath path) const;

 private:
  WindowParams p_;
};

// Every coordinate of the clip position is finite.
bool finite_position(const ClipVertex& v);
// The clip position and user clip distances of v into c (its attributes untouched).
void clip_position(const ClipVertex& v, ClipVert& c);
// A window coordinate in sub-pixels, rounded half away from zero (NaN: 0).
int64_t snap(double window);
// False when w = 0 came out of clipping's cancellation: the primitive has no window position.
bool has_window_position(const WinPosition& v);

}  // namespace pineda::raster
