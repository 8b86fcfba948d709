// Figure frames: the paper's Figure 6 — plain Bullet and TC-SB side by side at fixed steps, the TC-SB surface
// reconstructed at full resolution and its links with those an operation is replacing marked — as data. The two
// bodies start from the same net and step in lockstep with the suite's settings; nothing here is timed.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "softbody/tc_softbody.h"
#include "suite/suite.h"

namespace tcsb {

/// A TC-SB link at one step: its endpoints (indices into FigureFrame::tcsb_nodes) and what it is doing.
struct FrameLink {
  int a = 0, b = 0;
  LinkRole role = LinkRole::kSteady;
};

/// Both bodies after `step` steps.
struct FigureFrame {
  int step = 0;
  std::vector<Eigen::Vector3d> plain;         ///< plain Bullet, one point per grid node (row-major, width x height)
  std::vector<Eigen::Vector3d> tcsb_surface;  ///< TC-SB reconstructed at every grid node, geomorphed as the fidelity
                                              ///< pass shows it (SurfaceMorph)
  std::vector<Eigen::Vector3d> tcsb_nodes;    ///< TC-SB's simulated (Bullet) nodes
  std::vector<int> tcsb_levels;               ///< the LOD level of each of them (0: a grid node)
  /// In a scene with a camera: the uniform grid of the budget's node count (calibrated with `calibrated`), its nodes
  /// row-major (FigureFrames::uniform_width x uniform_height); else empty.
  std::vector<Eigen::Vector3d> uniform_nodes;
  std::vector<FrameLink> tcsb_links;  ///< TC-SB's Bullet links
  int interpolations = 0;             ///< operations blending (the paper's I)
};

/// The frames of one net, or where they stopped.
struct FigureFrames {
  std::string net;
  int width = 0, height = 0;
  double extent = 0.0;  ///< metres, the net's larger side: what the fidelity pass's % of the extent is of
  double compression = 1.0;
  bool calibrated = false;                    ///< TC-SB with the suite's calibration (per-level link stiffness)
  int uniform_width = 0, uniform_height = 0;  ///< the uniform grid's, in a scene with a camera
  std::vector<FigureFrame> frames;            ///< one per requested step that was reached, in step order
  std::optional<int> diverged_step;           ///< a body diverged after this step; later frames are missing
  std::string diverged_reason;
};

/// Steps plain Bullet and TC-SB (node budget `compression` of the net's nodes, the suite's feedback; with
/// `calibrated`, the suite calibration's per-level stiffness, as the pass's tcsb_calibrated) built from the suite's
/// net `net_index` and records both after each of `steps` (ascending, distinct, >= 0; 0 is the initial state). In a
/// scene with a camera the uniform grid of the budget steps beside them (as the pass's uniform_grid, or
/// uniform_grid_calibrated with `calibrated`), so the camera's view of all three can be drawn.
/// Throws std::invalid_argument on an index or steps out of range, or `calibrated` without a calibration.
FigureFrames record_figure_frames(const Suite& suite, std::size_t net_index, double compression,
                                  const std::vector<int>& steps, bool calibrated = false);

/// The name used in JSON for a link role ("steady", "fade_in", "fade_out", "doomed", "tether").
const char* link_role_name(LinkRole role);

}  // namespace tcsb
