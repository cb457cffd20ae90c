#pragma once
/// Filled contours on linear triangles. Within a triangle the field is linear, v(x, y) = a + b x + c y,
/// so {v >= level} is the triangle cut by a straight line: clipping the polygon against that half
/// plane (Sutherland-Hodgman) with the crossing on edge p-q at p + (level - v_p)/(v_q - v_p) (q - p)
/// gives it exactly. The band between two levels is one clip after the other; a quadrilateral is
/// split into two triangles first.

#include <array>
#include <cassert>
#include <cstddef>
#include <span>
#include <vector>

#include "plot/draw/polygon.hpp"  // signed_area

namespace saasgaps::plot {

struct ValuePoint {
  double x = 0.0, y = 0.0;
  double v = 0.0;  ///< the field's value here
};

using ValuePolygon = std::vector<ValuePoint>;

/// The part of a convex polygon (with linear v) where v >= level; empty when none.
ValuePolygon clip_at_least(const ValuePolygon& polygon, double level);

/// The part where v <= level.
ValuePolygon clip_at_most(const ValuePolygon& polygon, double level);

/// The part where lo <= v <= hi.
ValuePolygon band(const ValuePolygon& polygon, double lo, double hi);

/// The triangles of a 3- or 4-node element (corners in counter-clockwise order): the quad a b c d
/// splits along its shorter diagonal, so that a distorted quad does not get a sliver triangle. A
/// quadratic element's outline of 6 or 8 points (corner, mid-side, ...) gives a triangle at each
/// corner and the triangles of its mid-side nodes' polygon (4 for a tri6, 6 for a quad8 or quad9).
std::vector<ValuePolygon> triangulate(std::span<const ValuePoint> corners);

/// For meshes of 10^6 elements: a triangle held by value (no heap per triangle), the same
/// triangles appended to `out`, and the part where v >= level clipped into a fixed buffer (a
/// triangle cut by a line has at most 4 corners). The same points as the functions above.
using ValueTriangle = std::array<ValuePoint, 3>;
void triangulate(std::span<const ValuePoint> corners, std::vector<ValueTriangle>& out);
struct ClippedTriangle {
  std::array<ValuePoint, 4> points;
  std::size_t size = 0;  ///< 0 when nothing is left (fewer than 3 corners)
  void push_back(const ValuePoint& p) {
    // A half plane cuts a triangle's boundary at most twice: at most 4 corners.
    assert(size < points.size());
    points[size++] = p;
  }
  [[nodiscard]] std::span<const ValuePoint> corners() const { return {points.data(), size}; }
};
ClippedTriangle clip_at_least(const ValueTriangle& triangle, double level);

}  // namespace saasgaps::plot
