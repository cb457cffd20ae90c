/// tri3: the constant-strain triangle of SAAS III, N = (1 - xi - eta, xi, eta); its kernel is the
/// report's (saas_kernel.hpp), one material point at the centroid.
#include "solver/fe/families/families.hpp"
#include "solver/fe/saas_kernel.hpp"

namespace saasgaps {

namespace {

constexpr std::array<EdgeNodes, 3> edges{{{{0, 1, -1}, 2}, {{1, 2, -1}, 2}, {{2, 0, -1}, 2}}};
constexpr std::array<std::array<double, 2>, 3> nodes{{{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}}};
constexpr std::array<ReferencePoint, 1> centroid{{{1.0 / 3.0, 1.0 / 3.0, 0.5}}};

void shape(double xi, double eta, ShapeValues& v) {
  v.N[0] = 1.0 - xi - eta;
  v.N[1] = xi;
  v.N[2] = eta;
  v.dN_dxi[0] = -1.0;
  v.dN_dxi[1] = 1.0;
  v.dN_dxi[2] = 0.0;
  v.dN_deta[0] = -1.0;
  v.dN_deta[1] = 0.0;
  v.dN_deta[2] = 1.0;
}

std::span<const ReferencePoint> points(Integration) { return centroid; }

}  // namespace

const ElementFamily tri3_family{ElementType::tri3, CellShape::triangle, 3, 3, 1, edges, nodes, 2, 5,
                                shape, points, points, saas_matrices, saas_states, true};

}  // namespace saasgaps
