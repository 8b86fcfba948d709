#include "report/frames_json.h"

#include <cmath>

#include "report/json_report.h"

namespace tcsb {

namespace {

nlohmann::ordered_json points_json(const std::vector<Eigen::Vector3d>& points) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Eigen::Vector3d& p : points) {
    nlohmann::ordered_json xyz = nlohmann::ordered_json::array();
    // 10 um is far below anything a figure shows, and keeps the file a few megabytes for an 81 x 81 net.
    for (int k = 0; k < 3; ++k) xyz.push_back(json_number(std::round(p[k] * 1e5) / 1e5));
    out.push_back(std::move(xyz));
  }
  return out;
}

nlohmann::ordered_json xyz_json(const std::array<double, 3>& v) {
  return nlohmann::ordered_json{json_number(v[0]), json_number(v[1]), json_number(v[2])};
}

}  // namespace

nlohmann::ordered_json frames_header(const Suite& suite, const Context& context, int schema_version, const char* kind) {
  nlohmann::ordered_json doc;
  doc["schema_version"] = schema_version;
  doc["tool"] = "tcsb";
  doc["kind"] = kind;
  doc["context"] = context_json(context, suite);
  doc["suite"] = suite_json(suite);
  doc["dt"] = suite.world.dt;
  return doc;
}

nlohmann::ordered_json camera_lens_json(const Camera& camera) {
  return {{"up", xyz_json(camera.up)},
          {"fov_deg", json_number(camera.fov_deg)},
          {"image", {camera.width_px, camera.height_px}}};
}

nlohmann::ordered_json camera_pose_json(const Suite& suite, int steps) {
  const CameraPose pose = suite.scene.camera->pose_at(static_cast<double>(steps) * suite.world.dt);
  return {{"position", xyz_json(pose.position)}, {"target", xyz_json(pose.target)}};
}

nlohmann::ordered_json frames_json(const Suite& suite, const Context& context, const FigureFrames& f) {
  nlohmann::ordered_json doc = frames_header(suite, context, kFramesSchemaVersion, "frames");
  doc["net"] = {{"name", f.net}, {"width", f.width}, {"height", f.height}, {"extent", json_number(f.extent)}};
  doc["compression"] = f.compression;
  doc["calibrated"] = f.calibrated;
  doc["status"] = f.diverged_step ? "diverged" : "ok";
  doc["diverged_step"] = json_integer(f.diverged_step);
  doc["diverged_reason"] = f.diverged_reason;
  const bool camera = suite.scene.camera.has_value();
  if (camera) {
    // The camera's lens and image; its pose per frame, where it stood after that many steps.
    doc["camera"] = camera_lens_json(*suite.scene.camera);
    doc["uniform_grid"] = {{"width", f.uniform_width}, {"height", f.uniform_height}};
  }
  nlohmann::ordered_json frames = nlohmann::ordered_json::array();
  for (const FigureFrame& frame : f.frames) {
    nlohmann::ordered_json links = nlohmann::ordered_json::array();
    for (const FrameLink& l : frame.tcsb_links) links.push_back({l.a, l.b, link_role_name(l.role)});
    nlohmann::ordered_json j;
    j["step"] = frame.step;
    j["interpolations"] = frame.interpolations;
    j["plain"] = points_json(frame.plain);
    j["tcsb_surface"] = points_json(frame.tcsb_surface);
    j["tcsb_nodes"] = points_json(frame.tcsb_nodes);
    j["tcsb_links"] = std::move(links);
    j["tcsb_levels"] = frame.tcsb_levels;
    if (camera) {
      j["camera"] = camera_pose_json(suite, frame.step);
      j["uniform_nodes"] = points_json(frame.uniform_nodes);
    }
    frames.push_back(std::move(j));
  }
  doc["frames"] = std::move(frames);
  return doc;
}

}  // namespace tcsb
