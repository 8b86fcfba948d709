// World budget: one node budget for every TC-SB body of a scene, spent where the BSWDF ranks detail highest across
// the bodies, not per body. Each body's controller ranks its own refine and coarse candidates (feedback/evaluator.h);
// the split finds one priority threshold for the whole world, so that every body refines what it ranks above it
// and coarsens what it ranks below it, and the bodies' node counts then add up to the budget. Each body's share
// becomes its controller's budget (Controller::set_budget), and the body's own budget policy does the rest. A
// banner far from the camera, whose blocks look small, gives its nodes to one nearby.
//
// The priorities are comparable across bodies as far as the saliency is: with the view terms a block's worth is
// its apparent size on the image times its motion share, the size absolute (pixels) but the motion normalised per
// body (feedback/saliency.h), so two bodies equally near the camera weigh alike whatever their motion.
//
// Cost: O(M log M) per split for M ranked candidates over all bodies (each body ranks at most
// 2 x max_ops_per_step), nothing per node.
#pragma once

#include <span>
#include <vector>

namespace tcsb {

/// What one body asks of the world budget: its committed nodes and the priorities of its ranked candidates.
struct BudgetDemand {
  int nodes = 0;      ///< committed simulated nodes now
  int simulated = 0;  ///< Bullet nodes now, blends included (at least `nodes`; 0: as `nodes`)
  /// Nodes the body's budget policy keeps free below its budget for operations in flight (budget_reserve in
  /// feedback/budget_policy.h): its controller's budget is its share plus this, or the policy would coarsen a block
  /// for every refine the share grants and the body would churn.
  int reserve = 0;
  int fewest = 1;               ///< nodes of its coarsest cut: no share goes below it
  int most = 1;                 ///< nodes of its finest cut (the net's): no share goes above it
  std::vector<double> refine;   ///< refine priorities, any order: each refine adds `nodes_per_operation`
  std::vector<double> coarse;   ///< coarse priorities, any order: each coarsen removes as many
  int nodes_per_operation = 3;  ///< a block of four children replaces its parent
};

/// Each body's share of `world_budget` nodes, in the order of `demands`: with τ the lowest priority for which the
/// bodies, refining every candidate ranked above τ + hysteresis / 2 and coarsening every candidate ranked below
/// τ - hysteresis / 2, fit the budget, a body's share is what it would then hold, clamped to [fewest, most]. When
/// even coarsening everything ranked does not fit, the coarsest reachable split is returned (the bodies come down
/// to it over the next steps, the split recomputed each step). Throws std::invalid_argument when world_budget < 1.
std::vector<int> split_world_budget(std::span<const BudgetDemand> demands, int world_budget, double hysteresis);

/// Holds the world to its budget while nodes move between bodies: a body whose share fell still simulates its old
/// nodes until its coarsening blends end, so the bodies whose shares rose may grow only into what the world has
/// free — the budget less every body's max(share, simulated). Growth is cut in proportion to each body's, rounding
/// down; shares that fall are kept. With it the scene's Bullet nodes stay within the budget as a single body's do
/// (feedback/budget_policy.h), at the price of a body's refinement waiting for another's coarsening.
std::vector<int> limit_growth_to_free_nodes(std::span<const BudgetDemand> demands, std::vector<int> shares,
                                            int world_budget);

class Controller;
class TcSoftBody;

/// A TC-SB body under a world budget and its controller.
struct WorldBudgetMember {
  TcSoftBody* body = nullptr;
  Controller* controller = nullptr;
};

/// Re-splits `world_budget` over `members` and gives each controller its budget: the shares of the world budget less
/// every body's reserve (split_world_budget), each plus its body's reserve, growth held to what the world has free
/// (limit_growth_to_free_nodes, on those budgets) (Controller::set_budget, effective at
/// its next before_step): call it once per step, after every member's after_step and before any before_step. A
/// member whose controller ranks nothing this boundary (Controller::budget_demand false) keeps its committed nodes.
/// The same split for the library's TreeCutDriver and the harness's scenes of many bodies.
void share_world_budget(std::span<const WorldBudgetMember> members, int world_budget, double hysteresis);

}  // namespace tcsb
