// Selection and feedback (glRenderMode): the primitives of a draw clipped to the view volume
// and mapped to window coordinates, handed to a sink instead of being rasterized.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "raster/clip.h"
#include "raster/draw_state.h"
#include "raster/primitive.h"

namespace pineda::raster {

struct FeedbackVertex {
  double window[4];  // x, y, z in [0, 1], clip w
  float color[4];
  float texcoord[4];  // unit 0
};

class FeedbackSink {
 public:
  virtual ~FeedbackSink() = default;
  virtual void point(const FeedbackVertex& v) = 0;
  // `reset`: the first segment of a strip or an independent line (GL_LINE_RESET_TOKEN).
  virtual void line(const FeedbackVertex& a, const FeedbackVertex& b, bool reset) = 0;
  virtual void polygon(std::span<const FeedbackVertex> v) = 0;
};

// Assembles, clips (view volume), culls and maps the primitives of one draw for `sink`.
// Polygon modes LINE and POINT give the polygon's boundary edges or vertices.
void feedback_primitives(const DrawState& state, Primitive mode, std::span<const ClipVertex> vertices,
                         std::span<const uint32_t> indices, FeedbackSink& sink);

}  // namespace pineda::raster
