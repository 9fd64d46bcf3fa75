// Deferred execution: identical output for any thread count, snapshots of draw state, and
// scenes that flush themselves when they grow large.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "raster/draw_record.h"
#include "raster/scene.h"
#include "raster/setup.h"
#include "raster/worker_pool.h"
#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

constexpr int kW = 300, kH = 211;  // partial tiles on both axes

std::shared_ptr<TextureImage> noise_texture(std::mt19937& rng) {
  auto t = std::make_shared<TextureImage>();
  for (int size = 16; size >= 1; size /= 2) {
    TextureLevel l{size, size, {}};
    for (int i = 0; i < size * size; ++i) l.texels.edit().push_back(static_cast<uint32_t>(rng()));
    t->levels.push_back(std::move(l));
  }
  return t;
}

// A busy random scene: blended, depth- and stencil-tested, textured triangles, lines, points.
void render_scene(Renderer& r, OwnedFramebuffer& fb) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> pos(-1.3f, 1.3f), unit(0.f, 1.f), w(0.5f, 3.f);
  r.set_framebuffer(fb.fb);
  clear_all(r, 0.1f, 1.0, 0);
  auto tex = noise_texture(rng);
  for (int d = 0; d < 40; ++d) {
    DrawState s = state_for(kW, kH);
    s.depth_test = d % 3 != 0;
    s.depth_func = CompareFunc::LessEqual;
    s.blend = d % 2 == 0;
    s.blend_state.src_rgb = BlendFactor::SrcAlpha;
    s.blend_state.dst_rgb = BlendFactor::OneMinusSrcAlpha;
    s.stencil_test = d % 4 == 1;
    s.stencil_front.depth_pass = StencilOp::IncrWrap;
    s.stencil_back.depth_pass = StencilOp::Invert;
    s.flat_shading = d % 5 == 0;
    s.line_width = static_cast<float>(1 + d % 3);
    s.point_size = static_cast<float>(1 + d % 4);
    if (d % 3 == 2) {
      s.texture_units[0].image = tex;
      s.texture_units[0].sampler.min_filter = TexFilter::LinearMipmapLinear;
    }
    if (d % 7 == 3) {
      s.scissor_test = true;
      s.scissor = {20, 30, 200, 150};
    }
    std::vector<ClipVertex> v;
    for (int i = 0; i < 60; ++i) {
      const float ww = w(rng);
      ClipVertex p = vertex(pos(rng) * ww, pos(rng) * ww, (unit(rng) * 2 - 1) * ww, ww, unit(rng), unit(rng), unit(rng), unit(rng));
      p.texcoord[0][0] = unit(rng) * 3;
      p.texcoord[0][1] = unit(rng) * 3;
      v.push_back(p);
    }
    const Primitive modes[] = {Primitive::Triangles, Primitive::TriangleStrip, Primitive::Lines, Primitive::Points,
                               Primitive::Quads, Primitive::LineLoop};
    r.draw(s, modes[d % 6], v);
    if (d == 20) {
      ClearState c;
      c.depth = true;
      c.scissor_test = true;
      c.scissor = {50, 50, 100, 100};
      r.clear(c);
    }
  }
  r.flush();
}

// `render` with 1, 2 and `most` threads: the same colour, depth and stencil values.
void expect_same_for_thread_counts(void (*render)(Renderer&, OwnedFramebuffer&), int most) {
  OwnedFramebuffer one(kW, kH), two(kW, kH), many(kW, kH);
  Renderer r1(1), r2(2), rn(most);
  render(r1, one);
  render(r2, two);
  render(rn, many);
  EXPECT_GT(one.count_nonzero_red(), kW * kH / 2);
  EXPECT_EQ(one.color, two.color);
  EXPECT_EQ(one.color, many.color);
  EXPECT_EQ(one.depth, two.depth);
  EXPECT_EQ(one.depth, many.depth);
  EXPECT_EQ(one.stencil_buf, two.stencil_buf);
  EXPECT_EQ(one.stencil_buf, many.stencil_buf);
}

TEST(Scene, ThreadCountsGiveIdenticalImages) { expect_same_for_thread_counts(render_scene, 4); }

// Enough primitives to fill several scenes, so that with threads each full scene runs while
// the next one bins (Renderer's running scene): draws that span scenes, state changes between
// draws, a clear among them; order-dependent results (stencil counts, blending).
void render_many_scenes(Renderer& r, OwnedFramebuffer& fb) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> pos(-1.1f, 1.1f), unit(0.f, 1.f), small(-0.08f, 0.08f);
  r.set_framebuffer(fb.fb);
  clear_all(r, 0.2f, 1.0, 0);
  for (int d = 0; d < 7; ++d) {
    DrawState s = state_for(kW, kH);
    s.depth_test = d % 2 == 0;
    s.depth_func = CompareFunc::LessEqual;
    s.blend = d % 3 == 1;
    s.blend_state.src_rgb = BlendFactor::SrcAlpha;
    s.blend_state.dst_rgb = BlendFactor::OneMinusSrcAlpha;
    s.stencil_test = true;
    s.stencil_front.depth_pass = StencilOp::IncrWrap;
    s.stencil_back.depth_pass = StencilOp::IncrWrap;
    std::vector<ClipVertex> v;
    const int triangles = 700 + 400 * d;  // 700 to 3100: some draws span two or more scenes
    for (int i = 0; i < triangles; ++i) {
      const float cx = pos(rng), cy = pos(rng), z = unit(rng) * 2 - 1;
      for (int k = 0; k < 3; ++k)
        v.push_back(vertex(cx + small(rng) * 3, cy + small(rng) * 3, z, 1.f, unit(rng), unit(rng), unit(rng), unit(rng)));
    }
    r.draw(s, Primitive::Triangles, v);
    if (d == 3) {
      ClearState c;
      c.color = true;
      c.scissor_test = true;
      c.scissor = {40, 30, 120, 90};
      r.clear(c);
    }
  }
  r.flush();
}

TEST(Scene, ScenesRunningWhileTheNextBinsGiveIdenticalImages) { expect_same_for_thread_counts(render_many_scenes, 3); }

// Triangles of about two pixels each, in scenes that fill several times over: the binning
// thread rasterizes them itself (Scene::worth_sharing), with the same result.
void render_tiny_triangles(Renderer& r, OwnedFramebuffer& fb) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> pos(-1.f, 1.f), unit(0.f, 1.f), tiny(-0.01f, 0.01f);
  r.set_framebuffer(fb.fb);
  clear_all(r, 0.3f, 1.0, 0);
  DrawState s = state_for(kW, kH);
  s.depth_test = true;
  s.blend = true;
  s.blend_state.src_rgb = BlendFactor::SrcAlpha;
  s.blend_state.dst_rgb = BlendFactor::OneMinusSrcAlpha;
  s.stencil_test = true;
  s.stencil_front.depth_pass = StencilOp::IncrWrap;
  std::vector<ClipVertex> v;
  for (int i = 0; i < 5000; ++i) {
    const float cx = pos(rng), cy = pos(rng), z = unit(rng) * 2 - 1;
    for (int k = 0; k < 3; ++k)
      v.push_back(vertex(cx + tiny(rng), cy + tiny(rng), z, 1.f, unit(rng), unit(rng), unit(rng), unit(rng)));
  }
  r.draw(s, Primitive::Triangles, v);
  r.flush();
}

TEST(Scene, TinyTrianglesGiveIdenticalImages) {
  OwnedFramebuffer one(kW, kH), two(kW, kH);
  Renderer r1(1), r2(2);
  render_tiny_triangles(r1, one);
  render_tiny_triangles(r2, two);
  EXPECT_NE(one.color, OwnedFramebuffer(kW, kH).color);
  EXPECT_EQ(one.color, two.color);
  EXPECT_EQ(one.depth, two.depth);
  EXPECT_EQ(one.stencil_buf, two.stencil_buf);
}

// Draws large enough that every thread bins and rasterizes them in a band of its own
// (parallel_binning.h), in every polygon mode: triangles of every size, many across the bands'
// edges, some clipped, indexed with indices past the end, axis-aligned rectangles as pairs of
// triangles (some in step with the draw's pairs, some not), flat shading, culling, a scissor;
// blended and stencil-counted, so that a fragment drawn twice, missed or out of order shows.
void render_large_draws(Renderer& r, OwnedFramebuffer& fb) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> pos(-1.2f, 1.2f), unit(0.f, 1.f), spread(-0.05f, 0.05f), w(0.6f, 2.f);
  r.set_framebuffer(fb.fb);
  clear_all(r, 0.4f, 1.0, 0);
  constexpr size_t kVertices = 13000;  // above ParallelBinning's kMinVertices
  const Primitive modes[] = {Primitive::Triangles, Primitive::TriangleStrip, Primitive::TriangleFan,
                             Primitive::Quads,     Primitive::QuadStrip,     Primitive::Polygon};
  for (int d = 0; d < 9; ++d) {
    DrawState s = state_for(kW, kH);
    s.depth_test = d % 2 == 0;
    s.depth_func = CompareFunc::LessEqual;
    s.blend = true;
    s.blend_state.src_rgb = BlendFactor::SrcAlpha;
    s.blend_state.dst_rgb = BlendFactor::OneMinusSrcAlpha;
    s.stencil_test = true;
    s.stencil_front.depth_pass = StencilOp::IncrWrap;
    s.stencil_back.depth_pass = StencilOp::Invert;
    s.flat_shading = d % 3 == 1;
    s.cull_face = d == 4;
    s.cull_front = d == 4;
    if (d == 5) {
      s.scissor_test = true;
      s.scissor = {25, 40, 230, 120};
    }
    std::vector<ClipVertex> v;
    const Primitive mode = d < 6 ? modes[d] : Primitive::Triangles;
    if (d == 6 || d == 7) {
      // Rectangles of 1 to 40 pixels as two triangles each, one colour per rectangle so that
      // they pair; d == 7 starts with a lone triangle, putting the pairs out of step.
      if (d == 7) v.insert(v.end(), {vertex(0, 0), vertex(0.1f, 0), vertex(0, 0.1f)});
      while (v.size() + 6 <= kVertices) {
        const float x0 = pos(rng), y0 = pos(rng), x1 = x0 + unit(rng) * 0.25f, y1 = y0 + unit(rng) * 0.4f;
        const float red = unit(rng), green = unit(rng), blue = unit(rng), alpha = unit(rng);
        auto at = [&](float x, float y) { return vertex(x, y, 0.25f, 1.f, red, green, blue, alpha); };
        v.insert(v.end(), {at(x0, y0), at(x1, y0), at(x1, y1), at(x0, y0), at(x1, y1), at(x0, y1)});
      }
    } else {
      float cx = pos(rng), cy = pos(rng);
      for (size_t i = 0; i < kVertices; ++i) {
        if (i % 40 == 0) cx = pos(rng), cy = pos(rng);  // strips wander, then jump
        const float size = i % 97 == 0 ? 20.f : 1.f;      // now and then a large one
        const float ww = i % 13 == 0 ? w(rng) : 1.f;
        v.push_back(vertex((cx + spread(rng) * size) * ww, (cy + spread(rng) * size) * ww, (unit(rng) * 2 - 1) * ww, ww,
                           unit(rng), unit(rng), unit(rng), unit(rng)));
        cx += spread(rng) * 0.3f;
        cy += spread(rng) * 0.3f;
      }
    }
    if (d == 8) {
      std::vector<uint32_t> indices;
      std::uniform_int_distribution<uint32_t> index(0, static_cast<uint32_t>(v.size()) + 50);  // some past the end
      for (size_t i = 0; i < kVertices; ++i) indices.push_back(index(rng));
      r.draw(s, mode, v, indices);
    } else {
      r.draw(s, mode, v);
    }
  }
  r.flush();
}

TEST(Scene, LargeDrawsBinnedInBandsGiveIdenticalImages) { expect_same_for_thread_counts(render_large_draws, 4); }

// A scene of 200 triangles with legs of `size` pixels: whether the pool's threads take it.
bool scene_of_triangles_is_shared(double size) {
  OwnedFramebuffer fb(256, 256);
  WorkerPool pool(2);
  Scene scene;
  scene.reset(fb.fb);
  scene.begin_draw(std::make_shared<const DrawRecord>(make_draw_record(state_for(256, 256), fb.fb)));
  SetupParams params;
  params.clip = {0, 0, 256, 256};
  for (int i = 0; i < 200; ++i) {
    const double x = 10 + i % 20 * 11, y = 10 + i / 20 * 11;
    WinVert v[3];
    const double corners[3][2] = {{x, y}, {x + size, y}, {x, y + size}};
    for (int k = 0; k < 3; ++k) {
      v[k].fx = corners[k][0];
      v[k].fy = corners[k][1];
      v[k].x = static_cast<int64_t>(v[k].fx * kSubpixelOne);
      v[k].y = static_cast<int64_t>(v[k].fy * kSubpixelOne);
    }
    PrimSetup prim;
    if (setup_triangle(v[0], v[1], v[2], params, prim)) scene.add_prim(prim);
  }
  return scene.worth_starting(pool);
}

TEST(Scene, OnlyPrimitivesWorthMovingGoToOtherThreads) {
  EXPECT_FALSE(scene_of_triangles_is_shared(2.0));  // bounding boxes of 3x3 pixels
  EXPECT_TRUE(scene_of_triangles_is_shared(10.0));  // of 11x11
}

TEST(Scene, DrawStateAndVerticesAreCopied) {
  OwnedFramebuffer fb(16, 16);
  Renderer r(2);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  {
    auto s = std::make_unique<DrawState>(state_for(16, 16));
    auto tex = std::make_shared<TextureImage>();
    tex->levels.push_back({1, 1, {0xff00ff00u}});
    s->texture_units[0].image = tex;
    s->texture_units[0].env_mode = TexEnvMode::Replace;
    std::vector<ClipVertex> v{vertex(-1, -1), vertex(1, -1), vertex(1, 1), vertex(-1, 1)};
    r.draw(*s, Primitive::Quads, v);
    s->viewport.width = 0;
    s->texture_units[0].image.reset();
    v.assign(4, vertex(5, 5));
  }
  r.flush();
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      ASSERT_EQ(fb.pixel(x, y)[0], 0);
      ASSERT_EQ(fb.pixel(x, y)[1], 255);
    }
}

// Draws of one DrawState in a row go on with one record (Scene::repeat_of_current_draw): each
// still draws its own primitives, and a change of the state in place, as a context makes it,
// reaches the next draw, as does the change back.
TEST(Scene, DrawsOfAnUnchangedStateDrawTheirOwnPrimitivesAndAChangeReachesTheNext) {
  OwnedFramebuffer fb(16, 16);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  auto rect = [](float x0, float y0, float x1, float y1, float red, float green, float blue) {
    return std::vector<ClipVertex>{vertex(x0, y0, 0, 1, red, green, blue), vertex(x1, y0, 0, 1, red, green, blue),
                                   vertex(x1, y1, 0, 1, red, green, blue), vertex(x0, y1, 0, 1, red, green, blue)};
  };
  DrawState s = state_for(16, 16);
  r.draw(s, Primitive::Quads, rect(-1, -1, 0, 1, 1, 0, 0));  // left half red
  r.draw(s, Primitive::Quads, rect(0, -1, 1, 1, 0, 1, 0));   // right half green
  s.blend = true;                                             // adding
  s.blend_state.src_rgb = s.blend_state.dst_rgb = s.blend_state.src_alpha = s.blend_state.dst_alpha = BlendFactor::One;
  r.draw(s, Primitive::Quads, rect(-1, -1, 1, 1, 0, 0, 1));  // blue over all
  s.blend = false;
  r.draw(s, Primitive::Quads, rect(-1, 0, 1, 1, 0, 0, 0));   // the top half black again
  r.flush();
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const uint8_t* p = fb.pixel(x, y);
      const bool top = y >= 8, left = x < 8;
      ASSERT_EQ(p[0], top || !left ? 0 : 255) << x << "," << y;
      ASSERT_EQ(p[1], top || left ? 0 : 255) << x << "," << y;
      ASSERT_EQ(p[2], top ? 0 : 255) << x << "," << y;
    }
}

TEST(Scene, LargeDrawsFlushOnTheirOwnAndKeepOrder) {
  OwnedFramebuffer fb(8, 8);
  Renderer r(2);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  DrawState s = state_for(8, 8);
  s.stencil_test = true;
  s.stencil_front.depth_pass = StencilOp::IncrWrap;
  std::vector<ClipVertex> v;
  constexpr int kTriangles = 70000;  // more than one scene holds
  for (int i = 0; i < kTriangles; ++i) {
    v.push_back(vertex(-1, -1));
    v.push_back(vertex(3, -1));
    v.push_back(vertex(-1, 3));
  }
  r.draw(s, Primitive::Triangles, v);
  r.flush();
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) ASSERT_EQ(fb.stencil_at(x, y), kTriangles % 256);
}

TEST(Scene, SetFramebufferCompletesPendingWork) {
  OwnedFramebuffer a(8, 8), b(8, 8);
  Renderer r(2);
  r.set_framebuffer(a.fb);
  clear_all(r, 1.f);
  r.set_framebuffer(b.fb);
  EXPECT_EQ(a.pixel(7, 7)[0], 255);
  EXPECT_EQ(b.pixel(7, 7)[0], 0);
}

}  // namespace
}  // namespace pineda::raster::test
