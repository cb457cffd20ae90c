// The mortar pairing's search (solver/segment_bins.hpp): which segments come near a box, and which
// may meet the normal lines of a segment of A, visiting only the bins those lines cross.
#include "solver/mortar/segment_bins.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace saasgaps {
namespace {

TEST(SweptLines, NearIsTheDistanceToTheNearestLine) {
  // One vertical line through the origin: 0.5 away from (0.5, 10).
  const SweptLines vertical{{0.0, 0.0}, {0.0, 0.0}, {0.0, 1.0}, {0.0, 1.0}};
  EXPECT_FALSE(vertical.near({0.5, 10.0}, 0.4));
  EXPECT_TRUE(vertical.near({0.5, 10.0}, 0.6));
  EXPECT_TRUE(vertical.near({0.0, -1e6}, 0.0));  // both ways along the line (an interference lies behind)
  // Normals fanning from 135 to 45 degrees along (0, 0) -> (1, 0): the line of xi = 1/2 is vertical
  // through (0.5, 0); far to the left only the steep lines reach, far above or below: (-200, 1) is
  // 140.7 from every line (sampled), (-200, 210) on the line of some xi near 0.
  const SweptLines fan{{0.0, 0.0}, {1.0, 0.0}, Vec2(-1.0, 1.0).normalized(), Vec2(1.0, 1.0).normalized()};
  EXPECT_TRUE(fan.near({0.5, 100.0}, 1e-9));
  EXPECT_FALSE(fan.near({-200.0, 1.0}, 100.0));  // conservative: |h| <= distance, so 100 < 140.7 stays false
  EXPECT_TRUE(fan.near({-200.0, 210.0}, 1e-9));
  EXPECT_TRUE(fan.near({-200.0, -201.0}, 1e-9));
}

/// A straight chain of `n` unit segments along r at z = 0.
std::vector<std::array<Vec2, 2>> chain(int n) {
  std::vector<std::array<Vec2, 2>> segments;
  for (int i = 0; i < n; ++i) segments.push_back({Vec2(i, 0.0), Vec2(i + 1, 0.0)});
  return segments;
}

TEST(SegmentBins, LinesVisitOnlyTheBinsTheyCross) {
  const auto segments = chain(1000);
  const SegmentBins bins(segments);
  std::vector<std::size_t> found;
  // A vertical line through r = 500.5, from far above: segment 500 and its neighbours within a bin.
  bins.query(SweptLines{{500.5, 50.0}, {500.5, 50.0}, {0.0, 1.0}, {0.0, 1.0}}, 0.0, found);
  EXPECT_TRUE(std::binary_search(found.begin(), found.end(), std::size_t{500}));
  EXPECT_LE(found.size(), 6U);
  EXPECT_LE(bins.bins_visited(), 4U);
  // A line that misses the chain's box: nothing, without visiting a bin.
  const std::size_t visited = bins.bins_visited();
  bins.query(SweptLines{{2000.0, 0.0}, {2001.0, 0.0}, {0.0, 1.0}, {0.0, 1.0}}, 0.5, found);
  EXPECT_TRUE(found.empty());
  EXPECT_EQ(bins.bins_visited(), visited);
  // A line along the chain meets every segment: all of them (each once, in order).
  bins.query(SweptLines{{-5.0, 0.0}, {-5.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}}, 0.0, found);
  ASSERT_EQ(found.size(), segments.size());
  for (std::size_t s = 0; s < found.size(); ++s) EXPECT_EQ(found[s], s);
  // The reach: a vertical line 0.3 beyond the chain's end finds the last segment only within reach.
  bins.query(SweptLines{{1000.3, 5.0}, {1000.3, 5.0}, {0.0, 1.0}, {0.0, 1.0}}, 0.5, found);
  EXPECT_TRUE(std::binary_search(found.begin(), found.end(), std::size_t{999}));
}

TEST(SegmentBins, LinesFindEverySegmentTheyMeetOnARandomChain) {
  // Against brute force: every segment a line of the fan crosses (tested on 2001 lines) is returned.
  std::vector<std::array<Vec2, 2>> segments;
  Vec2 p(0.0, 0.0);
  for (int i = 0; i < 300; ++i) {  // a wandering chain
    const double angle = 0.7 * std::sin(0.37 * i) + 0.4 * std::cos(1.3 * i);
    const Vec2 q = p + Vec2(std::cos(angle), std::sin(angle));
    segments.push_back({p, q});
    p = q;
  }
  const SegmentBins bins(segments);
  std::vector<std::size_t> found;
  for (int trial = 0; trial < 20; ++trial) {
    const Vec2 x1(10.0 * trial, 5.0 * std::sin(trial)), x2 = x1 + Vec2(1.0, 0.3);
    const SweptLines fan{x1, x2, Vec2(std::sin(0.1 * trial), 1.0).normalized(), Vec2(-0.2, 1.0).normalized()};
    bins.query(fan, 0.0, found);
    for (std::size_t s = 0; s < segments.size(); ++s) {
      bool crossed = false;
      for (int k = 0; k <= 2000 && !crossed; ++k) {
        const double xi = k / 2000.0;
        const Vec2 x = (1.0 - xi) * fan.x1 + xi * fan.x2;
        const Vec2 n = ((1.0 - xi) * fan.n1 + xi * fan.n2).normalized();
        const auto side = [&](const Vec2& y) { return n.x() * (y - x).y() - n.y() * (y - x).x(); };
        crossed = side(segments[s][0]) * side(segments[s][1]) < 0.0;
      }
      if (crossed) {
        EXPECT_TRUE(std::binary_search(found.begin(), found.end(), s)) << "trial " << trial << ", segment " << s;
      }
    }
  }
}

}  // namespace
}  // namespace saasgaps
