#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <set>
#include <thread>
#include <utility>
#include <vector>

#include "raster/renderer.h"

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

namespace pineda::raster {
namespace {

using Piece = std::pair<size_t, size_t>;

std::vector<Piece> pieces_of(Renderer& renderer, size_t count, size_t grain) {
  std::mutex mutex;
  std::vector<Piece> pieces;
  renderer.for_each_piece(count, grain, [&](size_t begin, size_t end) {
    std::lock_guard lock(mutex);
    pieces.emplace_back(begin, end);
  });
  std::sort(pieces.begin(), pieces.end());
  return pieces;
}

TEST(RendererPieces, CoverTheRangeOnceInWholeGrains) {
  for (const int threads : {1, 2, 4}) {
    Renderer renderer(threads);
    for (const size_t grain : {size_t{1}, size_t{64}, size_t{1024}})
      for (const size_t count : {size_t{0}, size_t{1}, size_t{63}, size_t{1024}, size_t{1025}, size_t{2048},
                                 size_t{5000}, size_t{100000}}) {
        const std::vector<Piece> pieces = pieces_of(renderer, count, grain);
        SCOPED_TRACE(testing::Message() << threads << " threads, grain " << grain << ", count " << count);
        if (count == 0) {
          EXPECT_TRUE(pieces.empty());
          continue;
        }
        size_t next = 0;
        for (size_t i = 0; i < pieces.size(); ++i) {
          EXPECT_EQ(pieces[i].first, next);
          EXPECT_LT(pieces[i].first, pieces[i].second);
          if (i + 1 < pieces.size()) {
            EXPECT_EQ((pieces[i].second - pieces[i].first) % grain, 0u);
          }
          next = pieces[i].second;
        }
        EXPECT_EQ(next, count);
        const size_t grains = (count + grain - 1) / grain;
        if (threads == 1 || grains < 2) {
          EXPECT_EQ(pieces.size(), 1u);
        } else {
          EXPECT_GE(pieces.size(), 2u);  // an idle pool shares the work
        }
        EXPECT_LE(pieces.size(), size_t(threads) * 4);
      }
  }
}

#if defined(__SSE__) || defined(__x86_64__)
// The pieces compute as the caller would: under its floating-point modes, on every thread.
TEST(RendererPieces, RunUnderTheCallersFloatingPointModes) {
  Renderer renderer(2);
  const unsigned saved = _mm_getcsr();
  const unsigned modes = ((saved | 0x8040u) & ~0x6000u) | 0x2000u;  // flush to zero, denormals are zero, round down
  _mm_setcsr(modes);
  std::mutex mutex;
  std::vector<unsigned> seen;
  std::set<std::thread::id> threads;
  renderer.for_each_piece(8192, 64, [&](size_t, size_t) {
    const unsigned piece_modes = _mm_getcsr();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));  // so that both threads take pieces
    std::lock_guard lock(mutex);
    seen.push_back(piece_modes);
    threads.insert(std::this_thread::get_id());
  });
  _mm_setcsr(saved);
  ASSERT_EQ(threads.size(), 2u);
  for (const unsigned m : seen) EXPECT_EQ(m & ~0x3Fu, modes & ~0x3Fu);  // the exception flags aside
}
#endif

}  // namespace
}  // namespace pineda::raster
