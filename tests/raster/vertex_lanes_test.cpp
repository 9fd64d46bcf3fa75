// transform_vertices works on batches of kVertexLanes vertices in lanes: a vertex's results
// must not depend on its batch or its lane (the same bits as transformed alone), and the
// lighting equation keeps its exact values.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "raster/vertex_lanes.h"
#include "raster/vertex_transform.h"

namespace pineda::raster {
namespace {

// Three lights of every kind (local with attenuation and a spotlight, directional, local
// again), a local viewer, two-sided lighting, colour material and a separate specular colour.
Transform lit_transform() {
  Transform t;
  t.modelview = glm::translate(glm::rotate(glm::mat4(1.f), 0.4f, glm::vec3(1, 2, 3)), glm::vec3(0.3f, -0.2f, -4.f));
  t.modelview_projection = glm::perspective(1.f, 1.25f, 0.5f, 20.f) * t.modelview;
  t.normal_matrix = glm::transpose(glm::inverse(glm::mat3(t.modelview)));
  t.normalize = true;
  Lighting& l = t.lighting;
  l.enabled = true;
  l.local_viewer = true;
  l.two_side = true;
  l.separate_specular = true;
  l.color_material.enabled = true;
  l.front.specular = {0.6f, 0.5f, 0.4f, 1.f};
  l.front.shininess = 12.f;
  l.back.diffuse = {0.3f, 0.9f, 0.2f, 0.5f};
  Light& spot = l.lights[0];
  spot.enabled = true;
  spot.position = {1.f, 2.f, -2.f, 1.f};
  spot.diffuse = {1.f, 0.8f, 0.6f, 1.f};
  spot.specular = {1.f, 1.f, 1.f, 1.f};
  spot.spot_direction = {-0.3f, -0.5f, -0.4f};
  spot.spot_cutoff = 40.f;
  spot.spot_exponent = 3.f;
  spot.linear_attenuation = 0.2f;
  Light& sun = l.lights[3];
  sun.enabled = true;
  sun.position = {-0.5f, 1.f, 1.f, 0.f};
  sun.diffuse = {0.4f, 0.4f, 0.5f, 1.f};
  sun.ambient = {0.1f, 0.1f, 0.1f, 1.f};
  Light& lamp = l.lights[7];
  lamp.enabled = true;
  lamp.position = {0.f, 0.f, -3.f, 2.f};
  lamp.specular = {0.5f, 0.5f, 0.5f, 1.f};
  lamp.quadratic_attenuation = 0.3f;
  return t;
}

std::vector<VertexInput> random_vertices(int count) {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> coordinate(-1.5f, 1.5f), unit(0.f, 1.f);
  std::vector<VertexInput> vertices(static_cast<size_t>(count));
  for (VertexInput& v : vertices) {
    for (float& c : v.position) c = coordinate(random);
    v.position[3] = 1.f + 0.2f * unit(random);
    for (float& c : v.normal) c = coordinate(random);
    for (float& c : v.color) c = unit(random);
  }
  vertices[5].normal[0] = vertices[5].normal[1] = vertices[5].normal[2] = 0.f;  // a zero normal
  return vertices;
}

TEST(VertexLanes, EveryVertexOfABatchIsLitAsIfAlone) {
  const Transform t = lit_transform();
  const int count = 2 * kVertexLanes + 5;  // two whole batches and a partial one
  const std::vector<VertexInput> vertices = random_vertices(count);
  std::vector<ClipVertex> together(static_cast<size_t>(count));
  std::memset(static_cast<void*>(together.data()), 0, together.size() * sizeof(ClipVertex));
  transform_vertices(t, vertices, std::span<ClipVertex>(together));
  int lit_front = 0;
  for (int i = 0; i < count; ++i) {
    ClipVertex alone;
    std::memset(static_cast<void*>(&alone), 0, sizeof alone);
    transform_vertices(t, std::span<const VertexInput>(&vertices[size_t(i)], 1), std::span<ClipVertex>(&alone, 1));
    EXPECT_EQ(std::memcmp(&alone, &together[size_t(i)], sizeof alone), 0) << "vertex " << i;
    lit_front += together[size_t(i)].secondary[0] > 0.f;
  }
  EXPECT_GT(lit_front, 0);  // the specular terms are exercised
}

// One directional light straight down the normal, the GL default material: emission 0 +
// ambient 0.2 * model ambient 0.2 + n.l 1 * diffuse 0.8 * light diffuse 1; alpha the diffuse's.
TEST(VertexLanes, DirectionalLightOnItsNormalGivesTheEquationsValue) {
  Transform t;
  t.lighting.enabled = true;
  t.lighting.lights[0].enabled = true;
  t.lighting.lights[0].diffuse = {1.f, 1.f, 1.f, 1.f};
  t.lighting.front.diffuse.a = 0.25f;
  std::vector<VertexInput> vertices(3);
  vertices[1].normal[2] = -1.f;  // facing away: ambient only
  vertices[2].normal[2] = 0.5f;  // n.l 0.5 without GL_NORMALIZE
  std::vector<ClipVertex> out;
  transform_vertices(t, vertices, out);
  const float ambient = 0.2f * 0.2f;
  EXPECT_EQ(out[0].color[0], ambient + 1.f * 0.8f * 1.f);
  EXPECT_EQ(out[1].color[1], ambient);
  EXPECT_EQ(out[2].color[2], ambient + 0.5f * 0.8f * 1.f);
  EXPECT_EQ(out[0].color[3], 0.25f);
}

// A spotlight adds nothing outside its cone, not even its ambient term.
TEST(VertexLanes, VerticesOutsideASpotlightsConeGetNoneOfIt) {
  Transform t;
  t.modelview = glm::mat4(1.f);
  t.lighting.enabled = true;
  Light& spot = t.lighting.lights[2];
  spot.enabled = true;
  spot.position = {0.f, 0.f, 1.f, 1.f};
  spot.spot_direction = {0.f, 0.f, -1.f};
  spot.spot_cutoff = 10.f;
  spot.ambient = {1.f, 1.f, 1.f, 1.f};
  std::vector<VertexInput> vertices(2);
  vertices[1].position[0] = 5.f;  // 79 degrees off the spotlight's axis
  std::vector<ClipVertex> out;
  transform_vertices(t, vertices, out);
  EXPECT_EQ(out[0].color[0], 0.2f * 0.2f + 0.2f * 1.f);
  EXPECT_EQ(out[1].color[0], 0.2f * 0.2f);
}

}  // namespace
}  // namespace pineda::raster
