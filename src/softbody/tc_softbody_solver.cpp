#include "softbody/tc_softbody_solver.h"

#include "softbody/tc_softbody.h"

namespace tcsb {

void solve_body_constraints(btSoftBody& body) {
  if (auto* tc = dynamic_cast<TcSoftBody*>(&body))
    tc->solve_constraints();
  else
    body.solveConstraints();
}

void step_body(btSoftBody& body, btScalar dt) {
  body.predictMotion(dt);
  solve_body_constraints(body);
  body.integrateMotion();
}

void TcSoftBodySolver::solveConstraints(btScalar /*solverdt*/) {
  // btDefaultSoftBodySolver::solveConstraints, with the dispatch above (the body set is the base class's).
  for (int i = 0; i < m_softBodySet.size(); ++i) {
    btSoftBody* body = m_softBodySet[i];
    if (body->isActive()) solve_body_constraints(*body);
  }
}

}  // namespace tcsb
