// The heap a process holds now (glibc's mallinfo2: in-use chunks and mmapped blocks), for the tests that check the
// memory estimate (suite/suite_memory.h) bounds what a run really takes.
#pragma once

#include <malloc.h>

#include <cstddef>

namespace tcsb::testing {

inline std::size_t heap_in_use() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

}  // namespace tcsb::testing
