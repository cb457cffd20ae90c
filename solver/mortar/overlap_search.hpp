#pragma once
/// The pairing of a slave side A with a master side B (docs/contact-surfaces.md, section 2, "Search"):
/// which pieces of each segment of A face which segment of B, and where a node of A's normal meets B's
/// smooth curve. Each piece of A is paired with the nearest (along n) segment of B that faces it
/// (segment normals opposed); no distance limit. B's segments are found by a search over bins
/// (segment_bins.hpp), O(1) per slave segment and node where the sides face each other, and the bins
/// its normal lines cross where a piece faces nothing; or all against all, the reference the search is
/// tested against (both give the same pieces).

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "solver/base/voigt.hpp"
#include "solver/mortar/segment_bins.hpp"
#include "solver/mortar/segment_quadrature.hpp"
#include "solver/mortar/surface_geometry.hpp"

namespace saasgaps {

/// How master segments are found: by the search over bins, or by trying every one.
enum class Pairing { search, all_against_all };

/// A piece of a slave segment and the master segment facing it there.
struct Overlap {
  ParameterInterval piece;
  std::size_t master = 0;
};

/// The master side's segments with a search over them (bins), or all-against-all without.
class MasterSegments {
 public:
  /// Keeps a reference to `master`: it must outlive this.
  MasterSegments(const SurfaceGeometry& master, Pairing pairing);

  [[nodiscard]] const SurfaceGeometry& master() const { return *master_; }

  /// Calls found(near, reach, final) with the master segments near `box` inflated by `reach`, the
  /// reach doubling each time, until found returns true; after max_doublings, or once the box would
  /// cover every segment, a last call (final) with every segment that may come within `line_reach`
  /// of one of `lines` (SegmentBins::query). All against all: one final call with every segment.
  template <class F>
  void search(const Box& box, double reach, const SweptLines& lines, double line_reach, F&& found) const {
    if (!bins_) {
      candidates_ += all_.size();
      found(std::span<const std::size_t>(all_), reach, true);
      return;
    }
    for (int doubling = 0; doubling < max_doublings; ++doubling, reach *= 2.0) {
      const Box query = box.inflated(reach);
      if (query.contains(bins_->bounds())) break;
      bins_->query(query, near_);
      candidates_ += near_.size();
      if (found(std::span<const std::size_t>(near_), reach, false)) return;
    }
    bins_->query(lines, line_reach, near_);
    candidates_ += near_.size();
    found(std::span<const std::size_t>(near_), reach, true);
  }
  /// The bounding box of master segment m (the search only).
  [[nodiscard]] const Box& box(std::size_t m) const { return boxes_[m]; }
  /// Master segments handed to the callers so far (each query's, summed).
  [[nodiscard]] std::size_t candidates() const { return candidates_; }

 private:
  /// Pieces facing B near them settle within a reach of one or two segment lengths; past this many
  /// doublings the lines' own bins are cheaper than a box of 2^max_doublings segment lengths.
  static constexpr int max_doublings = 4;

  const SurfaceGeometry* master_;
  std::vector<std::size_t> all_;
  std::vector<Box> boxes_;
  std::optional<SegmentBins> bins_;
  mutable std::vector<std::size_t> near_;
  mutable std::size_t candidates_ = 0;
};

/// The pieces of slave segment x1 -> x2 (nodal normals n1, n2, segment normal ns) that face the master
/// surface, each with the nearest facing master segment, in increasing xi. Searched with a query box
/// round the slave segment, inflated until every piece of [0, 1] is settled: a piece is settled when
/// its master segment lies inside the query box (another segment nearer along n(xi) would cross the
/// line from x(xi) to that hit, which lies in the box (convex), so its bounding box overlaps the
/// query's and it was a candidate). Pieces facing nothing are settled by the final query, of every
/// segment that meets one of the slave segment's normal lines (only those can face it).
///
/// curve: when the slave segment is half `half` of a 3-node edge, that edge's curve: master nodes are
/// projected onto the curve (project_onto_curve()), where the segment's points are.
std::vector<Overlap> facing_pieces(const Vec2& x1, const Vec2& x2, const Vec2& n1, const Vec2& n2, const Vec2& ns,
                                   const MasterSegments& master_segments, const QuadraticEdge* curve = nullptr,
                                   int half = -1);

/// The distance t along the unit direction n from x to the master's smooth curve (x + t n on it,
/// t < 0 behind x; distance_to_curve()), searched like facing_pieces() with the curves' largest offset
/// from their chords as the margin; nothing when the line meets no facing segment.
std::optional<double> curve_distance(const Vec2& x, const Vec2& n, const MasterSegments& master_segments);

}  // namespace saasgaps
