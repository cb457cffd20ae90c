#pragma once
/// A uniform grid of bins over the segments of a contact surface, for the mortar pairing's search
/// (overlap_search.hpp): which segments come near a box. Building is O(m) for m segments of
/// comparable length; a query costs the bins it overlaps plus the segments it returns.
///
/// Bins are square, of side about the mean segment length, but never more than max_bins_per_segment
/// bins per segment in all (a long thin surface, or a few long segments next to many short ones,
/// get larger bins). Each segment is listed in every bin its bounding box overlaps.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "solver/base/voigt.hpp"

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

/// The lines x(xi) + t n(xi), t real, xi in [0, 1], with x(xi) = (1 - xi) x1 + xi x2 and n(xi) along
/// (1 - xi) n1 + xi n2 (n1, n2 unit, not opposite): every point that a segment of A can face along
/// its normal field (x1 = x2, n1 = n2: one node's normal line).
struct SweptLines {
  Vec2 x1, x2, n1, n2;
  /// Whether some line may pass within `radius` of c: never false when one does. With
  /// m(xi) = (1 - xi) n1 + xi n2 (|m| <= 1) the distance of line xi from c is |h(xi)| / |m(xi)|,
  ///   h(xi) = cross(m(xi), c - x(xi)),  a quadratic in xi,
  /// so a line within radius has |h| <= radius: the test is min over [0, 1] of |h| <= radius (a root,
  /// or the least of |h| at 0, 1 and the vertex).
  [[nodiscard]] bool near(const Vec2& c, double radius) const;
};

class SegmentBins {
 public:
  static constexpr double max_bins_per_segment = 4.0;

  /// segments[s] = (start, end) of segment s.
  explicit SegmentBins(std::span<const std::array<Vec2, 2>> segments);

  /// The box of every segment.
  [[nodiscard]] const Box& bounds() const { return bounds_; }

  /// The segments whose bounding box may overlap `box` (each once, in increasing order), into `out`.
  void query(const Box& box, std::vector<std::size_t>& out) const;

  /// The segments that may come within `reach` of one of `lines` (each once, in increasing order),
  /// into `out`: those listed in the bins within reach of the lines (SweptLines::near with the bin's
  /// half-diagonal plus reach), found by a flood fill over neighbouring bins from seeds that meet
  /// every connected piece of the lines' region within the grid (the bins along the two edge lines
  /// xi = 0 and xi = 1 and the grid's four corner bins: a piece that holds neither edge line ends
  /// where its lines leave the grid, through a corner). The cost is the bins the lines cross, not
  /// the whole side: a segment of A facing nothing finds nothing in the few bins its lines cross
  /// (or none, when they miss B's box), where a box doubled until it covers B returns every segment.
  void query(const SweptLines& lines, double reach, std::vector<std::size_t>& out) const;

  /// Segments returned by every query so far (the candidates a caller then checks), and bins visited.
  [[nodiscard]] std::size_t returned() const { return returned_; }
  [[nodiscard]] std::size_t bins_visited() const { return visited_; }

 private:
  [[nodiscard]] std::array<long, 2> cell(const Vec2& p) const;
  /// Starts a query: the next stamp (stamps wrap round by starting afresh).
  void next_query() const;
  /// Appends bin b's segments not yet returned by this query to out.
  void collect(std::size_t b, std::vector<std::size_t>& out) const;

  Box bounds_;
  double size_ = 1.0;
  std::array<long, 2> count_{1, 1};
  std::vector<std::size_t> start_;    // CSR: per bin, its segments at [start_[b], start_[b + 1])
  std::vector<std::size_t> segment_;
  mutable std::vector<std::uint32_t> stamp_;  // per segment: the query that last returned it
  mutable std::uint32_t queries_ = 0;
  mutable std::vector<std::uint32_t> bin_stamp_;  // per bin: the line query that last reached it
  mutable std::size_t returned_ = 0;
  mutable std::size_t visited_ = 0;
};

}  // namespace saasgaps
