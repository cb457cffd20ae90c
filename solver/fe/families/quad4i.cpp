/// quad4i: the bilinear quadrilateral N_a = (1 + xi xi_a)(1 + eta eta_a) / 4 with incompatible modes
/// (incompatible_modes.hpp); 2 x 2 integration, four material points.
#include "solver/fe/families/families.hpp"
#include "solver/fe/incompatible_modes.hpp"
#include "solver/fe/quadrature.hpp"

namespace saasgaps {

namespace {

constexpr std::array<EdgeNodes, 4> edges{{{{0, 1, -1}, 2}, {{1, 2, -1}, 2}, {{2, 3, -1}, 2}, {{3, 0, -1}, 2}}};
constexpr std::array<std::array<double, 2>, 4> nodes{{{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}};

void shape(double xi, double eta, ShapeValues& v) {
  for (std::size_t a = 0; a < 4; ++a) {
    const double xa = nodes[a][0];
    const double ya = nodes[a][1];
    v.N[a] = (1.0 + xi * xa) * (1.0 + eta * ya) / 4.0;
    v.dN_dxi[a] = xa * (1.0 + eta * ya) / 4.0;
    v.dN_deta[a] = ya * (1.0 + xi * xa) / 4.0;
  }
}

std::span<const ReferencePoint> points(Integration) { return gauss_square(2); }

}  // namespace

const ElementFamily quad4i_family{ElementType::quad4i, CellShape::quadrilateral, 4, 4, 1, edges, nodes, 3, 9,
                                  shape, points, points, incompatible_mode_matrices, incompatible_mode_states};

}  // namespace saasgaps
