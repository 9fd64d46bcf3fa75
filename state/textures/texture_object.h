// Texture objects and their name space. Each object keeps its levels in RGBA8 and hands
// the rasterizer an immutable snapshot, rebuilt only after a change: a queued scene keeps
// the image it was recorded with, so changing a texture never waits for rendering.
#pragma once
#include <GL/gl.h>

#include <array>
#include <map>
#include <memory>
#include <vector>

#include "raster/texture.h"
#include "state/textures/texture_target.h"
#include "state/textures/shared_texels.h"

namespace pineda {

struct TextureLevelData {
  GLint width = 0, height = 0, depth = 1, border = 0;  // without the border
  GLint internal_format = 0;  // as the application gave it (for glGetTexLevelParameter)
  raster::TexBaseFormat base = raster::TexBaseFormat::RGBA;  // what `texels` were reduced to
  SharedTexels<uint32_t> texels;
  SharedTexels<uint8_t> stencil;  // a DEPTH_STENCIL level's stencil indices, beside the depth texels
};

// What glTexParameter sets; glPushAttrib(GL_TEXTURE_BIT) saves it whole.
struct TexParams {
  GLenum min_filter = GL_NEAREST_MIPMAP_LINEAR, mag_filter = GL_LINEAR;
  GLenum wrap_s = GL_REPEAT, wrap_t = GL_REPEAT, wrap_r = GL_REPEAT;
  float border_color[4] = {0, 0, 0, 0};
  float priority = 1.f;
  float min_lod = -1000.f, max_lod = 1000.f, lod_bias = 0.f;
  GLint base_level = 0, max_level = 1000;
  bool generate_mipmap = false;
  // GL 1.4 depth textures and shadow comparison
  GLenum depth_mode = GL_LUMINANCE, compare_mode = GL_NONE, compare_func = GL_LEQUAL;
  GLenum srgb_decode = GL_DECODE_EXT;  // EXT_texture_sRGB_decode: SKIP_DECODE_EXT reads sRGB texels as stored
  GLenum swizzle[4] = {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA};  // EXT_texture_swizzle
  GLint crop_rect[4] = {0, 0, 0, 0};  // OES_draw_texture (OpenGL ES 1.1): u, v, width, height
};

struct TextureObject {
  GLenum target = 0;  // 0 until first bound
  std::vector<TextureLevelData> levels;  // index = level; a cube map's +X face
  std::array<std::vector<TextureLevelData>, kCubeFaces - 1> other_faces;  // a cube map's -X to -Z faces
  TexParams params;

  // The levels of cube face `face` (0: +X, as `levels`); face 0 for any other target.
  std::vector<TextureLevelData>& face_levels(int face) { return face == 0 ? levels : other_faces[face - 1]; }
  const std::vector<TextureLevelData>& face_levels(int face) const {
    return face == 0 ? levels : other_faces[face - 1];
  }

  // The image the sampler reads, or null when the texture is incomplete; `sampling`: the
  // parameters of a sampler object bound to the unit, which replace the texture's sampling
  // parameters (textures/sampling_params.h), its minification filter in the completeness rules
  // too. The image reads the levels' texels where they are (one face, no swizzle), unless
  // `rendered_into`: the draw renders into the texture (a feedback loop), and its tiles must
  // not read what others write.
  std::shared_ptr<const raster::TextureImage> snapshot(const TexParams* sampling = nullptr, bool rendered_into = false);
  raster::Sampler sampler(const TexParams* sampling = nullptr) const;
  void changed() {
    drop_snapshots();
    ++version;
  }
  // GL_GENERATE_MIPMAP: after `level` (of cube face `face`) changed, rebuilds the levels below
  // it when it is the base level and generation is on.
  void level_changed(int level, int face = 0);
  // The same after glTexSubImage replaced the texels of `box` in `level`: a snapshot that no
  // queued draw holds reads the changed texels where they are (or takes the box into its own
  // copy of them) instead of being rebuilt whole.
  struct TexelBox {
    int x, y, z, width, height, depth;
  };
  void box_changed(int level, int face, const TexelBox& box);
  // Before the texels of `level` change in place (glTexSubImage): a snapshot that a queued draw
  // holds keeps the texels it reads, as they are (the level's are copied apart from them).
  void before_texels_change(int level, int face);
  // Rebuilds the levels below `level` of cube face `face` from it (glGenerateMipmap).
  void generate_levels(int level, int face = 0);
  // Counts changes: a framebuffer attachment's copy of a depth image compares it (framebuffers/).
  uint64_t version = 0;

  // glTexStorage's levels (ARB_texture_storage); 0 while the storage is mutable.
  GLint immutable_levels = 0;
  // After glTexStorage made `levels` levels: the storage is immutable, and the base and
  // maximum levels are clamped into them.
  void make_immutable(GLint levels);
  // BASE_LEVEL or MAX_LEVEL as glTexParameter stores it: an immutable texture's clamped into
  // its levels (base to [0, levels - 1], max to [base, levels - 1]).
  GLint clamped_level_param(GLenum pname, GLint level) const;

 private:
  void drop_snapshots() {
    snapshot_.reset();
    snapshot_valid_ = false;
    other_snapshot_.reset();
    other_snapshot_valid_ = false;
  }
  // Copies `box` of `level` into the snapshot; false when there is none to patch.
  bool patch_snapshot(int level, int face, const TexelBox& box);

  // What of the sampling parameters a snapshot depends on: whether the minification filter
  // needs mipmaps (completeness), and whether sRGB texels are decoded; and whether it copies
  // the texels (snapshot()'s rendered_into).
  struct SnapshotKey {
    bool mipmapped = false, srgb_decode = true, copies = false;
    bool operator==(const SnapshotKey&) const = default;
  };
  static SnapshotKey snapshot_key(const TexParams& sampling, bool copies);
  std::shared_ptr<raster::TextureImage> build_snapshot(SnapshotKey key) const;

  // For the texture's own sampling parameters, and for the last sampler object's that differ
  // in the key. Each remembers its key, so a sampling parameter needs no invalidation: each draw
  // takes the sampler anew, and a snapshot is rebuilt only when its key changes (a program
  // setting its wrap modes and filters before every draw copied its whole texture each time).
  std::shared_ptr<raster::TextureImage> snapshot_, other_snapshot_;
  SnapshotKey snapshot_key_, other_snapshot_key_;
  bool snapshot_valid_ = false, other_snapshot_valid_ = false;
};

class TextureNamespace {
 public:
  TextureNamespace();
  void generate(GLsizei n, GLuint* names);
  // The object for `name`, created when missing; name 0 is the target's default texture.
  TextureObject& get_or_create(GLuint name, GLenum target);
  TextureObject* find(GLuint name);
  void remove(GLuint name);
  bool is_texture(GLuint name) const;
  // The proxy object of a kind (GL_PROXY_TEXTURE_*): levels without texels, never bound.
  TextureObject& proxy(TexTarget kind) { return proxies_[size_t(kind)]; }

 private:
  std::map<GLuint, std::unique_ptr<TextureObject>> objects_;
  std::map<GLuint, bool> reserved_;  // generated names not bound yet
  GLuint next_name_ = 1;
  std::array<TextureObject, kTexTargetCount> defaults_, proxies_;  // indexed by TexTarget
};

}  // namespace pineda
