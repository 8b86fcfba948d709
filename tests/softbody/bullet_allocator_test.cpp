// Bullet's allocations fail with std::bad_alloc once install_throwing_bullet_allocator() ran, instead of handing a
// null pointer to code that never checks it (a SIGSEGV later, somewhere in the solver).
#include "softbody/bullet_allocator.h"

#include <LinearMath/btAlignedAllocator.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <new>

namespace tcsb {
namespace {

TEST(BulletAllocator, FailedAllocationThrowsBadAlloc) {
  install_throwing_bullet_allocator();
  // More than any address space: malloc returns null for it on every machine.
  EXPECT_THROW(btAlignedAlloc(SIZE_MAX / 2, 16), std::bad_alloc);
}

TEST(BulletAllocator, AlignmentIsKept) {
  install_throwing_bullet_allocator();
  for (int alignment : {16, 64}) {
    void* p = btAlignedAlloc(100, alignment);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % static_cast<std::uintptr_t>(alignment), 0u);
    btAlignedFree(p);
  }
}

}  // namespace
}  // namespace tcsb
