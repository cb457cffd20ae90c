/// tri6: the quadratic triangle. With L1 = 1 - xi - eta, L2 = xi, L3 = eta: corners N_i = L_i (2 L_i - 1),
/// mid-sides N4 = 4 L1 L2, N5 = 4 L2 L3, N6 = 4 L3 L1. Stiffness and material points: the 3-point
/// rule of degree 2 (exact for the plane stiffness of a straight-sided element).
#include "solver/fe/families/families.hpp"
#include "solver/fe/isoparametric_kernel.hpp"
#include "solver/fe/quadrature.hpp"

namespace saasgaps {

namespace {

constexpr std::array<EdgeNodes, 3> edges{{{{0, 3, 1}, 3}, {{1, 4, 2}, 3}, {{2, 5, 0}, 3}}};
constexpr std::array<std::array<double, 2>, 6> nodes{
    {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}}};

void shape(double xi, double eta, ShapeValues& v) {
  const double l1 = 1.0 - xi - eta;
  const double l2 = xi;
  const double l3 = eta;
  v.N = {l1 * (2.0 * l1 - 1.0), l2 * (2.0 * l2 - 1.0), l3 * (2.0 * l3 - 1.0), 4.0 * l1 * l2, 4.0 * l2 * l3,
         4.0 * l3 * l1};
  // dL1 = (-1, -1), dL2 = (1, 0), dL3 = (0, 1).
  v.dN_dxi = {-(4.0 * l1 - 1.0), 4.0 * l2 - 1.0, 0.0, 4.0 * (l1 - l2), 4.0 * l3, -4.0 * l3};
  v.dN_deta = {-(4.0 * l1 - 1.0), 0.0, 4.0 * l3 - 1.0, -4.0 * l2, 4.0 * l2, 4.0 * (l1 - l3)};
}

std::span<const ReferencePoint> points(Integration) { return gauss_triangle(3); }

}  // namespace

const ElementFamily tri6_family{ElementType::tri6, CellShape::triangle, 6, 3, 2, edges, nodes, 9, 22,
                                shape, points, points, isoparametric_matrices, isoparametric_states};

}  // namespace saasgaps
