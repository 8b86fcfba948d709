#include "report/world_frames_json.h"

#include <cmath>

#include "report/frames_json.h"
#include "report/json_report.h"

namespace tcsb {

namespace {

/// 1 mm is a fifth of a pixel on the street camera's image of a banner 2 m away, and keeps a fly-by of ~90 frames of
/// sixteen 33 x 33 banners under a hundred megabytes.
constexpr double kWorldFrameUnitsPerMetre = 1e3;

nlohmann::ordered_json flat_xyz_json(const std::vector<Eigen::Vector3d>& points) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Eigen::Vector3d& p : points)
    for (int k = 0; k < 3; ++k)
      out.push_back(json_number(std::round(p[k] * kWorldFrameUnitsPerMetre) / kWorldFrameUnitsPerMetre));
  return out;
}

}  // namespace

nlohmann::ordered_json world_frames_json(const Suite& suite, const Context& context, const WorldFrames& f) {
  nlohmann::ordered_json doc = frames_header(suite, context, kWorldFramesSchemaVersion, "world_frames");
  doc["compression"] = f.compression;
  doc["camera"] = camera_lens_json(*suite.scene.camera);
  nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
  for (const NetSpec& n : f.bodies) bodies.push_back({{"net", n.name}, {"width", n.width}, {"height", n.height}});
  doc["bodies"] = std::move(bodies);
  nlohmann::ordered_json methods = nlohmann::ordered_json::array();
  for (const WorldMethodResult& m : f.methods)
    methods.push_back({{"method", m.method},
                       {"status", m.status},
                       {"diverged_step", json_integer(m.diverged_step)},
                       {"diverged_reason", m.diverged_reason},
                       {"mean_nodes", json_number(m.mean_nodes)}});
  doc["methods"] = std::move(methods);
  nlohmann::ordered_json frames = nlohmann::ordered_json::array();
  for (const WorldFrame& frame : f.frames) {
    nlohmann::ordered_json scenes = nlohmann::ordered_json::array();
    for (std::size_t m = 0; m < frame.scenes.size(); ++m) {
      const WorldFrameScene& scene = frame.scenes[m];
      nlohmann::ordered_json scene_bodies = nlohmann::ordered_json::array();
      for (std::size_t b = 0; b < scene.surfaces.size(); ++b)
        scene_bodies.push_back({{"xyz", flat_xyz_json(scene.surfaces[b])}, {"levels", scene.levels[b]}});
      scenes.push_back({{"method", f.methods[m].method}, {"nodes", scene.nodes}, {"bodies", std::move(scene_bodies)}});
    }
    frames.push_back(
        {{"step", frame.step}, {"camera", camera_pose_json(suite, frame.step)}, {"scenes", std::move(scenes)}});
  }
  doc["frames"] = std::move(frames);
  return doc;
}

}  // namespace tcsb
