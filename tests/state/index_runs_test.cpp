// IndexRuns: a large indexed draw's primitives in runs of a bounded number of vertices, each
// index mapped to its vertex's place in the run.
#include "state/vertex_arrays/index_runs.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <span>
#include <vector>

namespace pineda {
namespace {

std::vector<uint32_t> as_vector(std::span<const uint32_t> s) { return {s.begin(), s.end()}; }

// The primitives' indices as the runs give them back, with the runs' sizes checked.
std::vector<uint32_t> through_runs(const std::vector<uint32_t>& indices, size_t group, size_t max_vertices,
                                   size_t vertex_count, size_t* runs = nullptr) {
  IndexRuns splitter;
  std::vector<uint32_t> out;
  size_t count = 0;
  for (size_t position = 0; position < indices.size();) {
    const size_t next = splitter.next(indices, position, group, max_vertices, vertex_count);
    const std::span<const uint32_t> vertices = splitter.vertices(), run_indices = splitter.run_indices();
    EXPECT_GT(next, position);
    position = next;
    EXPECT_LE(vertices.size(), max_vertices);
    EXPECT_EQ(run_indices.size() % group, 0u);
    for (uint32_t i : run_indices) {
      EXPECT_LT(i, vertices.size());
      if (i < vertices.size()) out.push_back(vertices[i]);
    }
    ++count;
  }
  if (runs) *runs = count;
  return out;
}

TEST(IndexRuns, AGridMeshComesBackInOrderInRunsOfAtMostTheBound) {
  constexpr uint32_t kSide = 101;  // 100 x 100 cells, two triangles each
  std::vector<uint32_t> indices;
  for (uint32_t j = 0; j + 1 < kSide; ++j)
    for (uint32_t i = 0; i + 1 < kSide; ++i) {
      const uint32_t v = j * kSide + i;
      indices.insert(indices.end(), {v, v + 1, v + kSide + 1, v, v + kSide + 1, v + kSide});
    }
  size_t runs = 0;
  EXPECT_EQ(through_runs(indices, 3, 1000, kSide * kSide, &runs), indices);
  // A run's first row of cells names 202 vertices, each further row 101 new ones: 8 rows and
  // most of a ninth (1000 vertices at most) a run, 100 rows in 12 runs.
  EXPECT_EQ(runs, 12u);
}

TEST(IndexRuns, EachVertexTakesOnePlaceInARun) {
  const std::vector<uint32_t> indices = {7, 3, 9, 3, 9, 12, 7, 7, 7};
  IndexRuns splitter;
  EXPECT_EQ(splitter.next(indices, 0, 3, 100, 13), indices.size());
  EXPECT_EQ(as_vector(splitter.vertices()), (std::vector<uint32_t>{7, 3, 9, 12}));
  EXPECT_EQ(as_vector(splitter.run_indices()), (std::vector<uint32_t>{0, 1, 2, 1, 2, 3, 0, 0, 0}));
  // A second run starts with no vertex of the first.
  EXPECT_EQ(splitter.next(indices, 6, 3, 100, 13), indices.size());
  EXPECT_EQ(as_vector(splitter.vertices()), (std::vector<uint32_t>{7}));
  EXPECT_EQ(as_vector(splitter.run_indices()), (std::vector<uint32_t>{0, 0, 0}));
}

TEST(IndexRuns, ARunEndsBeforeAPrimitiveThatCouldPassTheBound) {
  const std::vector<uint32_t> indices = {0, 1, 2, 3, 4, 5, 0, 1, 2};
  IndexRuns splitter;
  // Four vertices at most: the second triangle's three new ones would make six.
  EXPECT_EQ(splitter.next(indices, 0, 3, 4, 6), 3u);
  EXPECT_EQ(as_vector(splitter.vertices()), (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(splitter.next(indices, 3, 3, 4, 6), 6u);
  EXPECT_EQ(as_vector(splitter.vertices()), (std::vector<uint32_t>{3, 4, 5}));
}

TEST(IndexRuns, ARunOfFewVerticesEndsAtEightIndicesAVertex) {
  // 100 triangles of the same three vertices, at most six vertices a run: 48 indices (16
  // triangles) a run, 7 runs.
  std::vector<uint32_t> indices;
  for (int i = 0; i < 100; ++i) indices.insert(indices.end(), {0, 1, 2});
  size_t runs = 0;
  EXPECT_EQ(through_runs(indices, 3, 6, 3, &runs), indices);
  EXPECT_EQ(runs, 7u);
}

TEST(IndexRuns, PrimitivesPastTheVerticesAndAnIncompleteLastOneAreLeftOut) {
  // Lines: (0, 1), (2, 50) names a vertex past the 10, (3, 4), then a lone 5.
  const std::vector<uint32_t> indices = {0, 1, 2, 50, 3, 4, 5};
  EXPECT_EQ(through_runs(indices, 2, 100, 10), (std::vector<uint32_t>{0, 1, 3, 4}));
  EXPECT_TRUE(through_runs({1, 2}, 3, 100, 10).empty());
}

TEST(IndexRuns, VerticesSharingASlotStillComeBackRight) {
  // 2 * 4 slots for four vertices at most: 0, 8, 16 and 24 share slot 0.
  const std::vector<uint32_t> indices = {0, 8, 16, 0, 24, 8, 16, 16, 0};
  EXPECT_EQ(through_runs(indices, 3, 4, 25), indices);
}

}  // namespace
}  // namespace pineda
