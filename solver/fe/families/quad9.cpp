/// quad9: the Lagrange (biquadratic) quadrilateral, N = l_i(xi) l_j(eta) with l_-1 = s (s - 1) / 2,
/// l_0 = 1 - s^2, l_1 = s (s + 1) / 2; nodes: corners, mid-sides, centre. Integration full 3 x 3
/// (default) or reduced 2 x 2; material points are the rule's points.
#include "solver/fe/families/families.hpp"
#include "solver/fe/isoparametric_kernel.hpp"
#include "solver/fe/quadrature.hpp"

namespace saasgaps {

namespace {

constexpr auto& nodes = quadratic_quad_nodes;

/// l(s) and l'(s) of the 1D quadratic through -1, 0, 1 for the node at `at`.
void lagrange(double s, double at, double& l, double& dl) {
  if (at < 0.0) {
    l = s * (s - 1.0) / 2.0;
    dl = s - 0.5;
  } else if (at > 0.0) {
    l = s * (s + 1.0) / 2.0;
    dl = s + 0.5;
  } else {
    l = 1.0 - s * s;
    dl = -2.0 * s;
  }
}

void shape(double xi, double eta, ShapeValues& v) {
  for (std::size_t a = 0; a < 9; ++a) {
    double lx = 0.0, dlx = 0.0, ly = 0.0, dly = 0.0;
    lagrange(xi, nodes[a][0], lx, dlx);
    lagrange(eta, nodes[a][1], ly, dly);
    v.N[a] = lx * ly;
    v.dN_dxi[a] = dlx * ly;
    v.dN_deta[a] = lx * dly;
  }
}

std::span<const ReferencePoint> points(Integration integration) {
  return gauss_square(integration == Integration::reduced ? 2 : 3);
}

}  // namespace

const ElementFamily quad9_family{ElementType::quad9, CellShape::quadrilateral, 9, 4, 2,
                                 quadratic_quad_edges, quadratic_quad_nodes, 10, 28,
                                 shape, points, points, isoparametric_matrices, isoparametric_states};

}  // namespace saasgaps
