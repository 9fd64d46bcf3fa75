// Which colour buffers of the drawables glDrawBuffer and glReadBuffer select.
#include <cstring>
#include <vector>

#include "raster/multisample.h"
#include "state/context.h"

namespace pineda {
namespace {

enum class Target { None = 0, Front = 1, Back = 2, Both = 3 };  // bits: front, back

Target draw_target(GLenum buffer, const Drawable& d) {
  // A framebuffer object's view holds the selected attachment as its only colour buffer.
  if (buffer >= GL_COLOR_ATTACHMENT0 && buffer <= GL_COLOR_ATTACHMENT15) return Target::Front;
  const bool separate_front = d.double_buffered && d.front.base;
  switch (buffer) {
    case GL_FRONT: case GL_FRONT_LEFT: return Target::Front;
    case GL_BACK: case GL_BACK_LEFT: return d.double_buffered ? Target::Back : Target::None;
    case GL_LEFT: case GL_FRONT_AND_BACK: return separate_front ? Target::Both : Target::Front;
    default: return Target::None;
  }
}

// The union over every draw buffer (glDrawBuffers): fixed-function colour goes to each.
Target draw_targets(GLenum buffer0, const ExtraDrawBuffers& more, const Drawable& d) {
  int bits = static_cast<int>(draw_target(buffer0, d));
  for (GLenum b : more) bits |= static_cast<int>(draw_target(b, d));
  return static_cast<Target>(bits);
}

// The first draw buffer index whose buffer includes `pass` (Front or Back).
int first_output_for(Target pass, GLenum buffer0, const ExtraDrawBuffers& more, const Drawable& d) {
  for (int i = 0; i < kMaxDrawBuffers; ++i) {
    const GLenum b = i == 0 ? buffer0 : more[size_t(i - 1)];
    if (static_cast<int>(draw_target(b, d)) & static_cast<int>(pass)) return i;
  }
  return 0;
}

bool reads_front(GLenum buffer) {
  return buffer == GL_FRONT || buffer == GL_FRONT_LEFT || buffer == GL_LEFT;
}

// A copy of the depth and stencil buffers, to render a second colour buffer from the same
// depth and stencil values as the first.
struct DepthStencilCopy {
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;

  explicit DepthStencilCopy(const raster::Framebuffer& fb) {
    for (int y = 0; y < fb.height; ++y) {
      if (fb.depth.bits) {
        const uint32_t* row = fb.depth.base + fb.depth.stride * y;
        depth.insert(depth.end(), row, row + fb.width);
      }
      if (fb.stencil.bits) {
        const uint8_t* row = fb.stencil.base + fb.stencil.stride * y;
        stencil.insert(stencil.end(), row, row + fb.width);
      }
    }
  }

  void restore(const raster::Framebuffer& fb) const {
    const size_t w = static_cast<size_t>(fb.width);
    for (int y = 0; y < fb.height; ++y) {
      if (fb.depth.bits) std::memcpy(fb.depth.base + fb.depth.stride * y, &depth[w * y], w * 4);
      if (fb.stencil.bits) std::memcpy(fb.stencil.base + fb.stencil.stride * y, &stencil[w * y], w);
    }
  }
};

bool same_color(const raster::ColorBuffer& a, const raster::ColorBuffer& b) {
  const raster::ColorReduction &ra = a.reduction, &rb = b.reduction;
  return a.base == b.base && a.stride == b.stride && a.format == b.format && ra.active == rb.active &&
         std::memcmp(ra.bits, rb.bits, 4) == 0 && std::memcmp(ra.source, rb.source, 4) == 0;
}

bool same_buffers(const raster::Framebuffer& a, const raster::Framebuffer& b) {
  if (a.color_targets != b.color_targets || a.color_index != b.color_index) return false;
  for (int i = 0; i < a.color_targets; ++i)
    if (!same_color(a.target_color(i), b.target_color(i))) return false;
  return a.width == b.width && a.height == b.height && a.depth.base == b.depth.base &&
         a.depth.stride == b.depth.stride && a.depth.bits == b.depth.bits && a.stencil.base == b.stencil.base &&
         a.stencil.stride == b.stencil.stride && a.stencil.bits == b.stencil.bits && a.cleared_tiles == b.cleared_tiles;
}

}  // namespace

void Context::set_framebuffer_views(Drawable* draw, Drawable* read) {
  fbo_draw_ = draw;
  fbo_read_ = read;
  bind_framebuffer(false);
}

void Context::bind_framebuffer(bool always) {
  Drawable* d = draw_drawable();
  raster::Framebuffer fb;
  if (d) {
    fb = d->framebuffer;
    switch (draw_targets(draw_buffer, extra_draw_buffers, *d)) {
      case Target::None: fb.color = {}; break;
      case Target::Front: fb.color = d->front_color(); break;
      case Target::Back: case Target::Both: break;
    }
    if (fb.color.base != d->framebuffer.color.base) fb.cleared_tiles = nullptr;  // a front buffer
  }
  // Binding the same buffers again would only flush the queued rendering.
  if (always || !same_buffers(fb, renderer_->framebuffer())) {
    renderer_->set_framebuffer(fb);
    renderer_storage_ = d ? d->kept_storage : decltype(renderer_storage_){};
  }
}

void Context::use_color_buffer(const raster::ColorBuffer& color, int draw_buffer) {
  const raster::Framebuffer& bound = renderer_->framebuffer();
  if (bound.color.base == color.base && bound.color.stride == color.stride && bound.color_index == draw_buffer) return;
  raster::Framebuffer fb = draw_drawable()->framebuffer;
  if (color.base != fb.color.base) fb.cleared_tiles = nullptr;  // a front buffer
  fb.color = color;
  fb.color_index = draw_buffer;
  renderer_->set_framebuffer(fb);
  renderer_storage_ = draw_drawable()->kept_storage;
}

bool Context::renders_draw_buffers_in_one_pass() const {
  const Drawable* const d = framebuffers.draw_binding ? nullptr : draw_drawable();
  return !d || draw_targets(draw_buffer, extra_draw_buffers, *d) != Target::Both;
}

void Context::render_to_draw_buffers(raster::FunctionRef<void()> render) {
  draw_pass_output_ = 0;
  if (framebuffers.draw_binding) {
    // The view holds every draw buffer: one pass writes them all (raster/draw_targets.h).
    refresh_changed_framebuffer_views(*this);
    note_draw_framebuffer_rendered(*this);
    return render();
  }
  Drawable* const draw_ = draw_drawable();
  if (!draw_) return render();
  switch (draw_targets(draw_buffer, extra_draw_buffers, *draw_)) {
    case Target::None: use_color_buffer({}); return render();
    case Target::Front:
      draw_->front_drawn = true;
      draw_pass_output_ = first_output_for(Target::Front, draw_buffer, extra_draw_buffers, *draw_);
      use_color_buffer(draw_->front_color(), draw_pass_output_);
      return render();
    case Target::Back:
      draw_pass_output_ = first_output_for(Target::Back, draw_buffer, extra_draw_buffers, *draw_);
      use_color_buffer(draw_->framebuffer.color, draw_pass_output_);
      return render();
    case Target::Both: draw_->front_drawn = true; break;
  }
  // Each fragment is tested once against depth and stencil, and written to both buffers:
  // the second pass starts from the depth and stencil values the first one started from,
  // and so ends with the same ones.
  const raster::Framebuffer& fb = draw_->framebuffer;
  draw_pass_output_ = first_output_for(Target::Back, draw_buffer, extra_draw_buffers, *draw_);
  use_color_buffer(fb.color, draw_pass_output_);
  renderer_->flush();
  const DepthStencilCopy before(fb);
  render();
  renderer_->flush();
  before.restore(fb);
  draw_pass_output_ = first_output_for(Target::Front, draw_buffer, extra_draw_buffers, *draw_);
  use_color_buffer(draw_->front, draw_pass_output_);
  render();
  draw_pass_output_ = 0;
}

raster::Framebuffer Context::read_framebuffer() const {
  const Drawable* read = read_drawable();
  if (!read) return raster::Framebuffer{};
  raster::Framebuffer fb = read->framebuffer;
  if (reads_front(read_buffer)) fb.color = read->front_color();
  if (fb.samples > 1 && read->resolved.base) {  // a multisampled window reads resolved colour, sample 0's depth
    if (!reads_front(read_buffer)) {
      renderer_->flush();
      raster::resolve_color(fb, read->resolved);
      fb.color = read->resolved;
    }
    fb.samples = 1;
  }
  return fb;
}

}  // namespace pineda
