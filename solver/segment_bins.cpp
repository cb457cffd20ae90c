#include "segment_bins.hpp"

#include <algorithm>
#include <cmath>

namespace saasgaps {

Box box_of(const Vec2& a, const Vec2& b) { return {a.cwiseMin(b), a.cwiseMax(b)}; }

SegmentBins::SegmentBins(std::span<const std::array<Vec2, 2>> segments) : stamp_(segments.size(), 0) {
  if (segments.empty()) return;
  bounds_ = box_of(segments[0][0], segments[0][1]);
  double length = 0.0;
  for (const auto& s : segments) {
    bounds_.lo = bounds_.lo.cwiseMin(s[0].cwiseMin(s[1]));
    bounds_.hi = bounds_.hi.cwiseMax(s[0].cwiseMax(s[1]));
    length += (s[1] - s[0]).norm();
  }
  const Vec2 extent = bounds_.hi - bounds_.lo;
  const double m = static_cast<double>(segments.size());
  // Bins of the mean segment length, enlarged until there are at most max_bins_per_segment per segment.
  size_ = std::max(length / m, 1e-300);
  const double area_bins = (extent.x() / size_ + 1.0) * (extent.y() / size_ + 1.0);
  if (area_bins > max_bins_per_segment * m) {
    // (x / s + 1)(y / s + 1) = k m: solve the quadratic in 1 / s.
    const double k = max_bins_per_segment * m;
    const double a = extent.x() * extent.y(), bq = extent.x() + extent.y(), c = 1.0 - k;
    const double inv = a > 0.0 ? (-bq + std::sqrt(bq * bq - 4.0 * a * c)) / (2.0 * a) : (k - 1.0) / bq;
    size_ = std::max(size_, 1.0 / inv);
  }
  for (int d = 0; d < 2; ++d) count_[d] = static_cast<long>(std::floor(extent[d] / size_)) + 1;

  // Two passes: count, then fill (CSR).
  const auto bins = static_cast<std::size_t>(count_[0] * count_[1]);
  start_.assign(bins + 1, 0);
  auto for_cells = [&](const Box& b, auto&& f) {
    const auto lo = cell(b.lo), hi = cell(b.hi);
    for (long j = lo[1]; j <= hi[1]; ++j) {
      for (long i = lo[0]; i <= hi[0]; ++i) f(static_cast<std::size_t>(i + count_[0] * j));
    }
  };
  for (const auto& s : segments) for_cells(box_of(s[0], s[1]), [&](std::size_t b) { ++start_[b + 1]; });
  for (std::size_t b = 0; b < bins; ++b) start_[b + 1] += start_[b];
  segment_.resize(start_.back());
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t s = 0; s < segments.size(); ++s) {
    for_cells(box_of(segments[s][0], segments[s][1]), [&](std::size_t b) { segment_[fill[b]++] = s; });
  }
}

std::array<long, 2> SegmentBins::cell(const Vec2& p) const {
  std::array<long, 2> c{};
  for (int d = 0; d < 2; ++d) {
    const double x = std::floor((p[d] - bounds_.lo[d]) / size_);
    c[static_cast<std::size_t>(d)] = static_cast<long>(std::clamp(x, 0.0, static_cast<double>(count_[d] - 1)));
  }
  return c;
}

void SegmentBins::query(const Box& box, std::vector<std::size_t>& out) const {
  out.clear();
  if (start_.empty()) return;
  const Box clipped{box.lo.cwiseMax(bounds_.lo), box.hi.cwiseMin(bounds_.hi)};
  if (clipped.lo.x() > clipped.hi.x() || clipped.lo.y() > clipped.hi.y()) return;
  if (++queries_ == 0) {  // the stamps wrapped round: start afresh
    std::fill(stamp_.begin(), stamp_.end(), 0);
    queries_ = 1;
  }
  const auto lo = cell(clipped.lo), hi = cell(clipped.hi);
  for (long j = lo[1]; j <= hi[1]; ++j) {
    for (long i = lo[0]; i <= hi[0]; ++i) {
      const auto b = static_cast<std::size_t>(i + count_[0] * j);
      for (std::size_t e = start_[b]; e < start_[b + 1]; ++e) {
        const std::size_t s = segment_[e];
        if (stamp_[s] == queries_) continue;
        stamp_[s] = queries_;
        out.push_back(s);
      }
    }
  }
  std::sort(out.begin(), out.end());
}

}  // namespace saasgaps
