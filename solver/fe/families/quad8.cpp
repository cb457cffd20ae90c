/// quad8: the serendipity quadrilateral. Corners (xi_a, eta_a) = (+-1, +-1):
///   N_a = (1 + xi xi_a)(1 + eta eta_a)(xi xi_a + eta eta_a - 1) / 4;
/// mid-sides on eta = +-1: (1 - xi^2)(1 + eta eta_a) / 2; on xi = +-1: (1 + xi xi_a)(1 - eta^2) / 2.
/// Integration full 3 x 3 (default) or reduced 2 x 2; material points are the rule's points.
#include "solver/fe/families/families.hpp"
#include "solver/fe/isoparametric_kernel.hpp"
#include "solver/fe/quadrature.hpp"

namespace saasgaps {

namespace {

constexpr auto& nodes = quadratic_quad_nodes;

void shape(double xi, double eta, ShapeValues& v) {
  for (std::size_t a = 0; a < 4; ++a) {
    const double xa = nodes[a][0];
    const double ya = nodes[a][1];
    const double s = 1.0 + xi * xa;
    const double t = 1.0 + eta * ya;
    const double q = xi * xa + eta * ya - 1.0;
    v.N[a] = s * t * q / 4.0;
    v.dN_dxi[a] = xa * t * (q + s) / 4.0;
    v.dN_deta[a] = ya * s * (q + t) / 4.0;
  }
  for (std::size_t a = 4; a < 8; ++a) {
    const double xa = nodes[a][0];
    const double ya = nodes[a][1];
    if (xa == 0.0) {
      v.N[a] = (1.0 - xi * xi) * (1.0 + eta * ya) / 2.0;
      v.dN_dxi[a] = -xi * (1.0 + eta * ya);
      v.dN_deta[a] = ya * (1.0 - xi * xi) / 2.0;
    } else {
      v.N[a] = (1.0 + xi * xa) * (1.0 - eta * eta) / 2.0;
      v.dN_dxi[a] = xa * (1.0 - eta * eta) / 2.0;
      v.dN_deta[a] = -eta * (1.0 + xi * xa);
    }
  }
}

std::span<const ReferencePoint> points(Integration integration) {
  return gauss_square(integration == Integration::reduced ? 2 : 3);
}

}  // namespace

const ElementFamily quad8_family{ElementType::quad8, CellShape::quadrilateral, 8, 4, 2,
                                 quadratic_quad_edges, std::span(quadratic_quad_nodes).first<8>(), 16, 23,
                                 shape, points, points, isoparametric_matrices, isoparametric_states};

}  // namespace saasgaps
