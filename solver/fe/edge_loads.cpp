#include "solver/fe/edge_loads.hpp"

#include "solver/fe/element_geometry.hpp"
#include "solver/fe/quadrature.hpp"

namespace saasgaps {

std::array<Vec2, 2> edge_traction_loads(const Vec2& a, const Vec2& b, const Vec2& traction,
                                        AnalysisType analysis, double thickness) {
  const std::array<double, 2> w = edge_weights(a, b, analysis, thickness);
  return {w[0] * traction, w[1] * traction};
}

EdgeShape edge_shape(double s, int count) {
  if (count == 2) return {{(1.0 - s) / 2.0, (1.0 + s) / 2.0, 0.0}, {-0.5, 0.5, 0.0}};
  return {{s * (s - 1.0) / 2.0, 1.0 - s * s, s * (s + 1.0) / 2.0}, {s - 0.5, -2.0 * s, s + 0.5}};
}

std::array<EdgePoint, 4> edge_points(const std::array<Vec2, max_edge_nodes>& nodes, int count) {
  std::array<EdgePoint, 4> points;
  const auto rule = gauss_line(4);
  for (std::size_t p = 0; p < points.size(); ++p) {
    EdgePoint& e = points[p];
    const double s = rule[p].s;
    e.weight = rule[p].weight;
    const EdgeShape shape = edge_shape(s, count);
    e.N = shape.N;
    const std::array<double, max_edge_nodes>& dN = shape.dN;
    for (int k = 0; k < count; ++k) {
      e.x += e.N[static_cast<std::size_t>(k)] * nodes[static_cast<std::size_t>(k)];
      e.dx += dN[static_cast<std::size_t>(k)] * nodes[static_cast<std::size_t>(k)];
    }
  }
  return points;
}

double edge_area_weight(const EdgePoint& p, AnalysisType analysis, double thickness) {
  return p.weight * p.dx.norm() * (analysis == AnalysisType::axisymmetric ? two_pi * p.x.x() : thickness);
}

std::array<Vec2, max_edge_nodes> edge_pressure_loads(const std::array<Vec2, max_edge_nodes>& nodes, int count,
                                                     double pressure, double shear, double inward,
                                                     AnalysisType analysis, double thickness) {
  std::array<Vec2, max_edge_nodes> f{Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
  // The integrand is N_a (p n + s t) |dx/ds| r: a polynomial of degree 4 (axisymmetric quadratic
  // edge: N quadratic, dx/ds linear, r quadratic), which 3 Gauss points leave inexact; 4 are exact.
  for (const EdgePoint& q : edge_points(nodes, count)) {
    const Vec2 normal = inward * Vec2(-q.dx.y(), q.dx.x());  // unit inward normal times ds/d(s)
    const Vec2 traction = pressure * normal + shear * q.dx;
    const double weight = q.weight * (analysis == AnalysisType::axisymmetric ? two_pi * q.x.x() : thickness);
    for (int k = 0; k < count; ++k) f[static_cast<std::size_t>(k)] += (weight * q.N[static_cast<std::size_t>(k)]) * traction;
  }
  return f;
}

}  // namespace saasgaps
