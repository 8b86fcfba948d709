// TcSoftBodySolver: Bullet's default soft-body solver, except that a TcSoftBody solves its constraints with its own
// loop (TcSoftBody::solve_constraints: hanging interfaces) and refreshes its faces before it predicts its motion.
// Bullet's soft-body solver is pluggable: btSoftRigidDynamicsWorld takes one in its constructor and calls its
// solveConstraints for every body each step. step_body() is the same dispatch for a body stepped solo, so both paths
// share one implementation.
#pragma once

#include <BulletSoftBody/btDefaultSoftBodySolver.h>
#include <BulletSoftBody/btSoftBody.h>

namespace tcsb {

/// What a body needs before its step's predictMotion: a TC-SB body's faces rebuilt if its cut changed
/// (TcSoftBody::refresh_faces); nothing for any other body.
void prepare_body_step(btSoftBody& body);

/// A body's prediction of its step: btSoftBody::predictMotion, after keep_start_velocities() for a body of the
/// compliant material (compliant_solver.h).
void predict_body_motion(btSoftBody& body, btScalar dt);

/// A body's constraint solve: TcSoftBody::solve_constraints() for a TC-SB body, the small steps for a
/// CompliantSoftBody, btSoftBody::solveConstraints() for any other (a plain body takes Bullet's code path untouched).
void solve_body_constraints(btSoftBody& body);

/// One solo step of a lone body with collisions off, as btSoftRigidDynamicsWorld would take it: the prediction and
/// the constraint solve above, integrateMotion (after prepare_body_step).
void step_body(btSoftBody& body, btScalar dt);

/// The solver a btSoftRigidDynamicsWorld with TC-SB bodies is built with (`btSoftRigidDynamicsWorld(dispatcher,
/// broadphase, constraint_solver, configuration, &tc_solver)`): plain bodies step through it exactly as through
/// Bullet's default. A body with hanging interfaces needs it (TcSoftBody::validate() reports a world without it), and
/// it refreshes a TC-SB body's faces before each step.
class TcSoftBodySolver : public btDefaultSoftBodySolver {
 public:
  void predictMotion(btScalar solverdt) override;
  void solveConstraints(btScalar solverdt) override;
};

}  // namespace tcsb
