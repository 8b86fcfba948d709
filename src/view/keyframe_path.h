// Keyframe paths: a quantity scripted over simulated time by keyframes (times strictly ascending), linear between
// two keyframes and held before the first and after the last. The one interpolation of every scripted path — the
// camera's pose, a scene's moving pins, a kinematic collider's position — so they all move by the same rule. Plain
// arithmetic, header-only, no Bullet.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace tcsb {

/// Where a time falls on a path: between keyframes `from` and `to` (equal when held at an end), `weight` of the
/// way from one to the other.
struct KeyframeSpan {
  std::size_t from = 0;
  std::size_t to = 0;
  double weight = 0;
};

/// The span of `time` on `keys` (any type with a `time` member, ascending strictly; not empty).
template <class Key>
KeyframeSpan keyframe_span(const std::vector<Key>& keys, double time) {
  if (time <= keys.front().time) return {0, 0, 0};
  if (time >= keys.back().time) return {keys.size() - 1, keys.size() - 1, 0};
  // The first keyframe later than `time`; its predecessor is at or before it (times ascend strictly).
  const auto next = std::upper_bound(keys.begin(), keys.end(), time, [](double t, const Key& k) { return t < k.time; });
  const std::size_t to = static_cast<std::size_t>(next - keys.begin());
  return {to - 1, to, (time - keys[to - 1].time) / (keys[to].time - keys[to - 1].time)};
}

/// a + w (b - a), per component: exactly a where w is 0, so a held keyframe is its own value bit for bit.
inline std::array<double, 3> lerp(const std::array<double, 3>& a, const std::array<double, 3>& b, double w) {
  return {a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2])};
}

/// One keyframe of a scripted vector: `value` (metres) at `time` seconds of simulated time.
struct VectorKey {
  double time = 0;
  std::array<double, 3> value{0, 0, 0};
};

/// The value of a scripted vector at `time` (`keys` not empty).
inline std::array<double, 3> value_at(const std::vector<VectorKey>& keys, double time) {
  const KeyframeSpan s = keyframe_span(keys, time);
  return lerp(keys[s.from].value, keys[s.to].value, s.weight);
}

}  // namespace tcsb
