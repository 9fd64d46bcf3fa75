// Whether scenes of small primitives (Scene::small_prims) go to the pool's threads or are
// rasterized by the binning thread itself, chosen by the time per primitive each way has taken
// lately. Handing a primitive to another core moves its set-up between the cores' caches: on a
// machine where that is cheap, sharing small triangles is faster (small_tris with two threads:
// 51 ms a frame against 68 rasterized where binned, measured on this project's VM when its
// host was quiet); where it is dear, much slower (110-160 ms on the same VM, its host busy).
// Which thread rasterizes a tile never changes the image, so the choice may follow the clock.
#pragma once
#include <cstddef>

namespace pineda::raster {

class SmallPrimSharing {
 public:
  // The way for the next scene of small primitives: unmeasured ways first, then the faster,
  // with the slower one tried again every kRetryEvery scenes (the machine's load changes).
  // A way taken anew is held until a sample of it counts (record).
  bool share() const {
    if (!measured_[kLocal]) return false;
    if (!measured_[kShared]) return true;
    const bool faster_is_shared = ns_per_prim_[kShared] < ns_per_prim_[kLocal];
    return since_retry_ + 1 >= kRetryEvery ? !faster_is_shared : faster_is_shared;
  }
  // The time one such scene took the given way (from the previous hand-off to its own). The
  // first kWarmUpScenes samples after a change of way do not count: a thread that has just
  // taken scenes over runs with cold caches, and sharing measured only then looked a quarter
  // slower than rasterizing where binned on glsl_skinned, which ran in 0.75x the time shared.
  void record(bool shared, double ns, size_t prims) {
    if (prims == 0) return;
    const int way = shared ? kShared : kLocal;
    streak_ = way == last_way_ ? streak_ + 1 : 1;
    last_way_ = way;
    if (streak_ <= kWarmUpScenes) return;
    const double sample = ns / static_cast<double>(prims);
    const bool retry = measured_[kLocal] && measured_[kShared] && since_retry_ + 1 >= kRetryEvery;
    ns_per_prim_[way] = measured_[way] ? ns_per_prim_[way] + (sample - ns_per_prim_[way]) * kWeight : sample;
    measured_[way] = true;
    since_retry_ = retry ? 0 : since_retry_ + 1;
  }
  double ns_per_prim(bool shared) const { return ns_per_prim_[shared ? kShared : kLocal]; }

  static constexpr int kRetryEvery = 64;
  static constexpr int kWarmUpScenes = 2;
  static constexpr double kWeight = 0.25;  // of the newest sample in the running average

 private:
  static constexpr int kLocal = 0, kShared = 1;
  double ns_per_prim_[2] = {0.0, 0.0};
  bool measured_[2] = {false, false};
  int since_retry_ = 0;
  int last_way_ = -1, streak_ = 0;
};

}  // namespace pineda::raster
