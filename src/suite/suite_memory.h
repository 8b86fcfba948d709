// Suite memory estimate: how many bytes a run of a suite needs at most, so a suite too large for this machine is
// rejected while it is read, in milliseconds, instead of being killed by the kernel mid-run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/memory_limits.h"
#include "suite/suite.h"

namespace tcsb {

/// Bytes a run of this suite needs at most for its largest net (all methods' bodies alive at once), an estimate
/// used to reject suites that would not fit. Only the nets the suite runs in this process count (Suite::run_units),
/// here and below: a shard of small nets fits where the whole suite would not.
std::uint64_t estimate_peak_bytes(const Suite& suite);

/// Bytes a scene adds to every body: with colliders, the body's own btSoftRigidDynamicsWorld and its sparse
/// signed-distance field at most (sdf_cells); without, nothing.
double scene_world_bytes(const SceneSettings& scene);

/// Cells of the sparse signed-distance field one world may hold at once: those covering the region around each
/// collider where nodes may ask for its distance, at scene.sdf_voxel, up to Bullet's clamp of 256 x 1024.
double sdf_cells(const SceneSettings& scene);

/// Bytes the step recorder needs: one sample per step (warm-up included) of every repetition of every case.
double recorder_peak_bytes(const Suite& suite);

/// A suite that would not fit: what is too large, and the figures for the error message.
struct MemoryShortfall {
  std::size_t net = 0;      ///< index into suite.nets of the net with the largest peak
  bool recorder = false;    ///< the step recorder (steps x cases x repetitions), not a net, needs most
  double needed = 0;        ///< estimate_peak_bytes(suite)
  double usable = 0;        ///< 80 % of the headroom: what a run may take
  MemoryHeadroom headroom;  ///< the smallest of memory_headrooms() (base/memory_limits.h)
};

/// The shortfall when the suite needs more than 80 % of the smallest headroom in `headrooms`; nothing when it fits,
/// or when there is no headroom to go by.
std::optional<MemoryShortfall> memory_shortfall(const Suite& suite, const std::vector<MemoryHeadroom>& headrooms);

/// memory_shortfall against this process's limits now (memory_headrooms()).
std::optional<MemoryShortfall> memory_shortfall(const Suite& suite);

/// "12.3 MiB" or "1.5 GiB".
std::string format_bytes(double bytes);

}  // namespace tcsb
