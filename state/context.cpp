#include "state/context.h"

#include "state/limits.h"

namespace pineda {

namespace {

// PINEDA_DEBUG=1 prints every GL error's message to stderr, for programs that never ask.
bool print_errors_from_environment() {
  const char* v = std::getenv("PINEDA_DEBUG");
  return v && *v && std::string_view(v) != "0";
}

}  // namespace

namespace {

// The group, once the new context is one of its members: before the context touches it.
// (Its calls wait, under the group's lock, for a call of the first member in flight.)
std::shared_ptr<ShareGroup> joined(std::shared_ptr<ShareGroup> group) {
  group->join();
  return group;
}

}  // namespace

Context::Context(const ContextAttribs& attribs, std::shared_ptr<ShareGroup> share)
    : share_group_(joined(share ? std::move(share) : std::make_shared<ShareGroup>())),
      debug(attribs.debug, print_errors_from_environment()),
      textures(share_group_->textures),
      samplers(share_group_->samplers),
      lists(share_group_->lists),
      attribs_(attribs), renderer_(std::make_unique<raster::Renderer>(attribs.threads)) {
  for (auto& stack : texture_matrix) stack.max_depth = 10;
  projection.max_depth = 10;
  lighting.lights[0].diffuse = glm::vec4(1);
  lighting.lights[0].specular = glm::vec4(1);
  draw_state.point_params.size_max = kPointSizeRange[1];
  if (es2()) {
    // OpenGL ES 2.0 points are always sprites sized by gl_PointSize (ES 2.0 3.3).
    programs.point_size_from_shader = true;
    draw_state.point_params.sprite.enabled = true;
  }
}

Context::~Context() { share_group_->leave(); }

void Context::make_current(Drawable* draw, Drawable* read) {
  note_state_changed();
  draw_ = draw;
  read_ = read;
  // GL: the viewport, scissor and draw/read buffers take their initial values from the
  // drawable the context is first bound to; later bindings keep what the application set.
  if (!ever_bound_ && draw) {
    ever_bound_ = true;
    viewport.x = viewport.y = 0;
    viewport.width = draw->framebuffer.width;
    viewport.height = draw->framebuffer.height;
    draw_state.scissor = {0, 0, draw->framebuffer.width, draw->framebuffer.height};
    draw_buffer = read_buffer = draw->double_buffered ? GL_BACK : GL_FRONT;
  }
  bind_framebuffer();
}

void Context::release_current() {
  note_state_changed();
  renderer_->flush();
  draw_ = read_ = nullptr;
  renderer_->set_framebuffer(raster::Framebuffer{});
  renderer_storage_.clear();
}

void Context::drawable_changed() {
  note_state_changed();
  bind_framebuffer();
}

}  // namespace pineda
