// Running out of memory mid-run is bad input for this machine (a suite too large for its limits), not a crash: the
// user gets one line naming the suite and what was running, and exit 2.
#pragma once

#include <new>
#include <stdexcept>
#include <string>
#include <system_error>

namespace tcsb {

/// An allocation failed while `what` ran; what() is the one line to print.
class OutOfMemoryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The message for an allocation that failed while `what` ran ("suite ci, case n33/plain"), with the smallest
/// memory headroom left now (base/memory_limits.h).
std::string out_of_memory_message(const std::string& what);

/// Runs `work`; a std::bad_alloc from it (our containers, or Bullet's allocator: softbody/bullet_allocator.h), or
/// a thread that could not start for lack of resources (std::system_error EAGAIN: the feedback workers' stacks
/// under ulimit -v), becomes an OutOfMemoryError naming `what`.
template <typename Work>
decltype(auto) naming_out_of_memory(const std::string& what, Work&& work) {
  try {
    return work();
  } catch (const std::bad_alloc&) {
    throw OutOfMemoryError(out_of_memory_message(what));
  } catch (const std::system_error& e) {
    if (e.code() != std::errc::resource_unavailable_try_again) throw;
    throw OutOfMemoryError(out_of_memory_message(what + " (a thread could not start: " + e.what() + ")"));
  }
}

}  // namespace tcsb
