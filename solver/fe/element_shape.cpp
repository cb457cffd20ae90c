#include "solver/fe/element_shape.hpp"

#include <cmath>
#include <sstream>

#include "solver/fe/element_geometry.hpp"

namespace saasgaps {

namespace {

std::string number(double v) {
  std::ostringstream out;
  out.precision(6);
  out << v;
  return out.str();
}

/// Twice the signed area of the corner polygon (shoelace).
double twice_corner_area(const ElementFamily& f, const std::array<Vec2, max_element_nodes>& x) {
  double a = 0.0;
  for (int k = 0; k < f.corner_count; ++k) {
    const Vec2& p = x[static_cast<std::size_t>(k)];
    const Vec2& q = x[static_cast<std::size_t>((k + 1) % f.corner_count)];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a;
}

/// The report's rule on the corners alone.
std::optional<ShapeProblem> report_element_problem(const ElementFamily& f, const std::array<Vec2, max_element_nodes>& x) {
  std::array<Vec2, 4> corners;
  for (std::size_t k = 0; k < 4; ++k) corners[k] = k < static_cast<std::size_t>(f.corner_count) ? x[k] : Vec2::Zero();
  if (min_twice_area(f.corner_count, corners) > 0.0) return std::nullopt;
  ShapeProblem p;
  p.value = 0.5 * twice_corner_area(f, x);
  std::array<Vec2, 4> reversed = corners;
  for (int k = 0; k < f.corner_count; ++k) reversed[static_cast<std::size_t>(f.corner_count - 1 - k)] = corners[static_cast<std::size_t>(k)];
  p.kind = min_twice_area(f.corner_count, reversed) > 0.0 ? ShapeProblem::Kind::clockwise : ShapeProblem::Kind::degenerate;
  return p;
}

}  // namespace

std::array<int, max_element_nodes> reversed_order(ElementType type) {
  const ElementFamily& f = family(type);
  std::array<int, max_element_nodes> order{};
  for (int k = 0; k < max_element_nodes; ++k) order[static_cast<std::size_t>(k)] = k;
  const int c = f.corner_count;
  // Corners 0, c-1, .., 1; edge k (corner k to k+1) becomes the edge from corner k+1 to k, which in
  // the reversed listing is edge c-1-k.
  for (int k = 1; k < c; ++k) order[static_cast<std::size_t>(k)] = c - k;
  if (f.node_count > c) {
    for (int k = 0; k < c; ++k) order[static_cast<std::size_t>(c + k)] = c + (c - 1 - k);
  }
  return order;
}

std::optional<ShapeProblem> element_shape_problem(ElementType type, Integration integration,
                                                  const std::array<Vec2, max_element_nodes>& x) {
  const ElementFamily& f = family(type);
  if (f.report_element) return report_element_problem(f, x);

  const double area2 = twice_corner_area(f, x);
  if (!(area2 > 0.0)) {
    ShapeProblem p;
    p.value = 0.5 * area2;
    p.kind = area2 < 0.0 ? ShapeProblem::Kind::clockwise : ShapeProblem::Kind::degenerate;
    return p;
  }
  for (int e = 0; e < f.edge_count(); ++e) {
    const EdgeNodes& edge = f.edges[static_cast<std::size_t>(e)];
    if (edge.count != 3) continue;
    const Vec2& a = x[static_cast<std::size_t>(edge.first())];
    const Vec2& m = x[static_cast<std::size_t>(edge.node[1])];
    const Vec2& b = x[static_cast<std::size_t>(edge.last())];
    const Vec2 chord = b - a;
    const double length2 = chord.squaredNorm();
    const double along = (m - a).dot(chord) / length2;
    const double off = std::abs(chord.x() * (m - a).y() - chord.y() * (m - a).x()) / length2;
    if (along < 0.25 || along > 0.75 || off > max_midside_offset) {
      ShapeProblem p;
      p.kind = ShapeProblem::Kind::midside_off_edge;
      p.node = edge.node[1];
      p.value = off;
      p.detail = "its mid-side node " + std::to_string(edge.node[1] + 1) + " lies at " + number(along) +
                 " of its edge's chord and " + number(off) +
                 " chord lengths from it (a mid-side node belongs between 1/4 and 3/4 of the chord, at most " +
                 number(max_midside_offset) + " chord lengths off it; listed in the order of the edges?)";
      return p;
    }
  }
  const auto rule = f.stiffness_rule(integration);
  for (std::size_t q = 0; q < rule.size(); ++q) {
    ShapeValues v;
    f.shape(rule[q].xi, rule[q].eta, v);
    double j11 = 0.0, j12 = 0.0, j21 = 0.0, j22 = 0.0;
    for (int a = 0; a < f.node_count; ++a) {
      const auto k = static_cast<std::size_t>(a);
      j11 += x[k].x() * v.dN_dxi[k];
      j12 += x[k].x() * v.dN_deta[k];
      j21 += x[k].y() * v.dN_dxi[k];
      j22 += x[k].y() * v.dN_deta[k];
    }
    const double det = j11 * j22 - j12 * j21;
    if (!(det > 0.0)) {
      ShapeProblem p;
      p.kind = ShapeProblem::Kind::jacobian;
      p.point = static_cast<int>(q);
      p.xi = rule[q].xi;
      p.eta = rule[q].eta;
      p.value = det;
      p.detail = "det J = " + number(det) + " at integration point " + std::to_string(q + 1) + " (xi " +
                 number(rule[q].xi) + ", eta " + number(rule[q].eta) +
                 "): the element is inverted or too distorted there (a mid-side node too far in, or a "
                 "corner angle of 180 degrees or more)";
      return p;
    }
  }
  return std::nullopt;
}

}  // namespace saasgaps
