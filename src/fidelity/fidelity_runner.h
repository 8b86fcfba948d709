// The fidelity pass: what TC-SB's savings cost in accuracy. For each net the full-resolution plain body (the
// reference) and every subject of fidelity_plan() start from identical initial conditions and advance in lockstep —
// same dt, warm-up and measured steps — in blocks of a few steps: the reference steps a block and records its
// frames (positions, saliency on the finest cut, energy), then each subject steps the same block and, after each
// measured step, its surface is reconstructed at full resolution and compared with the reference's frame of that
// step. Blocks keep the bodies from competing for the cache on every step (each is timed nearly as if alone), and
// interleave them finely enough that machine drift hits all alike.
//
// The pass runs after the timed repetitions and is not part of any case's timing. Its metrics are deterministic
// (the TC-SB subject at a suite target retraces the timed case exactly, as its final state hash shows), so one run
// suffices. Each body's own steps are timed (reconstruction, metrics and recording outside the timed regions), which
// gives every subject, ablations included, a time ratio to the reference's plain steps measured in the same pass.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fidelity/fidelity_result.h"
#include "net/net.h"
#include "suite/suite.h"

namespace tcsb {

/// Called after each net's pass with the net's name.
using FidelityProgress = std::function<void(const std::string& net)>;

/// Runs the fidelity pass of `suite` on `nets` (built from suite.nets, same order; a null net, another shard's, is
/// skipped). Returns no cases when fidelity_plan(suite) is empty.
FidelityResult run_fidelity(const Suite& suite, const std::vector<std::shared_ptr<const Net>>& nets,
                            const FidelityProgress& progress = {});

/// Seed of a subject: the timed TC-SB case's case_seed() for TC-SB at a suite target, so the subject retraces that
/// case; a distinct deterministic seed (past every case index) otherwise.
std::uint64_t fidelity_seed(const Suite& suite, std::size_t net, const FidelitySubjectSpec& spec);

}  // namespace tcsb
