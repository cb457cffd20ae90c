#include "solver/mortar/segment_bins.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace saasgaps {

Box box_of(const Vec2& a, const Vec2& b) { return {a.cwiseMin(b), a.cwiseMax(b)}; }

namespace {
double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
}  // namespace

bool SweptLines::near(const Vec2& c, double radius) const {
  // h(xi) = cross(n1 + xi e, w - xi d) = h0 + h1 xi + h2 xi^2, e = n2 - n1, w = c - x1, d = x2 - x1.
  const Vec2 e = n2 - n1, w = c - x1, d = x2 - x1;
  const double h0 = cross(n1, w), h1 = cross(e, w) - cross(n1, d), h2 = -cross(e, d);
  const auto h = [&](double xi) { return h0 + xi * (h1 + xi * h2); };
  double lo = std::min(h(0.0), h(1.0)), hi = std::max(h(0.0), h(1.0));
  if (h2 != 0.0) {
    const double vertex = -h1 / (2.0 * h2);
    if (vertex > 0.0 && vertex < 1.0) {
      lo = std::min(lo, h(vertex));
      hi = std::max(hi, h(vertex));
    }
  }
  // Between its extremes on [0, 1] a continuous h takes every value: a root when they differ in sign.
  return lo <= radius && hi >= -radius;
}

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
  bin_stamp_.assign(bins, 0);
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

void SegmentBins::next_query() const {
  if (++queries_ == 0) {  // the stamps wrapped round: start afresh
    std::fill(stamp_.begin(), stamp_.end(), 0);
    std::fill(bin_stamp_.begin(), bin_stamp_.end(), 0);
    queries_ = 1;
  }
}

void SegmentBins::collect(std::size_t b, std::vector<std::size_t>& out) const {
  ++visited_;
  for (std::size_t e = start_[b]; e < start_[b + 1]; ++e) {
    const std::size_t s = segment_[e];
    if (stamp_[s] == queries_) continue;
    stamp_[s] = queries_;
    out.push_back(s);
  }
}

void SegmentBins::query(const Box& box, std::vector<std::size_t>& out) const {
  out.clear();
  if (start_.empty()) return;
  const Box clipped{box.lo.cwiseMax(bounds_.lo), box.hi.cwiseMin(bounds_.hi)};
  if (clipped.lo.x() > clipped.hi.x() || clipped.lo.y() > clipped.hi.y()) return;
  next_query();
  const auto lo = cell(clipped.lo), hi = cell(clipped.hi);
  for (long j = lo[1]; j <= hi[1]; ++j) {
    for (long i = lo[0]; i <= hi[0]; ++i) collect(static_cast<std::size_t>(i + count_[0] * j), out);
  }
  returned_ += out.size();
  std::sort(out.begin(), out.end());
}

void SegmentBins::query(const SweptLines& lines, double reach, std::vector<std::size_t>& out) const {
  out.clear();
  if (start_.empty()) return;
  next_query();
  // Points up to `reach` outside the grid fall into its edge bins (cell() clamps), which stay within
  // reach of where they were: so the grid is walked as if inflated by reach, bins tested with their
  // half-diagonal plus reach.
  const double radius = std::sqrt(0.5) * size_ + reach;
  const Vec2 grid_hi = bounds_.lo + size_ * Vec2(static_cast<double>(count_[0]), static_cast<double>(count_[1]));
  const Box grid = Box{bounds_.lo, grid_hi}.inflated(reach);
  std::vector<std::array<long, 2>> stack;
  const auto visit = [&](const std::array<long, 2>& c) {
    if (c[0] < 0 || c[1] < 0 || c[0] >= count_[0] || c[1] >= count_[1]) return;
    const auto b = static_cast<std::size_t>(c[0] + count_[0] * c[1]);
    if (bin_stamp_[b] == queries_) return;
    const Vec2 centre = bounds_.lo + size_ * Vec2(static_cast<double>(c[0]) + 0.5, static_cast<double>(c[1]) + 0.5);
    if (!lines.near(centre, radius)) return;
    bin_stamp_[b] = queries_;
    stack.push_back(c);
  };
  // Seeds: the bins along the edge lines within the (inflated) grid, sampled every half bin so that
  // consecutive samples fall in the same or neighbouring bins; and the four corner bins.
  for (const auto& [x, n] : {std::pair{lines.x1, lines.n1}, std::pair{lines.x2, lines.n2}}) {
    double t_lo = -std::numeric_limits<double>::infinity(), t_hi = std::numeric_limits<double>::infinity();
    for (int d = 0; d < 2; ++d) {  // the slab method: the t where x + t n is inside the grid along d
      if (n[d] == 0.0) {
        if (x[d] < grid.lo[d] || x[d] > grid.hi[d]) t_lo = std::numeric_limits<double>::infinity();
        continue;
      }
      const double a = (grid.lo[d] - x[d]) / n[d], b = (grid.hi[d] - x[d]) / n[d];
      t_lo = std::max(t_lo, std::min(a, b));
      t_hi = std::min(t_hi, std::max(a, b));
    }
    if (!(t_lo <= t_hi)) continue;
    const double step = 0.5 * size_;
    const auto samples = static_cast<long>(std::ceil((t_hi - t_lo) / step));
    for (long k = 0; k <= samples; ++k) visit(cell(x + std::min(t_lo + static_cast<double>(k) * step, t_hi) * n));
  }
  for (const long j : {0L, count_[1] - 1}) {
    for (const long i : {0L, count_[0] - 1}) visit({i, j});
  }
  // The flood: a connected piece of the region meets a connected set of bins (neighbours by edge or
  // corner), each within reach.
  while (!stack.empty()) {
    const std::array<long, 2> c = stack.back();
    stack.pop_back();
    collect(static_cast<std::size_t>(c[0] + count_[0] * c[1]), out);
    for (long dj = -1; dj <= 1; ++dj) {
      for (long di = -1; di <= 1; ++di) {
        if (di != 0 || dj != 0) visit({c[0] + di, c[1] + dj});
      }
    }
  }
  returned_ += out.size();
  std::sort(out.begin(), out.end());
}

}  // namespace saasgaps
