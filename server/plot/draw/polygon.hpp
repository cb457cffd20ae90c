#pragma once
/// Polygons of points with .x and .y members (device Points, contour ValuePoints).

#include <cstddef>

namespace saasgaps::plot {

/// Signed area by the shoelace formula, A = 1/2 sum (x_i y_i+1 - x_i+1 y_i): positive when the
/// corners run counter-clockwise in a y-up frame (clockwise on a y-down device).
template <typename Polygon>
double signed_area(const Polygon& polygon) {
  double twice = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    twice += polygon[i].x * polygon[(i + 1) % n].y - polygon[(i + 1) % n].x * polygon[i].y;
  }
  return twice / 2.0;
}

}  // namespace saasgaps::plot
