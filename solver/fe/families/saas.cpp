/// saas: the quadrilateral of SAAS III, four constant-strain triangles (i, i+1, centre) around a
/// centre node at the mean of the corners, whose unknowns are condensed out (saas_kernel.hpp). As an
/// interpolant it is piecewise linear on the four triangles of the reference square, with the
/// centre value the mean of the corner values; one material point, the centre.
#include <cmath>

#include "solver/fe/families/families.hpp"
#include "solver/fe/saas_kernel.hpp"

namespace saasgaps {

namespace {

constexpr std::array<EdgeNodes, 4> edges{{{{0, 1, -1}, 2}, {{1, 2, -1}, 2}, {{2, 3, -1}, 2}, {{3, 0, -1}, 2}}};
constexpr std::array<std::array<double, 2>, 4> nodes{{{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}};
constexpr std::array<ReferencePoint, 1> centre{{{0.0, 0.0, 4.0}}};

/// On the triangle (a, b, centre) of the reference square, with a, b corners: the barycentric
/// coordinates of (xi, eta), the centre's share spread as a quarter to each corner.
void shape(double xi, double eta, ShapeValues& v) {
  // Which triangle: the one whose outward direction (the corner pair's edge) is nearest.
  int a = 0;
  if (std::abs(xi) >= std::abs(eta)) {
    a = xi >= 0.0 ? 1 : 3;
  } else {
    a = eta >= 0.0 ? 2 : 0;
  }
  const int b = (a + 1) % 4;
  const auto& pa = nodes[static_cast<std::size_t>(a)];
  const auto& pb = nodes[static_cast<std::size_t>(b)];
  // Barycentrics of (xi, eta) in (pa, pb, 0): lambda_a pa + lambda_b pb = (xi, eta).
  const double det = pa[0] * pb[1] - pa[1] * pb[0];
  const double la = (xi * pb[1] - eta * pb[0]) / det;
  const double lb = (pa[0] * eta - pa[1] * xi) / det;
  const double lc = 1.0 - la - lb;
  const double dla_dxi = pb[1] / det, dla_deta = -pb[0] / det;
  const double dlb_dxi = -pa[1] / det, dlb_deta = pa[0] / det;
  for (int k = 0; k < 4; ++k) {
    v.N[static_cast<std::size_t>(k)] = lc / 4.0;
    v.dN_dxi[static_cast<std::size_t>(k)] = -(dla_dxi + dlb_dxi) / 4.0;
    v.dN_deta[static_cast<std::size_t>(k)] = -(dla_deta + dlb_deta) / 4.0;
  }
  v.N[static_cast<std::size_t>(a)] += la;
  v.N[static_cast<std::size_t>(b)] += lb;
  v.dN_dxi[static_cast<std::size_t>(a)] += dla_dxi;
  v.dN_deta[static_cast<std::size_t>(a)] += dla_deta;
  v.dN_dxi[static_cast<std::size_t>(b)] += dlb_dxi;
  v.dN_deta[static_cast<std::size_t>(b)] += dlb_deta;
}

std::span<const ReferencePoint> points(Integration) { return centre; }

}  // namespace

const ElementFamily saas_family{ElementType::saas, CellShape::quadrilateral, 4, 4, 1, edges, nodes, 3, 9,
                                shape, points, points, saas_matrices, saas_states, true};

}  // namespace saasgaps
