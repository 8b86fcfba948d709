#include "suite/scene_bodies.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tcsb {

const NetSpec* net_named(const Suite& suite, const std::string& name) {
  for (const NetSpec& n : suite.nets)
    if (n.name == name) return &n;
  return nullptr;
}

namespace {

/// Whether two placed nets' rest rectangles share area, at heights within `margin` of each other.
bool rest_rectangles_overlap(const NetSpec& a, const NetSpec& b, double margin) {
  const auto apart = [](double centre_a, double size_a, double centre_b, double size_b) {
    return std::abs(centre_a - centre_b) >= 0.5 * (size_a + size_b);
  };
  return std::abs(a.elevation - b.elevation) <= margin && !apart(a.centre_x, a.size_x, b.centre_x, b.size_x) &&
         !apart(a.centre_z, a.size_z, b.centre_z, b.size_z);
}

}  // namespace

std::vector<NetSpec> scene_body_nets(const Suite& suite) {
  std::vector<NetSpec> nets;
  for (const SceneBody& body : suite.scene.bodies) {
    const NetSpec* net = net_named(suite, body.net);
    if (!net) throw std::invalid_argument("scene_body_nets: no net named \"" + body.net + "\"");
    NetSpec placed = *net;
    placed.centre_x = body.position[0];
    placed.elevation = body.position[1];
    placed.centre_z = body.position[2];
    nets.push_back(std::move(placed));
  }
  return nets;
}

void check_scene_bodies(const suite_fields::Reader& r, const Suite& s) {
  const std::vector<SceneBody>& bodies = s.scene.bodies;
  if (s.feedback.budget_scope == BudgetScope::kWorld) {
    if (bodies.empty())
      r.fail("feedback.budget_scope", "\"world\" shares one budget over a scene's TC-SB bodies: set scene.bodies");
    if (std::find(s.methods.begin(), s.methods.end(), Method::kTcsb) == s.methods.end())
      r.fail("feedback.budget_scope", "\"world\" shares one budget over TC-SB bodies: methods must contain \"tcsb\"");
  }
  if (bodies.empty()) return;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!net_named(s, bodies[i].net))
      r.fail(index_path("scene.bodies", i) + ".net", "names no net of the suite: \"" + bodies[i].net + "\"");
    if (bodies[i].net != bodies.front().net)
      r.fail(index_path("scene.bodies", i) + ".net",
             "every body must be of one net (discrete LOD's levels are fitted for one net's grids), here \"" +
                 bodies.front().net + "\"");
  }
  const std::vector<NetSpec> placed = scene_body_nets(s);
  for (std::size_t i = 0; i < placed.size(); ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (rest_rectangles_overlap(placed[i], placed[k], s.scene.margin))
        r.fail(index_path("scene.bodies", i) + ".position",
               "overlaps scene.bodies[" + std::to_string(k) + "] at step 0 (their rest rectangles meet)");
  if (!s.scene.camera) r.fail("scene.camera", "a scene of bodies is measured in pixels: set scene.camera");
  if (bodies.size() > 1 && s.scene.camera->path.size() < 2)
    r.fail("scene.camera.path",
           "a scene of " + std::to_string(bodies.size()) +
               " bodies needs a camera moving along at least two keyframes, so each body is near for a while");
}

}  // namespace tcsb
