// LargestImageOffset: the longest of a few offsets on the image, pixels, as the largest std::hypot of them all would
// give it, to the last bit, at one or two hypots instead of one each. Only the offsets whose squared length comes
// within a relative 1e-9 of the largest are measured: the squares err by a few units in the last place and hypot by
// less than one, so an offset further below cannot have the larger hypot. The coarse-jump charge takes the longest
// of up to sixteen corner moves per candidate at each evaluation (feedback/coarse_jump.h), where the hypots were a
// fifth of its cost.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>

namespace tcsb {

class LargestImageOffset {
 public:
  static constexpr int kCapacity = 16;  ///< offsets add() takes; add_length() takes any number

  /// One offset, pixels (at most kCapacity of them).
  void add(const Eigen::Vector2d& offset) {
    const double square = offset.x() * offset.x() + offset.y() * offset.y();
    if (!std::isfinite(square)) {  // (an infinite or undefined offset: measured as it is)
      add_length(std::hypot(offset.x(), offset.y()));
      return;
    }
    offsets_[count_++] = offset;
    largest_square_ = std::max(largest_square_, square);
  }
  /// A length taken as it is (the image's diagonal for a point gone behind the camera, say).
  void add_length(double length) { length_ = std::max(length_, length); }
  /// The longest of what was added (0 when nothing was), as std::max over every offset's std::hypot and every
  /// length; an undefined one (NaN) is passed over, as std::max(longest, NaN) passes it over.
  double length() const {
    // (Squares near the underflow lose digits: when the largest is that small, every offset is measured.)
    const double within = largest_square_ < 1e-200 ? 0.0 : largest_square_ * (1 - 1e-9);
    double longest = length_;
    for (int k = 0; k < count_; ++k) {
      const Eigen::Vector2d& o = offsets_[static_cast<std::size_t>(k)];
      if (o.x() * o.x() + o.y() * o.y() >= within) longest = std::max(longest, std::hypot(o.x(), o.y()));
    }
    return longest;
  }

 private:
  std::array<Eigen::Vector2d, kCapacity> offsets_;
  int count_ = 0;
  double largest_square_ = 0;
  double length_ = 0;  // the largest length added as it is
};

}  // namespace tcsb
