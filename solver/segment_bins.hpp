#pragma once
/// A uniform grid of bins over the segments of a contact surface, for the mortar pairing's search
/// (mortar_coupling.cpp): which segments come near a box. Building is O(m) for m segments of
/// comparable length; a query costs the bins it overlaps plus the segments it returns.
///
/// Bins are square, of side about the mean segment length, but never more than max_bins_per_segment
/// bins per segment in all (a long thin surface, or a few long segments next to many short ones,
/// get larger bins). Each segment is listed in every bin its bounding box overlaps.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "voigt.hpp"

namespace saasgaps {

/// An axis-aligned box [lo, hi] in the (r, z) plane.
struct Box {
  Vec2 lo = Vec2::Zero();
  Vec2 hi = Vec2::Zero();
  [[nodiscard]] Box inflated(double by) const { return {(lo.array() - by).matrix(), (hi.array() + by).matrix()}; }
  [[nodiscard]] bool contains(const Vec2& p) const {
    return p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y();
  }
  [[nodiscard]] bool contains(const Box& b) const { return contains(b.lo) && contains(b.hi); }
};

/// The bounding box of a segment.
Box box_of(const Vec2& a, const Vec2& b);

class SegmentBins {
 public:
  static constexpr double max_bins_per_segment = 4.0;

  /// segments[s] = (start, end) of segment s.
  explicit SegmentBins(std::span<const std::array<Vec2, 2>> segments);

  /// The box of every segment.
  [[nodiscard]] const Box& bounds() const { return bounds_; }

  /// The segments whose bounding box may overlap `box` (each once, in increasing order), into `out`.
  void query(const Box& box, std::vector<std::size_t>& out) const;

 private:
  [[nodiscard]] std::array<long, 2> cell(const Vec2& p) const;

  Box bounds_;
  double size_ = 1.0;
  std::array<long, 2> count_{1, 1};
  std::vector<std::size_t> start_;    // CSR: per bin, its segments at [start_[b], start_[b + 1])
  std::vector<std::size_t> segment_;
  mutable std::vector<std::uint32_t> stamp_;  // per segment: the query that last returned it
  mutable std::uint32_t queries_ = 0;
};

}  // namespace saasgaps
