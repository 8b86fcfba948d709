#include "softbody/bullet_allocator.h"

#include <LinearMath/btAlignedAllocator.h>

#include <cstdlib>
#include <new>

namespace tcsb {
namespace {

void* malloc_or_throw(std::size_t size) {
  void* memory = std::malloc(size);
  if (memory == nullptr) throw std::bad_alloc();
  return memory;
}

void free_memory(void* memory) { std::free(memory); }

}  // namespace

void install_throwing_bullet_allocator() { btAlignedAllocSetCustom(malloc_or_throw, free_memory); }

}  // namespace tcsb
