#include "plot/draw/contour_bands.hpp"

#include <cmath>

namespace saasgaps::plot {

namespace {

/// Sutherland-Hodgman against the half plane where inside(v) holds, the boundary at v = level, into
/// `out` (a ValuePolygon or a ClippedTriangle).
template <typename Out, typename Inside>
void clip_into(std::span<const ValuePoint> polygon, double level, Inside inside, Out& out) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const ValuePoint& p = polygon[i];
    const ValuePoint& q = polygon[(i + 1) % n];
    const bool p_in = inside(p.v);
    const bool q_in = inside(q.v);
    if (p_in) out.push_back(p);
    if (p_in != q_in) {
      // v changes sign relative to level along p-q, so v_q != v_p.
      const double t = (level - p.v) / (q.v - p.v);
      out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y), level});
    }
  }
}

template <typename Inside>
ValuePolygon clip(const ValuePolygon& polygon, double level, Inside inside) {
  ValuePolygon out;
  clip_into(polygon, level, inside, out);
  return out.size() >= 3 ? out : ValuePolygon{};
}

}  // namespace

ValuePolygon clip_at_least(const ValuePolygon& polygon, double level) {
  return clip(polygon, level, [level](double v) { return v >= level; });
}

ValuePolygon clip_at_most(const ValuePolygon& polygon, double level) {
  return clip(polygon, level, [level](double v) { return v <= level; });
}

ValuePolygon band(const ValuePolygon& polygon, double lo, double hi) {
  return clip_at_most(clip_at_least(polygon, lo), hi);
}

ClippedTriangle clip_at_least(const ValueTriangle& triangle, double level) {
  ClippedTriangle out;
  clip_into(triangle, level, [level](double v) { return v >= level; }, out);
  if (out.size < 3) out.size = 0;
  return out;
}

void triangulate(std::span<const ValuePoint> c, std::vector<ValueTriangle>& out) {
  if (c.size() == 6 || c.size() == 8) {
    // A quadratic element's outline (corner, mid-side, corner, ...): a triangle at each corner
    // between its two mid-side nodes, then the polygon of the mid-side nodes, so that values are
    // interpolated through the mid-side nodes as the element does along its edges.
    const std::size_t n = c.size();
    std::array<ValuePoint, 4> middle{};
    for (std::size_t k = 0; k < n; k += 2) {
      out.push_back({c[(k + n - 1) % n], c[k], c[k + 1]});
      middle[k / 2] = c[k + 1];
    }
    triangulate(std::span<const ValuePoint>(middle.data(), n / 2), out);
    return;
  }
  if (c.size() == 3) {
    out.push_back({c[0], c[1], c[2]});
    return;
  }
  const auto length2 = [](const ValuePoint& p, const ValuePoint& q) {
    return (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y);
  };
  if (length2(c[0], c[2]) <= length2(c[1], c[3])) {
    out.push_back({c[0], c[1], c[2]});
    out.push_back({c[0], c[2], c[3]});
  } else {
    out.push_back({c[0], c[1], c[3]});
    out.push_back({c[1], c[2], c[3]});
  }
}

std::vector<ValuePolygon> triangulate(std::span<const ValuePoint> c) {
  std::vector<ValueTriangle> triangles;
  triangulate(c, triangles);
  std::vector<ValuePolygon> polygons;
  for (const ValueTriangle& t : triangles) polygons.emplace_back(t.begin(), t.end());
  return polygons;
}

}  // namespace saasgaps::plot
