// FeedbackSettings: parameters of the feedback stage (saliency, evaluator, controller), as a suite states them.
#pragma once

#include <array>

namespace tcsb {

/// What decides which nodes are refined and coarsened.
enum class PolicyKind {
  kSaliency,  ///< the BSWDF motion saliency (the paper's feedback stage)
  kRandom,    ///< seeded random choices under the same budget (an ablation, and the driver before feedback existed)
};

/// Whose node budget a TC-SB body spends.
enum class BudgetScope {
  kBody,   ///< its own: each body holds its compression target of its own nodes
  kWorld,  ///< the scene's: one budget for every TC-SB body, split each step (feedback/world_budget.h)
};

/// Feedback stage parameters. Defaults are documented in docs/design.md ("The feedback loop").
struct FeedbackSettings {
  PolicyKind policy = PolicyKind::kSaliency;
  double threshold = 0.05;           ///< hysteresis: a refine must beat the coarse it forces by this much
  int max_ops_per_step = 32;         ///< operations begun per step at most
  int evaluation_interval = 1;       ///< evaluate saliency every this many steps (its result applies one step later)
  double global_motion_scale = 1.0;  ///< m/s; saliency cap = 1 / (1 + |v_global| / scale)
  bool illumination = false;         ///< multiply by a Lambertian factor max(0, n . l)
  std::array<double, 3> light_direction{0.0, 1.0, 0.0};  ///< direction towards the light
  bool parallel = false;                                 ///< evaluate on worker threads while Bullet steps
  int threads = 1;                                       ///< worker threads when parallel
  double max_step_ms = 0.0;                              ///< time budget per step; 0 disables it
  /// Coarse priority added per 1 % of the net's extent that a coarsen would make the reconstructed surface jump
  /// (feedback/coarse_jump.h); 0 disables the charge (and its cost: positions copied, the jump computed per
  /// candidate). Against popping (issue 20, part 4); the paper has no such term.
  double popping_charge = 0.0;
  /// Weight of the level boundaries an operation adds or removes (feedback/interface_balance.h): each candidate's
  /// priority is multiplied by exp(-interface_charge x its neighbour balance / 4), so coarse regions grow together
  /// instead of as isolated blocks. 0 disables it (and its O(levels) per candidate). Issue 20; the paper has no such
  /// term.
  double interface_charge = 0.0;
  /// How much more a level boundary weighs near the pins, where the hanging cloth's tension concentrates
  /// (feedback/pin_tension.h): the interface charge of a block at distance r from the nearest pin is multiplied by
  /// 1 + interface_tension x L / max(r, 1), L the net's larger side, both in grid steps. 0 (weight 1 everywhere)
  /// disables it; it needs interface_charge > 0. Issue 20; the paper has no such term.
  double interface_tension = 0.0;
  /// Near the pins, how strongly a block leans to the level the budget forces on most of the cloth
  /// (feedback/interface_balance.h, budget_level): that level counts as one more neighbour in the interface charge,
  /// weighing pin_level_pull x (w - 1), w the pin tension's weight (0 far from the pins). At 30 % of the nodes most of
  /// the cloth is coarse, and fine patches at the pins doubled the error of a coarse cut; at 75 % most of it is fine.
  /// 0 disables it; it needs interface_tension > 0. Issue 20; the paper has no such term.
  double pin_level_pull = 0.0;
  /// Contact as an animation feature (the paper, §4: "other features need to be included"): a node Bullet found in
  /// contact with a rigid collider in the last step gets at least this saliency, whatever its motion, so detail goes
  /// to where the cloth meets the world — cloth resting on a collider has no relative motion, and the motion terms
  /// alone coarsen it. In [0, 1]; 0 disables it (and its O(contacts) per snapshot).
  double contact_saliency = 0.0;
  /// The BSWDF's view terms (the paper's omega_C and d_C, eqs. 1-2): motion is measured as the spectator sees it,
  /// through the scene's camera — a node's motion relative to its cut neighbours projected onto the image, in degrees
  /// of visual angle per second; the global-motion cap from the body's projected motion (view_motion_scale); nodes
  /// out of view get the lowest saliency. Needs a camera (the suite's scene.camera). Off: the paper's motion-only
  /// prototype, bit for bit.
  bool view = false;
  /// With view: the cap on saliency is 1 / (1 + omega / view_motion_scale), omega the body's centre of mass's speed
  /// across the image in degrees of visual angle per second.
  double view_motion_scale = 20.0;
  /// With view: the apparent size, pixels, at which a simulated node's block counts as fully visible detail. A block
  /// that looks smaller weighs in proportion (refining by visibility and apparent size, as view-dependent adaptive
  /// cloth does: Koh, Narain and O'Brien 2014), so detail a spectator could not resolve is the first to go.
  double view_detail_px = 8.0;
  /// With view: the share of a visible node's saliency that its apparent size gives it whatever it moves; the rest
  /// is its capped motion. In [0, 1]; above 0, a quiet node in view still outranks every node out of view. Which
  /// share suits which scene: docs/design.md, "The spectator".
  double view_static_share = 0.5;
  /// With view: what a node out of view or hidden keeps, as a share of the worth its block's apparent size would give
  /// it were the camera turned to it (ScreenProjection::facing_size_px; its motion is not seen, so it has none). In
  /// [0, 1]; 0, the default, gives it nothing, as the paper's view terms do. Above 0, a cloth the camera has just
  /// passed, or may turn to, keeps detail by its distance, so it does not come into view from its coarsest cut with
  /// the motion of a coarse cloth (docs/investigations/unseen-detail.md).
  double view_offscreen_share = 0.0;
  /// With view: also see the cloth as the spectator will this many seconds later (the camera's path then), a node
  /// worth the larger of the two (hidden nodes judged by the view now only). 0, the default: now only. A camera that
  /// is known to move — a scripted fly-by, a game's camera following its player — shows cloth coming into view
  /// before it does, so it is refined before it is seen (docs/investigations/unseen-detail.md).
  double view_lookahead_s = 0.0;
  /// With view: coarse priority added per pixel that a coarsen would make the reconstructed surface jump on the
  /// spectator's image now (feedback/coarse_jump.h, coarse_jump_px); 0 disables it. The popping charge as the
  /// spectator sees it: a block large on the image is coarsened last, one off-screen or far away as if uncharged, and
  /// under a world budget the nodes come from where a jump is not seen (docs/investigations/street-world-budget.md).
  double view_popping_charge = 0.0;
  /// Per body, or one budget for a scene of many bodies (a suite's scene.bodies; docs/design.md, "Scenes of many
  /// bodies"). Body: every single-cloth run, bit for bit.
  BudgetScope budget_scope = BudgetScope::kBody;
};

/// Name used in suites and reports: "saliency" or "random".
const char* policy_name(PolicyKind policy);

/// Throws std::invalid_argument naming the field ("FeedbackSettings: evaluation_interval must be >= 1, got 0") when a
/// setting is one no feedback stage can run with: the ranges the suite parser allows, for a library user who builds
/// the settings in code. make_controller checks its settings with it.
void check_feedback_settings(const FeedbackSettings& settings);

}  // namespace tcsb
