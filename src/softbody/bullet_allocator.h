// Bullet's allocations fail loudly: Bullet 3.24 does not check what btAlignedAlloc returns, so under a memory limit
// (a container, ulimit -v) a failed allocation became a SIGSEGV somewhere inside the solver. With the allocator
// installed here it becomes std::bad_alloc, which the harness reports as a suite too large for this machine.
#pragma once

namespace tcsb {

/// Routes Bullet's raw allocations through malloc/free, as Bullet's defaults do, but throws std::bad_alloc when
/// malloc returns null. Only the unaligned functions are replaced (btAlignedAllocSetCustom): Bullet's default aligned
/// allocator still aligns on top of them exactly as before, so addresses, and with them results, are unchanged.
/// Call once, before any Bullet object exists.
void install_throwing_bullet_allocator();

}  // namespace tcsb
