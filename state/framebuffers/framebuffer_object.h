// Framebuffer and renderbuffer objects (GL_ARB_framebuffer_object, GL_EXT_framebuffer_object):
// the objects, their name spaces and bindings, and the views through which the context
// renders into and reads from the bound ones.
//
// Storage: a renderbuffer owns its pixels (colour as RGBA8, depth as integers of its bits,
// stencil as bytes). A colour texture attachment is rendered in place: texture levels are
// RGBA8 (texture_object.h), and the write stage reduces each pixel to the level's format
// (raster::ColorReduction), so the level holds what glTexImage would have stored. A depth
// texture keeps float texels, so its attachment renders into an integer copy that is imported
// when the texture changed and written back before the texture is next read.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include "raster/cache_line_vector.h"
#include "state/draw_buffer_list.h"
#include "state/drawable.h"
#include "state/framebuffers/renderable_format.h"
#include "state/framebuffers/renderbuffer.h"
#include "state/framebuffers/view_source.h"
#include "state/state_key.h"

namespace pineda {

class Context;
struct TextureObject;
struct TextureLevelData;

constexpr int kMaxColorAttachments = 8;
constexpr int kMaxRenderbufferSize = 8192;
// GL_MAX_SAMPLES: llvmpipe's only multisample count; 1..4 samples are rounded up to it.
constexpr int kMaxSamples = 4;

struct Attachment {
  GLenum type = GL_NONE;  // GL_NONE, GL_RENDERBUFFER or GL_TEXTURE
  std::shared_ptr<Renderbuffer> renderbuffer;  // kept alive while attached, as GL requires
  GLuint name = 0;  // the renderbuffer's or texture's name
  GLint level = 0;
  int face = 0;     // cube map face 0..5 (+X, -X, +Y, -Y, +Z, -Z)
  bool cube = false;
  GLint layer = 0;  // 3D texture slice
  // A depth texture's depth values as integers of its bits, and the texture version imported.
  raster::CacheLineVector<uint32_t> depth_copy;
  uint64_t depth_copy_version = ~uint64_t{0};
};

// Attachment points: the colour attachments, then depth and stencil.
constexpr int kDepthPoint = kMaxColorAttachments;
constexpr int kStencilPoint = kMaxColorAttachments + 1;
constexpr int kAttachmentPoints = kMaxColorAttachments + 2;

struct FramebufferObject {
  std::array<Attachment, kAttachmentPoints> attachments;
  GLenum draw_buffer = GL_COLOR_ATTACHMENT0, read_buffer = GL_COLOR_ATTACHMENT0;
  ExtraDrawBuffers extra_draw_buffers{};  // DRAW_BUFFER1.. (glDrawBuffers), GL_NONE by default
  // What the context renders into and reads from, rebuilt by refresh_framebuffer_views when
  // their sources changed (an empty source: not built yet).
  Drawable draw_view, read_view;
  ViewSource draw_source, read_source;
  GLenum draw_status = 0, read_status = 0;  // framebuffer_status (without EXT rules) when they were built
  // After `attachments` changed: both views are rebuilt when next refreshed, even if the object
  // is bound only one way now (a replaced attachment takes a depth texture's copy with it).
  void attachments_changed() { draw_source = read_source = ViewSource{}; }
};

struct FramebufferState {
  explicit FramebufferState(RenderbufferNames& shared_renderbuffers) : renderbuffers(shared_renderbuffers) {}

  std::map<GLuint, std::unique_ptr<FramebufferObject>> framebuffers;
  RenderbufferNames& renderbuffers;  // the share group's
  std::set<GLuint> generated_framebuffers;  // generated names not yet bound
  GLuint draw_binding = 0, read_binding = 0, renderbuffer_binding = 0;
  // The bound renderbuffer: it stays bound here when another context deletes its name.
  std::shared_ptr<Renderbuffer> bound_renderbuffer;
  // The window-system framebuffer's draw and read buffers while an object is bound (the
  // context's draw_buffer/read_buffer are those of the bound draw/read framebuffer).
  GLenum window_draw_buffer = GL_BACK, window_read_buffer = GL_BACK;
  ExtraDrawBuffers window_extra_draw_buffers{};
  // Set when queued rendering may write a texture attached to the draw framebuffer.
  bool textures_rendered = false;
  // The state at a draw's last refresh of the views (refresh_changed_framebuffer_views).
  StateKey views_refreshed;

  FramebufferObject* draw_object() const { return find(draw_binding); }
  FramebufferObject* read_object() const { return find(read_binding); }
  FramebufferObject* find(GLuint name) const {
    auto it = framebuffers.find(name);
    return name && it != framebuffers.end() ? it->second.get() : nullptr;
  }
};

// The attachment point index of an attachment enum (COLOR_ATTACHMENTi, DEPTH_ATTACHMENT,
// STENCIL_ATTACHMENT), or -1.
int attachment_point(GLenum attachment);

// GL 4.1 4.4.4.2 framebuffer completeness of a framebuffer object (what draws and reads
// require, as Mesa); `ext_rules` adds EXT_framebuffer_object's INCOMPLETE_DIMENSIONS_EXT and
// INCOMPLETE_FORMATS_EXT.
GLenum framebuffer_status(Context& ctx, const FramebufferObject& fb, bool ext_rules);

// Rebuilds the views of the bound framebuffer objects (after attachments, storage or the
// draw/read buffer changed) and points the context at them.
void refresh_framebuffer_views(Context& ctx);
// The same for a draw, unless no call changed the state since a draw's last refresh (StateKey:
// a draw into a framebuffer object refreshed them twice, a twentieth of a small draw's time).
void refresh_changed_framebuffer_views(Context& ctx);

// Called for every command that renders into the draw framebuffer.
void note_draw_framebuffer_rendered(Context& ctx);

// Completes rendering queued into textures of the draw framebuffer and makes the textures
// show it: before a texture is sampled, read or respecified.
void resolve_rendered_textures(Context& ctx);
// Whether `tex` is attached to the draw framebuffer (a draw sampling it is a feedback loop).
bool attached_to_draw_framebuffer(Context& ctx, const TextureObject& tex);

// Before a command renders into the draw framebuffer or reads the read framebuffer: true
// when it is complete; otherwise GL_INVALID_FRAMEBUFFER_OPERATION is recorded.
bool check_draw_framebuffer(Context& ctx);
bool check_read_framebuffer(Context& ctx);
// As check_read_framebuffer, for glReadPixels, glCopyTex(Sub)Image and glCopyPixels, which
// cannot read a multisampled framebuffer object (ARB_framebuffer_object: INVALID_OPERATION).
bool check_read_single_sampled(Context& ctx);

// Detaches a deleted texture or renderbuffer (`type` GL_TEXTURE or GL_RENDERBUFFER) from every
// framebuffer object that has it (Pineda detaches textures from unbound ones too: their
// storage goes with the name).
void detach_deleted(Context& ctx, GLenum type, GLuint name);

// Which bindings a framebuffer target (FRAMEBUFFER, DRAW_FRAMEBUFFER, READ_FRAMEBUFFER) names.
bool framebuffer_target(GLenum target, bool& draw, bool& read);

// glDrawBuffer (read: glReadBuffer) while a framebuffer object is bound.
void set_object_color_buffer(Context& ctx, GLenum buffer, bool read);

// The texture level an attachment names, or null when it has no image.
TextureLevelData* attached_level(Context& ctx, const Attachment& a);
// The format an attachment renders with, or nullopt when the image is missing.
std::optional<RenderableFormat> attachment_format(Context& ctx, const Attachment& a);

}  // namespace pineda
