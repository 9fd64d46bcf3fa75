// Renders random scenes with Pineda's raster/ and with Mesa llvmpipe (EGL surfaceless, an FBO,
// GL 1.x immediate mode) and prints, per scene kind, the pixels whose coverage differs and the
// largest channel difference. Run: GALLIUM_DRIVER=llvmpipe ./pineda_raster_llvmpipe_compare
#define GL_GLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "raster/multisample.h"
#include "raster/renderer.h"

namespace {

using namespace pineda::raster;

constexpr int kW = 128, kH = 96;

struct Vert {
  float x, y, z, w, r, g, b, a, s, t;
};

struct Scene {
  GLenum gl_mode;
  Primitive mode;
  float line_width = 1, point_size = 1;
  bool flat = false, depth = false, textured = false, line_mode = false;
  float offset_factor = 0, offset_units = 0;
  bool blend = false;  // SrcAlpha, OneMinusSrcAlpha over a coloured background
  bool msaa = false;   // 4x multisampled, resolved (llvmpipe: a renderbuffer and glBlitFramebuffer)
};

GLuint single_fbo = 0, msaa_fbo = 0;

struct Texture {
  std::shared_ptr<TextureImage> image = std::make_shared<TextureImage>();
  GLuint name = 0;
};

bool init_gl() {
  auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_display) return false;
  EGLDisplay d = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (!eglInitialize(d, nullptr, nullptr) || !eglBindAPI(EGL_OPENGL_API)) return false;
  EGLContext c = eglCreateContext(d, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, nullptr);
  if (!c || !eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, c)) return false;
  std::printf("reference: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  GLuint fbo, rb[2];
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glGenRenderbuffers(2, rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kW, kH);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, kW, kH);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  single_fbo = fbo;
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) return false;
  GLuint ms_rb[2];
  glGenFramebuffers(1, &msaa_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo);
  glGenRenderbuffers(2, ms_rb);
  glBindRenderbuffer(GL_RENDERBUFFER, ms_rb[0]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, kW, kH);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ms_rb[0]);
  glBindRenderbuffer(GL_RENDERBUFFER, ms_rb[1]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH24_STENCIL8, kW, kH);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ms_rb[1]);
  glViewport(0, 0, kW, kH);
  glDisable(GL_DITHER);
  return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

const float kBackground[4] = {0.3f, 0.6f, 0.9f, 0.45f};

std::vector<uint8_t> draw_gl(const std::vector<Vert>& v, const Scene& sc) {
  const float* bg = sc.blend ? kBackground : nullptr;
  glBindFramebuffer(GL_FRAMEBUFFER, sc.msaa ? msaa_fbo : single_fbo);
  glClearColor(bg ? bg[0] : 0, bg ? bg[1] : 0, bg ? bg[2] : 0, bg ? bg[3] : 0);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glShadeModel(sc.flat ? GL_FLAT : GL_SMOOTH);
  glLineWidth(sc.line_width);
  glPointSize(sc.point_size);
  sc.depth ? glEnable(GL_DEPTH_TEST) : glDisable(GL_DEPTH_TEST);
  sc.textured ? glEnable(GL_TEXTURE_2D) : glDisable(GL_TEXTURE_2D);
  sc.blend ? glEnable(GL_BLEND) : glDisable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  const bool offset = sc.offset_factor != 0 || sc.offset_units != 0;
  offset ? glEnable(GL_POLYGON_OFFSET_FILL) : glDisable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(sc.offset_factor, sc.offset_units);
  glPolygonMode(GL_FRONT_AND_BACK, sc.line_mode ? GL_LINE : GL_FILL);
  glBegin(sc.gl_mode);
  for (const Vert& p : v) {
    glColor4f(p.r, p.g, p.b, p.a);
    glTexCoord2f(p.s, p.t);
    glVertex4f(p.x, p.y, p.z, p.w);
  }
  glEnd();
  if (sc.msaa) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, single_fbo);
    glBlitFramebuffer(0, 0, kW, kH, 0, 0, kW, kH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, single_fbo);
  }
  std::vector<uint8_t> out(kW * kH * 4);
  glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  return out;
}

std::vector<uint8_t> draw_pineda(const std::vector<Vert>& v, const Scene& sc, const Texture& tex) {
  const int samples = sc.msaa ? kMaxSamples : 1;
  std::vector<uint8_t> color(kW * kH * 4 * samples), resolved(kW * kH * 4);
  std::vector<uint32_t> depth(kW * kH * samples);
  Framebuffer fb;
  fb.width = kW;
  fb.height = kH;
  fb.samples = samples;
  fb.color = {color.data(), kW * 4, ColorFormat::RGBA8, {}, kW * kH * 4};
  fb.depth = {depth.data(), kW, 24, kW * kH};
  Renderer r(1);
  r.set_framebuffer(fb);
  ClearState c;
  c.color = c.depth = true;
  if (sc.blend) std::copy(kBackground, kBackground + 4, c.color_value);
  r.clear(c);
  DrawState s;
  s.viewport = {0, 0, kW, kH, 0, 1};
  s.cull_back = false;
  s.line_width = sc.line_width;
  s.point_size = sc.point_size;
  s.flat_shading = sc.flat;
  s.depth_test = sc.depth;
  s.offset_fill = sc.offset_factor != 0 || sc.offset_units != 0;
  s.offset_factor = sc.offset_factor;
  s.offset_units = sc.offset_units;
  if (sc.line_mode) s.polygon_front = s.polygon_back = PolygonMode::Line;
  s.blend = sc.blend;
  s.blend_state.src_rgb = s.blend_state.src_alpha = BlendFactor::SrcAlpha;
  s.blend_state.dst_rgb = s.blend_state.dst_alpha = BlendFactor::OneMinusSrcAlpha;
  if (sc.textured) {
    s.texture_units[0].image = tex.image;
    s.texture_units[0].sampler.min_filter = TexFilter::LinearMipmapLinear;
  }
  std::vector<ClipVertex> cv;
  for (const Vert& p : v) {
    ClipVertex x{};
    const float pos[4] = {p.x, p.y, p.z, p.w}, col[4] = {p.r, p.g, p.b, p.a};
    for (int i = 0; i < 4; ++i) {
      x.clip[i] = pos[i];
      x.color[i] = x.back_color[i] = col[i];
    }
    for (auto& t : x.texcoord) {
      t[0] = p.s;
      t[1] = p.t;
      t[2] = 0;
      t[3] = 1;
    }
    x.edge_flag = true;
    cv.push_back(x);
  }
  r.draw(s, sc.mode, cv);
  r.flush();
  if (!sc.msaa) return color;
  resolve_color(fb, {resolved.data(), kW * 4, ColorFormat::RGBA8, {}, 0});
  return resolved;
}

Texture make_texture() {
  Texture t;
  std::mt19937 rng(3);
  glGenTextures(1, &t.name);
  glBindTexture(GL_TEXTURE_2D, t.name);
  int level = 0;
  for (int size = 16; size >= 1; size /= 2, ++level) {
    TextureLevel l{size, size, {}};
    for (int i = 0; i < size * size; ++i) l.texels.edit().push_back(rng() | 0xff000000u);
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, l.texels.data());
    t.image->levels.push_back(std::move(l));
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  return t;
}

void compare(const char* name, int iterations, int vertices, bool perspective, const Scene& sc, const Texture& tex) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> pos(-1.2f, 1.2f), unit(0.f, 1.f), w_range(0.5f, 4.f);
  long coverage = 0, shaded = 0, over_one = 0;
  int max_diff = 0;
  for (int it = 0; it < iterations; ++it) {
    std::vector<Vert> v;
    for (int i = 0; i < vertices; ++i) {
      const float w = perspective ? w_range(rng) : 1.f;
      v.push_back({pos(rng) * w, pos(rng) * w, (unit(rng) * 2 - 1) * w * 0.9f, w, unit(rng), unit(rng), unit(rng),
                   sc.blend ? unit(rng) : 1.f, unit(rng) * 2, unit(rng) * 2});
    }
    const auto a = draw_gl(v, sc), b = draw_pineda(v, sc, tex);
    for (int i = 0; i < kW * kH; ++i) {
      const bool ca = sc.blend || a[i * 4 + 3], cb = sc.blend || b[i * 4 + 3];
      if (ca != cb) {
        ++coverage;
        continue;
      }
      if (!ca) continue;
      ++shaded;
      for (int c = 0; c < 4; ++c) {
        const int d = std::abs(a[i * 4 + c] - b[i * 4 + c]);
        max_diff = std::max(max_diff, d);
        over_one += d > 1;
      }
    }
  }
  std::printf("%-22s coverage differs %6ld px; of %7ld shaded px: max channel diff %3d, channels off by >1: %ld\n",
              name, coverage, shaded, max_diff, over_one);
}

}  // namespace

int main() {
  if (!init_gl()) {
    std::printf("no EGL/GL reference available\n");
    return 1;
  }
  const Texture tex = make_texture();
  compare("triangles", 300, 3, false, {GL_TRIANGLES, Primitive::Triangles}, tex);
  compare("triangles persp", 300, 3, true, {GL_TRIANGLES, Primitive::Triangles}, tex);
  compare("triangles flat", 100, 3, false, {GL_TRIANGLES, Primitive::Triangles, 1, 1, true}, tex);
  compare("depth", 100, 12, true, {GL_TRIANGLES, Primitive::Triangles, 1, 1, false, true}, tex);
  compare("polygon offset", 50, 3, true, {GL_TRIANGLES, Primitive::Triangles, 1, 1, false, true, false, false, 2, 3}, tex);
  compare("blend", 50, 3, false, {GL_TRIANGLES, Primitive::Triangles, 1, 1, false, false, false, false, 0, 0, true}, tex);
  compare("quads", 100, 4, false, {GL_QUADS, Primitive::Quads}, tex);
  compare("quad strip", 100, 6, false, {GL_QUAD_STRIP, Primitive::QuadStrip}, tex);
  compare("polygon", 100, 5, false, {GL_POLYGON, Primitive::Polygon}, tex);
  compare("polygon line mode", 100, 3, false, {GL_TRIANGLES, Primitive::Triangles, 1, 1, false, false, false, true}, tex);
  compare("lines", 300, 2, false, {GL_LINES, Primitive::Lines}, tex);
  compare("wide lines", 200, 2, false, {GL_LINES, Primitive::Lines, 3}, tex);
  compare("line strip persp", 100, 4, true, {GL_LINE_STRIP, Primitive::LineStrip}, tex);
  compare("line loop", 100, 5, false, {GL_LINE_LOOP, Primitive::LineLoop}, tex);
  compare("points", 100, 20, false, {GL_POINTS, Primitive::Points}, tex);
  compare("points size 5", 100, 20, false, {GL_POINTS, Primitive::Points, 1, 5}, tex);
  compare("textured", 100, 3, true, {GL_TRIANGLES, Primitive::Triangles, 1, 1, false, false, true}, tex);
  compare("msaa triangles", 300, 3, false,
          {GL_TRIANGLES, Primitive::Triangles, 1, 1, false, false, false, false, 0, 0, false, true}, tex);
  compare("msaa depth", 100, 12, true,
          {GL_TRIANGLES, Primitive::Triangles, 1, 1, false, true, false, false, 0, 0, false, true}, tex);
  return 0;
}
