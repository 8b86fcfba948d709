// Public API: TcSoftBody, the TreeCut soft body, with its settings and the world parameters it reads.
//
// A TcSoftBody is a btSoftBody (public inheritance, so anything that takes a btSoftBody takes it), whose simulated
// nodes are a cut through the net's LOD tree. It starts at the finest cut, identical to a plain body of the net.
//
// The rule for btSoftBody's members. Read any of them. Between steps you may write what Bullet lets an application
// write on any soft body: node positions, velocities and forces (m_x, m_q, m_v, m_f, or addForce/addVelocity) of
// unpinned nodes. Everything structural belongs to TcSoftBody: the size and order of m_nodes and m_links, inverse
// masses (m_im), link rest lengths and constants (m_rl, m_c0, m_c1), materials, the node DBVT, the pinned nodes, and
// the faces (for Bullet's aerodynamic model, call enable_faces(): they follow the cut, refreshed before each step by
// simulate_step, a TreeCutDriver's pre-tick, or refresh_faces() from a stepping loop of your own).
// Writing those breaks the cut's invariants; validate() reports every such break, one line each, and is the check
// to run in a debug build or a test after touching a body. Change the cut only through begin_refine/begin_coarse
// (or a Controller), once per step boundary after advance_blends().
//
// Inheritance rather than composition is deliberate: the body must be a btSoftBody for Bullet's solver and
// collision code, and a wrapper would either copy Bullet's interface or expose the same object anyway.
#pragma once

#include "softbody/solver_settings.h"     // IWYU pragma: export
#include "softbody/tc_settings.h"         // IWYU pragma: export
#include "softbody/tc_softbody.h"         // IWYU pragma: export
#include "softbody/tc_softbody_solver.h"  // IWYU pragma: export
