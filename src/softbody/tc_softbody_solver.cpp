#include "softbody/tc_softbody_solver.h"

#include "softbody/compliant_solver.h"
#include "softbody/tc_softbody.h"

namespace tcsb {

void prepare_body_step(btSoftBody& body) {
  if (auto* tc = dynamic_cast<TcSoftBody*>(&body)) tc->refresh_faces();
}

void predict_body_motion(btSoftBody& body, btScalar dt) {
  if (compliant_settings(body)) keep_start_velocities(body);
  body.predictMotion(dt);
}

void solve_body_constraints(btSoftBody& body) {
  if (auto* tc = dynamic_cast<TcSoftBody*>(&body))
    tc->solve_constraints();
  else if (auto* compliant = dynamic_cast<CompliantSoftBody*>(&body))
    compliant->solve_constraints();
  else
    body.solveConstraints();
}

void step_body(btSoftBody& body, btScalar dt) {
  prepare_body_step(body);
  predict_body_motion(body, dt);
  solve_body_constraints(body);
  body.integrateMotion();
}

void TcSoftBodySolver::predictMotion(btScalar solverdt) {
  // btDefaultSoftBodySolver::predictMotion, after prepare_body_step.
  for (int i = 0; i < m_softBodySet.size(); ++i) {
    btSoftBody* body = m_softBodySet[i];
    if (!body->isActive()) continue;
    prepare_body_step(*body);
    predict_body_motion(*body, solverdt);
  }
}

void TcSoftBodySolver::solveConstraints(btScalar /*solverdt*/) {
  // btDefaultSoftBodySolver::solveConstraints, with the dispatch above (the body set is the base class's).
  for (int i = 0; i < m_softBodySet.size(); ++i) {
    btSoftBody* body = m_softBodySet[i];
    if (body->isActive()) solve_body_constraints(*body);
  }
}

}  // namespace tcsb
