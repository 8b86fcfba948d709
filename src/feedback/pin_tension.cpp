#include "feedback/pin_tension.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tcsb {

namespace {

constexpr double kNoPin = std::numeric_limits<double>::infinity();

/// One-dimensional squared-distance transform: out[q] = min over p of (q - p)^2 + f[p], over the p where f is finite
/// (the lower envelope of the parabolas rooted there). `f` and `out` have the same size; `sites` and `bounds` are
/// scratch of that size (+1). Entries stay infinite when no f is finite.
void transform_line(const std::vector<double>& f, std::vector<double>& out, std::vector<int>& sites,
                    std::vector<double>& bounds) {
  const int n = static_cast<int>(f.size());
  int k = -1;  // the envelope's last parabola
  for (int q = 0; q < n; ++q) {
    if (f[static_cast<std::size_t>(q)] == kNoPin) continue;
    const double fq = f[static_cast<std::size_t>(q)] + double(q) * q;
    double s = -kNoPin;
    while (k >= 0) {
      const int p = sites[static_cast<std::size_t>(k)];
      s = (fq - (f[static_cast<std::size_t>(p)] + double(p) * p)) / (2.0 * (q - p));  // where q's parabola wins
      if (s > bounds[static_cast<std::size_t>(k)]) break;
      --k;
    }
    ++k;
    sites[static_cast<std::size_t>(k)] = q;
    bounds[static_cast<std::size_t>(k)] = k == 0 ? -kNoPin : s;
  }
  if (k < 0) {
    std::fill(out.begin(), out.end(), kNoPin);
    return;
  }
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (j < k && bounds[static_cast<std::size_t>(j + 1)] < q) ++j;
    const int p = sites[static_cast<std::size_t>(j)];
    out[static_cast<std::size_t>(q)] = double(q - p) * (q - p) + f[static_cast<std::size_t>(p)];
  }
}

}  // namespace

std::vector<float> pin_distances(const LodTree& tree) {
  const int w = tree.level_width(0), h = tree.level_height(0);
  const auto at = [w](int x, int y) { return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + x; };
  std::vector<double> squared(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  for (std::size_t i = 0; i < squared.size(); ++i) squared[i] = tree.nodes()[i].pinned() ? 0.0 : kNoPin;
  const int longest = std::max(w, h);
  std::vector<double> f, out;
  std::vector<int> sites(static_cast<std::size_t>(longest));
  std::vector<double> bounds(static_cast<std::size_t>(longest) + 1);
  // One pass transforms `lines` lines of `length` cells, cell (line, i) at squared[index(line, i)].
  const auto pass = [&](int lines, int length, auto index) {
    f.resize(static_cast<std::size_t>(length));
    out.resize(static_cast<std::size_t>(length));
    for (int line = 0; line < lines; ++line) {
      for (int i = 0; i < length; ++i) f[static_cast<std::size_t>(i)] = squared[index(line, i)];
      transform_line(f, out, sites, bounds);
      for (int i = 0; i < length; ++i) squared[index(line, i)] = out[static_cast<std::size_t>(i)];
    }
  };
  // Columns first, then rows over the columns' result: separable, so exact in two dimensions.
  pass(w, h, [&](int x, int y) { return at(x, y); });
  pass(h, w, [&](int y, int x) { return at(x, y); });
  std::vector<float> distance(squared.size());
  for (std::size_t i = 0; i < squared.size(); ++i)
    distance[i] =
        squared[i] == kNoPin ? std::numeric_limits<float>::infinity() : static_cast<float>(std::sqrt(squared[i]));
  return distance;
}

std::vector<float> interface_weights(const LodTree& tree, double tension) {
  std::vector<float> weight(tree.size(), 1.0f);
  if (!(tension > 0)) return weight;
  // A block's distance is its nearest leaf's: children come before their parents in id order (level by level), so
  // one pass in id order carries every minimum up.
  std::vector<float> distance = pin_distances(tree);
  distance.resize(tree.size(), std::numeric_limits<float>::infinity());
  for (std::size_t id = 0; id < tree.size(); ++id) {
    const TreeId parent = tree.nodes()[id].parent;
    if (parent != kNoTreeNode)
      distance[static_cast<std::size_t>(parent)] = std::min(distance[static_cast<std::size_t>(parent)], distance[id]);
  }
  const double side = std::max(tree.level_width(0), tree.level_height(0)) - 1;
  for (std::size_t id = 0; id < tree.size(); ++id)
    if (std::isfinite(distance[id]))
      weight[id] = static_cast<float>(1.0 + tension * side / std::max(1.0, static_cast<double>(distance[id])));
  return weight;
}

}  // namespace tcsb
