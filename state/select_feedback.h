// Selection and feedback state (glRenderMode, GL 1.1 5.2-5.3), and the draw path's detour
// for the SELECT and FEEDBACK modes.
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "raster/draw_state.h"
#include "raster/vertex.h"

namespace pineda {

class Context;

constexpr size_t kMaxNameStackDepth = 64;

struct RenderModeState {
  GLenum mode = GL_RENDER;

  // GL_SELECT
  GLuint* select_buffer = nullptr;
  GLsizei select_size = 0;
  size_t select_count = 0;  // words of hit records so far (may pass select_size: overflow)
  GLint hits = 0;
  bool hit = false;  // a primitive was hit since the last record was written
  double hit_min_z = 1.0, hit_max_z = 0.0;
  std::vector<GLuint> names;

  // GL_FEEDBACK
  GLfloat* feedback_buffer = nullptr;
  GLsizei feedback_size = 0;
  GLenum feedback_type = GL_2D;
  size_t feedback_count = 0;  // values so far (may pass feedback_size: overflow)

  // Appends to the feedback buffer, counting what does not fit.
  void feedback_value(double v) {
    if (feedback_count < size_t(feedback_size)) feedback_buffer[feedback_count] = static_cast<GLfloat>(v);
    ++feedback_count;
  }
  void select_value(GLuint v) {
    if (select_count < size_t(select_size)) select_buffer[select_count] = v;
    ++select_count;
  }
  // Counts a hit at window depth z for the pending hit record.
  void hit_at(double z) {
    hit = true;
    hit_min_z = z < hit_min_z ? z : hit_min_z;
    hit_max_z = z > hit_max_z ? z : hit_max_z;
  }
  // Writes the pending hit record (GL 1.1 5.2), if any.
  void write_hit_record();
};

// glBitmap, glDrawPixels and glCopyPixels outside RENDER mode (GL 1.1 5.3): in FEEDBACK mode
// `token` and the current raster position as its vertex, when the position is valid; in SELECT
// mode nothing (GL 1.1 appendix B, corollary 6). False in RENDER mode: the caller draws.
bool pixel_rect_feedback(Context& ctx, GLenum token);

// A valid raster position is a selection hit at its depth (GL 1.1 5.2).
void raster_pos_select_hit(Context& ctx);

// Instead of rasterizing: hits (SELECT) or feedback tokens (FEEDBACK) for the primitives.
void select_feedback_draw(Context& ctx, const raster::DrawState& state, raster::Primitive mode,
                          std::span<const raster::ClipVertex> vertices, std::span<const uint32_t> indices);

}  // namespace pineda
