#pragma once
/// Consistent nodal loads of a traction on one edge of an element: f_a = integral N_a t dS over the
/// edge, dS = thickness ds (plane) or 2 pi r ds (axisymmetric, the full ring).
///
/// A straight 2-node edge a-b under a uniform traction: plane t L / 2 each; axisymmetric
/// 2 pi L (2 r_a + r_b) / 6 at a, mirrored at b (closed form). A 3-node edge (a, m, b) is the
/// quadratic curve through its nodes, x(s) = sum N_k(s) x_k, N = (s (s - 1) / 2, 1 - s^2,
/// s (s + 1) / 2) on s in [-1, 1]; a pressure acts along the curve's own normal at every point and a
/// shear along its tangent, integrated by 4-point Gauss (plane: 1/6, 4/6, 1/6 of the force on a
/// straight edge; on a curved one the length element and the normal come from the curve).

#include <array>

#include "solver/base/voigt.hpp"
#include "solver/fe/element_family.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// The shape functions of a 2-node (a, b) or 3-node (a, m, b) edge at s in [-1, 1] and their
/// derivatives d/ds: linear, or N = (s (s - 1) / 2, 1 - s^2, s (s + 1) / 2).
struct EdgeShape {
  std::array<double, max_edge_nodes> N{};
  std::array<double, max_edge_nodes> dN{};
};
EdgeShape edge_shape(double s, int count);

/// A point of the 4-point Gauss rule along the edge through `nodes` (2 or 3 points, from a to b) on
/// s in [-1, 1]: the edge's shape functions N_k (linear, or the quadratic ones above), the point
/// x = sum N_k x_k and dx/ds (the tangent times the length element), and the Gauss weight.
struct EdgePoint {
  std::array<double, max_edge_nodes> N{};
  Vec2 x = Vec2::Zero();
  Vec2 dx = Vec2::Zero();
  double weight = 0.0;
};
std::array<EdgePoint, 4> edge_points(const std::array<Vec2, max_edge_nodes>& nodes, int count);

/// The area weight of an edge point: weight |dx/ds| t (plane) or weight |dx/ds| 2 pi r (axisymmetric).
double edge_area_weight(const EdgePoint& p, AnalysisType analysis, double thickness);

/// Loads of a uniform traction (t_r, t_z) per unit area on the straight edge a-b.
std::array<Vec2, 2> edge_traction_loads(const Vec2& a, const Vec2& b, const Vec2& traction,
                                        AnalysisType analysis, double thickness);

/// The loads of a pressure and a shear on the edge through `nodes` (2 or 3 points, from a to b):
/// pressure > 0 pushes along `inward` (the unit normal's side that points into the element: +1 or
/// -1 times the left normal (-dz/ds, dr/ds) of the edge run from a to b), shear > 0 acts along a -> b.
/// Returns one force per edge node.
std::array<Vec2, max_edge_nodes> edge_pressure_loads(const std::array<Vec2, max_edge_nodes>& nodes, int count,
                                                     double pressure, double shear, double inward,
                                                     AnalysisType analysis, double thickness);

}  // namespace saasgaps
