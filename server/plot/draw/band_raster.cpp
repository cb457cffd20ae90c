#include "plot/draw/band_raster.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>

namespace saasgaps::plot {

namespace {

std::uint32_t opaque_pixel(Rgb c) {
  const auto byte = [](double v) { return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  return 0xFF000000U | (byte(c.r) << 16) | (byte(c.g) << 8) | byte(c.b);
}

/// x where the edge a-b (a.y < b.y) crosses the row at y. Always from the upper endpoint, so both
/// triangles of a shared edge get the same x to the last bit.
double edge_x(const ValuePoint& a, const ValuePoint& b, double y) {
  return a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
}

/// First index whose pixel centre (index + 1/2) is >= t, clamped to 0 .. limit.
int first_centre_at_or_after(double t, int limit) {
  const double i = std::ceil(t - 0.5);
  return static_cast<int>(std::clamp(i, 0.0, static_cast<double>(limit)));
}

}  // namespace

int band_of(const std::vector<double>& levels, double v) {
  // The levels strictly inside (l_1 .. l_n-1) that are <= v: a value below l_1 is band 0, one at or
  // above l_n-1 the top band, whatever it is outside the range.
  if (levels.size() <= 2) return 0;
  return static_cast<int>(std::upper_bound(levels.begin() + 1, levels.end() - 1, v) - (levels.begin() + 1));
}

std::optional<std::array<Point, 2>> iso_segment(const ValueTriangle& t, double level) {
  std::array<Point, 2> ends;
  int found = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const ValuePoint& p = t[i];
    const ValuePoint& q = t[(i + 1) % 3];
    // The crossing rule of clip_at_least: an edge whose ends lie on different sides of v >= level.
    if ((p.v >= level) != (q.v >= level)) {
      const double s = (level - p.v) / (q.v - p.v);
      ends[found++ & 1] = {p.x + s * (q.x - p.x), p.y + s * (q.y - p.y)};
    }
  }
  // A triangle's boundary changes side an even number of times: 0 or 2.
  if (found != 2) return std::nullopt;
  return ends;
}

BandRaster::BandRaster(int width, int height, std::vector<double> levels, const std::vector<Rgb>& colors)
    : width_(width), height_(height), levels_(std::move(levels)) {
  assert(levels_.size() >= 2 && colors.size() == levels_.size() - 1);  // one colour per band
  for (const Rgb& c : colors) pixels_of_band_.push_back(opaque_pixel(c));
  surface_.reset(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  if (const cairo_status_t s = cairo_surface_status(surface_.get()); s != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("cannot create the band image: ") + cairo_status_to_string(s));
  }
  cairo_surface_flush(surface_.get());
  stride_ = cairo_image_surface_get_stride(surface_.get());
  data_ = cairo_image_surface_get_data(surface_.get());
}

cairo_surface_t* BandRaster::surface() {
  cairo_surface_mark_dirty(surface_.get());
  return surface_.get();
}

void BandRaster::fill(const ValueTriangle& triangle) {
  std::array<ValuePoint, 3> p = triangle;
  std::sort(p.begin(), p.end(), [](const ValuePoint& a, const ValuePoint& b) { return a.y < b.y; });
  const int row_begin = first_centre_at_or_after(p[0].y, height_);
  const int row_end = first_centre_at_or_after(p[2].y, height_);
  if (row_begin >= row_end) return;
  // v = p0.v + b (x - p0.x) + c (y - p0.y), from the two edges out of p0.
  const double x1 = p[1].x - p[0].x, y1 = p[1].y - p[0].y, v1 = p[1].v - p[0].v;
  const double x2 = p[2].x - p[0].x, y2 = p[2].y - p[0].y, v2 = p[2].v - p[0].v;
  const double det = x1 * y2 - x2 * y1;
  if (det == 0.0 || !std::isfinite(det)) return;  // collinear corners cover no area
  const double b = (v1 * y2 - v2 * y1) / det, c = (x1 * v2 - x2 * v1) / det;
  // One band over the whole triangle (most triangles of a fine mesh): no value per pixel.
  const int low_band = band_of(levels_, std::min({p[0].v, p[1].v, p[2].v}));
  const int high_band = band_of(levels_, std::max({p[0].v, p[1].v, p[2].v}));
  for (int j = row_begin; j < row_end; ++j) {
    const double y = j + 0.5;
    const double xa = edge_x(p[0], p[2], y);
    const double xb = y < p[1].y ? edge_x(p[0], p[1], y) : edge_x(p[1], p[2], y);
    const int i_begin = first_centre_at_or_after(std::min(xa, xb), width_);
    const int i_end = first_centre_at_or_after(std::max(xa, xb), width_);
    auto* row = reinterpret_cast<std::uint32_t*>(data_ + static_cast<std::ptrdiff_t>(j) * stride_);
    if (low_band == high_band) {
      std::fill(row + i_begin, row + i_end, pixels_of_band_[low_band]);
      continue;
    }
    for (int i = i_begin; i < i_end; ++i) {
      const double v = p[0].v + b * (i + 0.5 - p[0].x) + c * (y - p[0].y);
      row[i] = pixels_of_band_[band_of(levels_, v)];
    }
  }
}

}  // namespace saasgaps::plot
