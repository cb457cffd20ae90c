#include "solver/fe/element_geometry.hpp"

#include <algorithm>
#include <cassert>

namespace saasgaps {

LinearTriangle linear_triangle(const Vec2& p0, const Vec2& p1, const Vec2& p2, AnalysisType analysis,
                               double thickness) {
  const std::array<const Vec2*, 3> p{&p0, &p1, &p2};
  const double two_a = twice_signed_area(p0, p1, p2);
  assert(two_a > 0.0 && "element kernels need counter-clockwise, non-degenerate triangles");
  LinearTriangle t;
  t.area = 0.5 * two_a;
  t.r_centroid = (p0.x() + p1.x() + p2.x()) / 3.0;
  for (int i = 0; i < 3; ++i) {
    const Vec2& pj = *p[(i + 1) % 3];
    const Vec2& pk = *p[(i + 2) % 3];
    t.dN_dr[i] = (pj.y() - pk.y()) / two_a;
    t.dN_dz[i] = (pk.x() - pj.x()) / two_a;
  }
  if (analysis == AnalysisType::axisymmetric) {
    assert(t.r_centroid > 0.0);
    t.w = two_pi * t.r_centroid * t.area;
  } else {
    t.w = thickness * t.area;
  }
  return t;
}

double twice_signed_area(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
}

double min_twice_area(int node_count, const std::array<Vec2, 4>& x) {
  if (node_count == 3) return twice_signed_area(x[0], x[1], x[2]);
  const Vec2 centre = 0.25 * (x[0] + x[1] + x[2] + x[3]);
  double smallest = twice_signed_area(x[0], x[1], centre);
  for (int i = 1; i < 4; ++i) smallest = std::min(smallest, twice_signed_area(x[i], x[(i + 1) % 4], centre));
  return smallest;
}

std::array<Vec2, 5> quad_points(const std::array<Vec2, 4>& x) {
  return {x[0], x[1], x[2], x[3], 0.25 * (x[0] + x[1] + x[2] + x[3])};
}

std::array<double, 5> quad_values(const std::array<double, 4>& v) {
  return {v[0], v[1], v[2], v[3], 0.25 * (v[0] + v[1] + v[2] + v[3])};
}

std::array<double, 2> edge_weights(const Vec2& a, const Vec2& b, AnalysisType analysis, double thickness) {
  const double length = (b - a).norm();
  if (analysis == AnalysisType::axisymmetric) {
    // int N_a 2 pi r ds over a linear edge = 2 pi L (2 r_a + r_b) / 6.
    return {two_pi * length * (2.0 * a.x() + b.x()) / 6.0, two_pi * length * (a.x() + 2.0 * b.x()) / 6.0};
  }
  const double w = 0.5 * length * thickness;
  return {w, w};
}

}  // namespace saasgaps
