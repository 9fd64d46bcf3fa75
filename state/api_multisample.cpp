// glSampleCoverage and the rest of the multisample state (state/multisample.h).
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/attrib_stack.h"
#include "state/context.h"
#include "state/multisample.h"

namespace pineda {
namespace {

// The draw framebuffer's sample count: 1 when single-sampled (and without one).
int draw_samples(Context& ctx) {
  const Drawable* d = ctx.draw_drawable();
  return d ? d->framebuffer.samples : 1;
}

}  // namespace

bool* multisample_capability(Context& ctx, GLenum cap) {
  MultisampleState& m = ctx.multisample;
  switch (cap) {
    case GL_MULTISAMPLE: return &m.multisample;
    case GL_SAMPLE_ALPHA_TO_COVERAGE: return &m.alpha_to_coverage;
    case GL_SAMPLE_ALPHA_TO_ONE: return &m.alpha_to_one;
    case GL_SAMPLE_COVERAGE: return &m.sample_coverage;
    default: return nullptr;
  }
}

bool query_multisample(Context& ctx, unsigned pname, GetValues& out) {
  const MultisampleState& m = ctx.multisample;
  switch (pname) {
    case GL_SAMPLE_COVERAGE_VALUE: out = get_floats({m.coverage_value}); return true;
    case GL_SAMPLE_COVERAGE_INVERT: out = get_bools({double(m.coverage_invert)}); return true;
    case GL_SAMPLE_BUFFERS: out = get_ints({draw_samples(ctx) > 1 ? 1.0 : 0.0}); return true;
    case GL_SAMPLES: out = get_ints({draw_samples(ctx) > 1 ? double(draw_samples(ctx)) : 0.0}); return true;
    default: return false;
  }
}

void restore_multisample(Context& ctx, const AttribFrame& f) {
  MultisampleState& m = ctx.multisample;
  if (f.mask & GL_MULTISAMPLE_BIT) {
    m = f.multisample;
  } else if (f.mask & GL_ENABLE_BIT) {
    m.multisample = f.multisample.multisample;
    m.alpha_to_coverage = f.multisample.alpha_to_coverage;
    m.alpha_to_one = f.multisample.alpha_to_one;
    m.sample_coverage = f.multisample.sample_coverage;
  }
}

}  // namespace pineda

namespace pineda::gl {

void SampleCoverage(Context& ctx, GLfloat value, GLboolean invert) {
  ctx.multisample.coverage_value = value > 0.f ? std::min(value, 1.f) : 0.f;  // NaN: 0
  ctx.multisample.coverage_invert = invert != GL_FALSE;
}
void SampleCoverageARB(Context& ctx, GLfloat value, GLboolean invert) { SampleCoverage(ctx, value, invert); }

}  // namespace pineda::gl
