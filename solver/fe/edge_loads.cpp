#include "solver/fe/edge_loads.hpp"

#include "solver/fe/element_geometry.hpp"
#include "solver/fe/quadrature.hpp"

namespace saasgaps {

std::array<Vec2, 2> edge_traction_loads(const Vec2& a, const Vec2& b, const Vec2& traction,
                                        AnalysisType analysis, double thickness) {
  const std::array<double, 2> w = edge_weights(a, b, analysis, thickness);
  return {w[0] * traction, w[1] * traction};
}

std::array<Vec2, max_edge_nodes> edge_pressure_loads(const std::array<Vec2, max_edge_nodes>& nodes, int count,
                                                     double pressure, double shear, double inward,
                                                     AnalysisType analysis, double thickness) {
  std::array<Vec2, max_edge_nodes> f{Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
  // The integrand is N_a (p n + s t) |dx/ds| r: a polynomial of degree 4 (axisymmetric quadratic
  // edge: N quadratic, dx/ds linear, r quadratic), which 3 Gauss points leave inexact; 4 are exact.
  for (const LinePoint& q : gauss_line(4)) {
    const double s = q.s;
    std::array<double, max_edge_nodes> N{};
    std::array<double, max_edge_nodes> dN{};
    if (count == 2) {
      N = {(1.0 - s) / 2.0, (1.0 + s) / 2.0, 0.0};
      dN = {-0.5, 0.5, 0.0};
    } else {
      N = {s * (s - 1.0) / 2.0, 1.0 - s * s, s * (s + 1.0) / 2.0};
      dN = {s - 0.5, -2.0 * s, s + 0.5};
    }
    Vec2 x = Vec2::Zero();
    Vec2 dx = Vec2::Zero();  // dx/ds: the tangent times the length element
    for (int k = 0; k < count; ++k) {
      x += N[static_cast<std::size_t>(k)] * nodes[static_cast<std::size_t>(k)];
      dx += dN[static_cast<std::size_t>(k)] * nodes[static_cast<std::size_t>(k)];
    }
    const Vec2 normal = inward * Vec2(-dx.y(), dx.x());  // unit inward normal times ds/d(s)
    const Vec2 traction = pressure * normal + shear * dx;
    const double weight = q.weight * (analysis == AnalysisType::axisymmetric ? two_pi * x.x() : thickness);
    for (int k = 0; k < count; ++k) f[static_cast<std::size_t>(k)] += (weight * N[static_cast<std::size_t>(k)]) * traction;
  }
  return f;
}

}  // namespace saasgaps
