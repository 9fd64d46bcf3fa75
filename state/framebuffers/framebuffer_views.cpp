// Completeness of framebuffer objects and the views the context renders through.
#include <algorithm>
#include <span>

#include "state/context.h"
#include "state/framebuffers/depth_copy.h"
#include "state/framebuffers/framebuffer_object.h"

namespace pineda {
namespace {

TextureObject* attached_texture(Context& ctx, const Attachment& a) {
  return a.type == GL_TEXTURE ? ctx.textures.find(a.name) : nullptr;
}

// The attachment's image size; false when it has no image.
bool image_size(Context& ctx, const Attachment& a, int& width, int& height) {
  if (a.type == GL_RENDERBUFFER) {
    width = a.renderbuffer->width;
    height = a.renderbuffer->height;
    return width > 0 && height > 0;
  }
  const TextureLevelData* level = attached_level(ctx, a);
  if (!level) return false;
  width = level->width;
  height = level->height;
  return true;
}

GLint image_internal_format(Context& ctx, const Attachment& a) {
  if (a.type == GL_RENDERBUFFER) return GLint(a.renderbuffer->internal_format);
  const TextureLevelData* level = attached_level(ctx, a);
  return level ? level->internal_format : 0;
}

GLsizei attachment_samples(const Attachment& a) { return a.type == GL_RENDERBUFFER ? a.renderbuffer->samples : 0; }

// The depth texture's texels as integers of `bits` bits, when the texture changed since the
// last import.
void import_depth(Context& ctx, Attachment& a, const TextureLevelData& level, int bits) {
  const TextureObject* tex = attached_texture(ctx, a);
  const size_t n = size_t(level.width) * size_t(level.height);
  if (a.depth_copy_version == tex->version && a.depth_copy.size() == n) return;
  // Rendering queued into this copy is written back first, so none is lost.
  resolve_rendered_textures(ctx);
  if (a.depth_copy_version == tex->version && a.depth_copy.size() == n) return;
  const size_t offset = n * size_t(a.layer);
  a.depth_copy.assign(n, 0);
  const size_t present = std::min(n, level.texels.size() - std::min(offset, level.texels.size()));
  depth_integers_from_floats(level.texels.data() + offset, a.depth_copy.data(), present, bits);
  a.depth_copy_version = tex->version;
}

raster::ColorBuffer color_buffer(Context& ctx, const Attachment& a, const RenderableFormat& format) {
  raster::ColorBuffer cb;
  cb.reduction = color_reduction(format.color);
  if (a.type == GL_RENDERBUFFER) {
    cb.base = reinterpret_cast<uint8_t*>(a.renderbuffer->pixels->color.data());
    cb.stride = ptrdiff_t(a.renderbuffer->width) * 4;
    cb.sample_stride = cb.stride * a.renderbuffer->height;
    return cb;
  }
  TextureLevelData* level = attached_level(ctx, a);
  const size_t slice = size_t(level->width) * size_t(level->height) * size_t(a.layer);
  cb.base = reinterpret_cast<uint8_t*>(level->texels.data() + slice);
  cb.stride = ptrdiff_t(level->width) * 4;
  return cb;
}

// The view of `fb` whose colour buffers are the attachments of `buffers` (draw buffer i's at
// i; GL_NONE ends the list when nothing follows); an incomplete framebuffer has an empty view
// (nothing is drawn into it). Returns the framebuffer's status.
GLenum build_view(Context& ctx, FramebufferObject& fb, std::span<const GLenum> buffers, Drawable& view) {
  view = Drawable{};
  view.accum = false;
  const GLenum status = framebuffer_status(ctx, fb, false);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    view.red_bits = view.green_bits = view.blue_bits = view.alpha_bits = 0;
    return status;
  }
  raster::Framebuffer& out = view.framebuffer;
  out.width = out.height = kMaxRenderbufferSize;
  for (const Attachment& a : fb.attachments) {
    int w = 0, h = 0;
    if (a.type == GL_NONE || !image_size(ctx, a, w, h)) continue;
    if (a.type == GL_RENDERBUFFER) view.kept_storage.push_back(a.renderbuffer->pixels);
    if (a.type == GL_TEXTURE) {  // (a depth texture renders into the attachment's copy instead)
      const TextureLevelData* level = attached_level(ctx, a);
      view.kept_storage.push_back(level->texels.owner());
      if (!level->stencil.empty()) view.kept_storage.push_back(level->stencil.owner());
    }
    out.width = std::min(out.width, w);
    out.height = std::min(out.height, h);
    out.samples = std::max(attachment_samples(a), 1);  // the same for all: the framebuffer is complete
  }
  view.red_bits = view.green_bits = view.blue_bits = view.alpha_bits = 0;
  bool bits_set = false;  // RED_BITS...: the first draw buffer with an image
  for (size_t i = 0; i < buffers.size(); ++i) {
    const GLenum buffer = buffers[i];
    const int point = buffer == GL_NONE ? -1 : attachment_point(buffer);
    if (point < 0 || point >= kMaxColorAttachments || fb.attachments[point].type == GL_NONE) continue;
    const Attachment& a = fb.attachments[point];
    const RenderableFormat format = *attachment_format(ctx, a);
    if (i == 0) out.color = color_buffer(ctx, a, format);
    else out.more_color[i - 1] = color_buffer(ctx, a, format);
    out.color_targets = std::max(out.color_targets, int(i) + 1);
    if (bits_set) continue;
    bits_set = true;
    view.red_bits = format.color.red;
    view.green_bits = format.color.green;
    view.blue_bits = format.color.blue;
    view.alpha_bits = format.color.alpha;
  }
  Attachment& depth = fb.attachments[kDepthPoint];
  if (depth.type != GL_NONE) {
    const RenderableFormat format = *attachment_format(ctx, depth);
    out.depth.bits = format.depth_bits;
    if (depth.type == GL_RENDERBUFFER) {
      out.depth.base = depth.renderbuffer->pixels->depth.data();
      out.depth.stride = depth.renderbuffer->width;
      out.depth.sample_stride = out.depth.stride * depth.renderbuffer->height;
    } else {
      const TextureLevelData* level = attached_level(ctx, depth);
      import_depth(ctx, depth, *level, format.depth_bits);
      out.depth.base = depth.depth_copy.data();
      out.depth.stride = level->width;
    }
  }
  Attachment& stencil = fb.attachments[kStencilPoint];
  if (stencil.type == GL_RENDERBUFFER) {
    out.stencil.bits = 8;
    out.stencil.base = stencil.renderbuffer->pixels->stencil.data();
    out.stencil.stride = stencil.renderbuffer->width;
    out.stencil.sample_stride = out.stencil.stride * stencil.renderbuffer->height;
  } else if (stencil.type == GL_TEXTURE) {  // a DEPTH_STENCIL texture's indices, rendered in place
    TextureLevelData* level = attached_level(ctx, stencil);
    out.stencil.bits = 8;
    out.stencil.base = level->stencil.data() + size_t(level->width) * level->height * size_t(stencil.layer);
    out.stencil.stride = level->width;
  }
  return status;
}

// The source of the view build_view makes of `fb` with `buffers`.
ViewSource view_source(Context& ctx, const FramebufferObject& fb, std::span<const GLenum> buffers) {
  ViewSource source;
  source.add(buffers.size());
  for (const GLenum b : buffers) source.add(b);
  for (int p = 0; p < kAttachmentPoints; ++p) {
    const Attachment& a = fb.attachments[p];
    if (a.type == GL_NONE) continue;
    source.add(static_cast<uint64_t>(p) << 32 | a.type);
    source.add(a.name);
    source.add(static_cast<uint64_t>(static_cast<uint32_t>(a.level)) << 32 | static_cast<uint32_t>(a.layer));
    source.add(static_cast<uint64_t>(a.face) << 1 | (a.cube ? 1u : 0u));
    if (a.type == GL_RENDERBUFFER) {
      const Renderbuffer& rb = *a.renderbuffer;
      source.add(&rb);
      source.add(static_cast<uint64_t>(static_cast<uint32_t>(rb.width)) << 32 | static_cast<uint32_t>(rb.height));
      source.add(static_cast<uint64_t>(rb.internal_format) << 32 | static_cast<uint32_t>(rb.samples));
      source.add(rb.pixels.get());
      if (rb.pixels) {
        source.add(rb.pixels->color.data());
        source.add(rb.pixels->depth.data());
        source.add(rb.pixels->stencil.data());
      }
      continue;
    }
    const TextureObject* tex = attached_texture(ctx, a);
    source.add(tex);
    if (!tex) continue;
    source.add(tex->version);
    source.add(a.depth_copy.data());  // what a depth texture renders into
    const TextureLevelData* level = attached_level(ctx, a);
    source.add(level);
    if (!level) continue;
    source.add(static_cast<uint64_t>(static_cast<uint32_t>(level->width)) << 32 | static_cast<uint32_t>(level->height));
    source.add(static_cast<uint64_t>(static_cast<uint32_t>(level->depth)) << 32 | static_cast<uint32_t>(level->internal_format));
    source.add(level->texels.data());
    source.add(level->texels.size());
    source.add(level->stencil.data());
    source.add(level->stencil.size());
  }
  return source;
}

// Builds the view unless its source is unchanged; `status`: the framebuffer's, as it was built.
void refresh_view(Context& ctx, FramebufferObject& fb, std::span<const GLenum> buffers, Drawable& view,
                  ViewSource& built_from, GLenum& status) {
  if (view_source(ctx, fb, buffers) == built_from) return;
  status = build_view(ctx, fb, buffers, view);
  // As built: building may import a depth texture's copy (after writing back queued rendering,
  // which counts as a change of the texture).
  built_from = view_source(ctx, fb, buffers);
}

bool renders_into_textures(const FramebufferObject& fb) {
  return std::any_of(fb.attachments.begin(), fb.attachments.end(), [](const Attachment& a) { return a.type == GL_TEXTURE; });
}

}  // namespace

int attachment_point(GLenum attachment) {
  if (attachment >= GL_COLOR_ATTACHMENT0 && attachment < GL_COLOR_ATTACHMENT0 + kMaxColorAttachments)
    return int(attachment - GL_COLOR_ATTACHMENT0);
  if (attachment == GL_DEPTH_ATTACHMENT) return kDepthPoint;
  if (attachment == GL_STENCIL_ATTACHMENT) return kStencilPoint;
  return -1;
}

TextureLevelData* attached_level(Context& ctx, const Attachment& a) {
  TextureObject* tex = attached_texture(ctx, a);
  if (!tex || a.level < 0) return nullptr;
  std::vector<TextureLevelData>& levels = tex->face_levels(a.cube ? a.face : 0);
  if (size_t(a.level) >= levels.size()) return nullptr;
  TextureLevelData& level = levels[a.level];
  if (level.width <= 0 || level.height <= 0 || a.layer >= level.depth) return nullptr;
  if (level.texels.size() < size_t(level.width) * level.height * level.depth) return nullptr;
  return &level;
}

std::optional<RenderableFormat> attachment_format(Context& ctx, const Attachment& a) {
  if (a.type == GL_RENDERBUFFER) {
    if (a.renderbuffer->width <= 0 || a.renderbuffer->height <= 0) return std::nullopt;
    return a.renderbuffer->format;
  }
  const TextureLevelData* level = attached_level(ctx, a);
  if (!level) return std::nullopt;
  const std::optional<RenderableFormat> format = texture_renderable_format(level->internal_format);
  if (format && format->has_stencil() && level->stencil.size() < level->texels.size()) return std::nullopt;
  return format;
}

GLenum framebuffer_status(Context& ctx, const FramebufferObject& fb, bool ext_rules) {
  int images = 0, width = -1, height = -1;
  GLsizei samples = 0;
  bool sizes_differ = false, formats_differ = false;
  GLint color_format = 0;
  for (int p = 0; p < kAttachmentPoints; ++p) {
    const Attachment& a = fb.attachments[p];
    if (a.type == GL_NONE) continue;
    const std::optional<RenderableFormat> format = attachment_format(ctx, a);
    if (!format) return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
    const bool fits = p < kMaxColorAttachments ? format->kind == RenderableFormat::Kind::Color
                      : p == kDepthPoint       ? format->has_depth()
                                               : format->has_stencil();
    if (!fits) return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
    int w = 0, h = 0;
    image_size(ctx, a, w, h);
    if (images++ == 0) {
      width = w;
      height = h;
      samples = attachment_samples(a);
    } else {
      if (w != width || h != height) sizes_differ = true;
      // ARB_framebuffer_object, EXT_framebuffer_multisample: one RENDERBUFFER_SAMPLES for all.
      if (attachment_samples(a) != samples) return GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE;
    }
    if (p < kMaxColorAttachments) {
      const GLint f = image_internal_format(ctx, a);
      if (color_format && f != color_format) formats_differ = true;
      color_format = f;
    }
  }
  if (images == 0) return GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT;
  if (ext_rules && sizes_differ) return GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_EXT;
  if (ext_rules && formats_differ) return GL_FRAMEBUFFER_INCOMPLETE_FORMATS_EXT;
  // No draw and read buffer rules (INCOMPLETE_DRAW_BUFFER, INCOMPLETE_READ_BUFFER): GL 4.1 and
  // GL_ARB_ES2_compatibility, which Pineda offers, dropped them, as Mesa's llvmpipe does. A
  // depth-only framebuffer whose draw buffer is still COLOR_ATTACHMENT0 renders (piglit's
  // depth-stencil-blit, fbo-clear-formats, glmark2's shadow scene through the EXT entry point).
  return GL_FRAMEBUFFER_COMPLETE;
}

void refresh_framebuffer_views(Context& ctx) {
  FramebufferState& fs = ctx.framebuffers;
  FramebufferObject* draw = fs.draw_object();
  FramebufferObject* read = fs.read_object();
  // The context's draw and read buffers are the bound objects' (glPopAttrib may set them).
  if (draw) {
    draw->draw_buffer = ctx.draw_buffer;
    draw->extra_draw_buffers = ctx.extra_draw_buffers;
  }
  if (read) read->read_buffer = ctx.read_buffer;
  if (draw) {
    std::array<GLenum, kMaxDrawBuffers> buffers{draw->draw_buffer};
    std::copy(draw->extra_draw_buffers.begin(), draw->extra_draw_buffers.end(), buffers.begin() + 1);
    refresh_view(ctx, *draw, buffers, draw->draw_view, draw->draw_source, draw->draw_status);
  }
  if (read)
    refresh_view(ctx, *read, std::span<const GLenum>(&read->read_buffer, 1), read->read_view, read->read_source,
                 read->read_status);
  ctx.set_framebuffer_views(draw ? &draw->draw_view : nullptr, read ? &read->read_view : nullptr);
}

void refresh_changed_framebuffer_views(Context& ctx) {
  const StateKey key = ctx.state_key();
  if (key == ctx.framebuffers.views_refreshed) return;
  refresh_framebuffer_views(ctx);
  ctx.framebuffers.views_refreshed = key;
}

void note_draw_framebuffer_rendered(Context& ctx) {
  if (const FramebufferObject* fb = ctx.framebuffers.draw_object(); fb && renders_into_textures(*fb)) {
    // The next draw that samples them resolves them first (a draw working it out anew, StateKey).
    if (!ctx.framebuffers.textures_rendered) ctx.note_state_changed();
    ctx.framebuffers.textures_rendered = true;
  }
}

void resolve_rendered_textures(Context& ctx) {
  FramebufferState& fs = ctx.framebuffers;
  if (!fs.textures_rendered) return;
  fs.textures_rendered = false;
  ctx.note_state_changed();  // the textures change (a draw may resolve them: StateKey)
  ctx.finish();
  FramebufferObject* fb = fs.draw_object();
  if (!fb) return;
  for (int p = 0; p < kAttachmentPoints; ++p) {
    Attachment& a = fb->attachments[p];
    TextureObject* tex = attached_texture(ctx, a);
    TextureLevelData* level = attached_level(ctx, a);
    if (!tex || !level) continue;
    const bool depth_copy = p == kDepthPoint && a.depth_copy_version == tex->version;
    if (depth_copy) {
      const std::optional<RenderableFormat> format = attachment_format(ctx, a);
      const int bits = format ? format->depth_bits : 24;
      const size_t n = std::min(a.depth_copy.size(), size_t(level->width) * size_t(level->height));
      const size_t offset = n * size_t(a.layer);
      const size_t present = std::min(n, level->texels.size() - std::min(offset, level->texels.size()));
      depth_floats_from_integers(a.depth_copy.data(), level->texels.data() + offset, present, bits);
    }
    tex->changed();
    if (depth_copy) a.depth_copy_version = tex->version;
  }
}

bool attached_to_draw_framebuffer(Context& ctx, const TextureObject& tex) {
  const FramebufferObject* fb = ctx.framebuffers.draw_object();
  if (!fb) return false;
  return std::any_of(fb->attachments.begin(), fb->attachments.end(),
                     [&](const Attachment& a) { return a.type == GL_TEXTURE && ctx.textures.find(a.name) == &tex; });
}

bool check_draw_framebuffer(Context& ctx) {
  FramebufferObject* fb = ctx.framebuffers.draw_object();
  if (!fb) return true;
  refresh_changed_framebuffer_views(ctx);
  if (fb->draw_status == GL_FRAMEBUFFER_COMPLETE) return true;
  ctx.record_error(GL_INVALID_FRAMEBUFFER_OPERATION, "the draw framebuffer is not complete");
  return false;
}

bool check_read_framebuffer(Context& ctx) {
  FramebufferObject* fb = ctx.framebuffers.read_object();
  if (!fb) return true;
  resolve_rendered_textures(ctx);
  refresh_framebuffer_views(ctx);
  if (fb->read_status == GL_FRAMEBUFFER_COMPLETE) return true;
  ctx.record_error(GL_INVALID_FRAMEBUFFER_OPERATION, "the read framebuffer is not complete");
  return false;
}

bool check_read_single_sampled(Context& ctx) {
  if (!check_read_framebuffer(ctx)) return false;
  const FramebufferObject* fb = ctx.framebuffers.read_object();
  if (!fb || fb->read_view.framebuffer.samples == 1) return true;
  ctx.record_error(GL_INVALID_OPERATION, "the read framebuffer is multisampled");
  return false;
}

void detach_deleted(Context& ctx, GLenum type, GLuint name) {
  FramebufferState& fs = ctx.framebuffers;
  const bool attached = std::any_of(fs.framebuffers.begin(), fs.framebuffers.end(), [&](const auto& entry) {
    const auto& points = entry.second->attachments;
    return std::any_of(points.begin(), points.end(), [&](const Attachment& a) { return a.type == type && a.name == name; });
  });
  if (!attached) return;
  resolve_rendered_textures(ctx);
  ctx.finish();
  for (auto& [fb_name, fb] : fs.framebuffers) {
    // GL detaches a renderbuffer from the bound framebuffers only; an unbound one keeps it.
    const bool bound = fb_name == fs.draw_binding || fb_name == fs.read_binding;
    if (type == GL_RENDERBUFFER && !bound) continue;
    for (Attachment& a : fb->attachments)
      if (a.type == type && a.name == name) {
        a = Attachment{};
        fb->attachments_changed();
      }
  }
  refresh_framebuffer_views(ctx);
}

}  // namespace pineda
