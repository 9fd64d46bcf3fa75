// The objects that contexts created with a share list (glXCreateContext's shareList,
// eglCreateContext's share_context, OSMesa's sharelist) hold in common: textures (the
// default ones too, as Mesa), buffer objects, display lists, shader and program objects.
// Queries and framebuffer objects stay per context.
#pragma once
#include <atomic>
#include <memory>
#include <mutex>

#include "state/buffer_object.h"
#include "state/display_list.h"
#include "state/programs/program_objects.h"
#include "state/texture_object.h"

namespace pineda {

struct ShareGroup {
  TextureNamespace textures;
  ObjectNames<BufferObject> buffers;
  DisplayLists lists;
  ShaderProgramNames programs;

  // Contexts of a group may run on different threads: while the group has more than one
  // member, every GL call holds this lock (glapi/), so calls on shared objects never race.
  std::recursive_mutex mutex;
  std::atomic<int> members{0};
};

// The lock a GL call holds: empty (free) when the context shares with nobody.
inline std::unique_lock<std::recursive_mutex> lock_if_shared(ShareGroup& group) {
  if (group.members.load(std::memory_order_acquire) > 1) return std::unique_lock(group.mutex);
  return {};
}

}  // namespace pineda
