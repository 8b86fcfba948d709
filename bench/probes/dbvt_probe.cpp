// tcsb_dbvt_probe: how often each body's node DBVT re-inserts a leaf, and how deep its tree is, over a suite's timed
// window (docs/methodology.md, "Where Bullet's extra time goes").
//
// Usage: tcsb_dbvt_probe SUITE NET_INDEX COMPRESSION [RESTORE_ORDER [SHUFFLE_LINKS [PER_STEP]]]   (RESTORE_ORDER 0 or
// 1: tcsb.restore_order, with restore_order_min_nodes 0; omitted or -1: the suite's settings. SHUFFLE_LINKS 1: the
// stock bodies' links are put in a random order first, by Bullet's btSoftBody::randomizeConstraints(), to see what
// the link order alone does to their motion. PER_STEP 1: each timed step's re-inserts too, one line a step, to see
// when they come). Runs TC-SB, plain_equal and plain on the net, one after the other,
// the feedback on the simulation thread, for the suite's warm-up and timed steps.
//
// A leaf's box changes only when btDbvt::update(leaf, volume, velocity, margin) finds the node outside it and
// re-inserts the leaf (removal, then a descent from the root), and collisions are off (m_cfg.collisions = 0), so the
// tree never feeds back into the physics. A re-insert is counted for a node simulated before and after a step whose
// leaf is the same object and whose box changed; leaves inserted by operations during the step are not counted.
// Every 10 timed steps the tree's mean and maximum leaf depth and the summed surface area of its internal boxes are
// sampled; their means over the window are printed.
#include <BulletCollision/BroadphaseCollision/btDbvt.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "case/case_body.h"
#include "net/net.h"
#include "scene/scene_world.h"
#include "suite/suite.h"

namespace {

using namespace tcsb;

struct TreeShape {
  long depth_sum = 0;
  int max_depth = 0;
  int leaves = 0;
  double area = 0;  // internal boxes' surface areas, summed
};

void measure(const btDbvtNode* n, int depth, TreeShape& shape) {
  if (n->isleaf()) {
    shape.depth_sum += depth;
    shape.max_depth = std::max(shape.max_depth, depth);
    ++shape.leaves;
    return;
  }
  const btVector3 e = n->volume.Extents() * 2;
  shape.area += 2 * (e.x() * e.y() + e.y() * e.z() + e.z() * e.x());
  measure(n->childs[0], depth + 1, shape);
  measure(n->childs[1], depth + 1, shape);
}

const char* name_of(Method m) {
  switch (m) {
    case Method::kTcsb: return "tcsb";
    case Method::kPlainEqual: return "plain_equal";
    default: return "plain";
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr,
                 "usage: tcsb_dbvt_probe SUITE NET_INDEX COMPRESSION [RESTORE_ORDER [SHUFFLE_LINKS [PER_STEP]]]\n");
    return 2;
  }
  Suite suite = parse_suite(argv[1]);
  const auto net_index = static_cast<std::size_t>(std::atoi(argv[2]));
  const double compression = std::atof(argv[3]);
  suite.feedback.parallel = false;
  if (argc > 4 && std::atoi(argv[4]) >= 0) {
    suite.tcsb.restore_order = std::atoi(argv[4]) != 0;
    suite.tcsb.restore_order_min_nodes = 0;
  }
  const bool shuffle_links = argc > 5 && std::atoi(argv[5]) != 0;
  const bool per_step = argc > 6 && std::atoi(argv[6]) != 0;
  const int warmup = suite.warmup_steps;
  const int steps = suite.steps;
  auto net = std::make_shared<const Net>(suite.nets.at(net_index));
  const btScalar dt = static_cast<btScalar>(suite.world.dt);
  for (const Method method : {Method::kTcsb, Method::kPlainEqual, Method::kPlain}) {
    SceneWorld world(suite.world);
    CaseKey key{net_index, method, std::nullopt, 0};
    if (method != Method::kPlain) key.compression = compression;
    auto body = make_case_body(suite, key, world, net, suite.seed);
    const btSoftBody& bullet = body->bullet();
    TcSoftBody* tc = body->tc();
    if (shuffle_links && tc == nullptr) const_cast<btSoftBody&>(bullet).randomizeConstraints();  // a stock body
    using Leaves = std::map<int, std::pair<const btDbvtNode*, btDbvtAabbMm>>;  // tree id -> (leaf, box)
    Leaves before;
    long reinserts = 0, node_steps = 0;
    std::map<int, std::pair<long, long>> by_level;  // LOD level -> (re-inserts, node-steps)
    double depth = 0, max_depth = 0, area = 0, nodes = 0;
    int samples = 0;
    for (int s = 0; s < warmup + steps; ++s) {
      body->step(dt);
      Leaves after;
      for (int i = 0; i < bullet.m_nodes.size(); ++i)
        after[tc ? tc->tree_id(i) : i] = {bullet.m_nodes[i].m_leaf, bullet.m_nodes[i].m_leaf->volume};
      if (s >= warmup) {
        const long reinserts_before = reinserts;
        for (const auto& [id, leaf] : after) {
          const auto it = before.find(id);
          if (it == before.end() || it->second.first != leaf.first) continue;  // inserted during this step
          const bool moved = std::memcmp(&it->second.second, &leaf.second, sizeof(btDbvtAabbMm)) != 0;
          reinserts += moved;
          ++node_steps;
          auto& level = by_level[tc ? net->lod().nodes()[static_cast<std::size_t>(id)].level : 0];
          level.first += moved;
          ++level.second;
        }
        if (per_step)
          std::printf("%-11s step %d: %d nodes, %ld re-inserts\n", name_of(method), s, bullet.m_nodes.size(),
                      reinserts - reinserts_before);
        if ((s - warmup) % 10 == 0) {
          TreeShape shape;
          measure(bullet.m_ndbvt.m_root, 0, shape);
          depth += static_cast<double>(shape.depth_sum) / shape.leaves;
          max_depth += shape.max_depth;
          area += shape.area;
          nodes += bullet.m_nodes.size();
          ++samples;
        }
      }
      before = std::move(after);
    }
    std::printf("%-11s%s net %s: %.0f nodes, re-inserts per step %.1f (%.2f %% of node-steps); leaf depth mean %.2f, "
                "max %.1f (log2 N %.2f); internal box area %.0f\n",
                name_of(method), shuffle_links && tc == nullptr ? " (links shuffled)" : "", net->spec().name.c_str(),
                nodes / samples, static_cast<double>(reinserts) / steps,
                100.0 * static_cast<double>(reinserts) / static_cast<double>(node_steps), depth / samples,
                max_depth / samples, std::log2(nodes / samples), area / samples);
    if (tc)
      for (const auto& [level, count] : by_level)
        std::printf("  level %d: %.1f nodes, %.2f %% re-inserted per step\n", level,
                    static_cast<double>(count.second) / steps,
                    100.0 * static_cast<double>(count.first) / static_cast<double>(count.second));
  }
  return 0;
}
