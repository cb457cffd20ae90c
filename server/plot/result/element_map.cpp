#include "plot/result/element_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace saasgaps::plot {

const ElementFamily& element_family(const SolidElement& e) {
  switch (e.nodes.size()) {
    case 3: return family(ElementType::tri3);
    case 4: return family(ElementType::saas);
    case 6: return family(ElementType::tri6);
    case 8: return family(e.centre >= 0 ? ElementType::quad9 : ElementType::quad8);
    default: break;
  }
  throw std::invalid_argument("element " + std::to_string(e.id) + " has an outline of " +
                              std::to_string(e.nodes.size()) + " nodes");
}

std::vector<int> family_nodes(const SolidElement& e) {
  const ElementFamily& f = element_family(e);
  std::vector<int> nodes(static_cast<std::size_t>(f.node_count), -1);
  // The outline walks the family's edges: each edge's nodes but its last (ResultMesh).
  std::size_t at = 0;
  for (const EdgeNodes& edge : f.edges) {
    for (int k = 0; k + 1 < edge.count; ++k) nodes[static_cast<std::size_t>(edge.node[static_cast<std::size_t>(k)])] = e.nodes[at++];
  }
  if (f.type == ElementType::quad9) nodes[8] = e.centre;
  return nodes;
}

std::optional<ReferenceCoordinates> inverse_map(const ResultMesh& mesh, const SolidElement& e, double r, double z) {
  const ElementFamily& f = element_family(e);
  const std::vector<int> nodes = family_nodes(e);
  double r0 = mesh.nodes[nodes[0]].r, r1 = r0, z0 = mesh.nodes[nodes[0]].z, z1 = z0;
  for (const int n : nodes) {
    r0 = std::min(r0, mesh.nodes[n].r);
    r1 = std::max(r1, mesh.nodes[n].r);
    z0 = std::min(z0, mesh.nodes[n].z);
    z1 = std::max(z1, mesh.nodes[n].z);
  }
  const double size = std::hypot(r1 - r0, z1 - z0);
  const std::array<double, 2> start = reference_centre(f.cell);
  double xi = start[0], eta = start[1];
  ShapeValues v;
  bool converged = false;
  for (int iteration = 0; iteration < 50 && !converged; ++iteration) {
    f.shape(xi, eta, v);
    double x = 0.0, y = 0.0, x_xi = 0.0, x_eta = 0.0, y_xi = 0.0, y_eta = 0.0;
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      const MeshNode& p = mesh.nodes[nodes[a]];
      x += v.N[a] * p.r;
      y += v.N[a] * p.z;
      x_xi += v.dN_dxi[a] * p.r;
      x_eta += v.dN_deta[a] * p.r;
      y_xi += v.dN_dxi[a] * p.z;
      y_eta += v.dN_deta[a] * p.z;
    }
    const double dr = r - x, dz = z - y;
    if (std::hypot(dr, dz) <= 1e-12 * size) {
      converged = true;
      break;
    }
    const double det = x_xi * y_eta - x_eta * y_xi;
    if (!(std::abs(det) > 0.0)) return std::nullopt;
    const double dxi = (y_eta * dr - x_eta * dz) / det, deta = (x_xi * dz - y_xi * dr) / det;
    xi += dxi;
    eta += deta;
    if (!std::isfinite(xi) || !std::isfinite(eta) || std::abs(xi) > 10.0 || std::abs(eta) > 10.0) return std::nullopt;
    // Steps at round-off size: the map is affine (or nearly) here, and the point is found.
    if (std::hypot(dxi, deta) <= 1e-14) converged = true;
  }
  if (!converged) return std::nullopt;
  constexpr double s = reference_slack;
  const bool inside = f.cell == CellShape::triangle ? xi >= -s && eta >= -s && xi + eta <= 1.0 + s
                                                    : std::abs(xi) <= 1.0 + s && std::abs(eta) <= 1.0 + s;
  if (!inside) return std::nullopt;
  return ReferenceCoordinates{xi, eta};
}

Subdivision subdivide(CellShape cell, int n) {
  if (n < 1) throw std::invalid_argument("a subdivision needs n >= 1");
  Subdivision s;
  if (cell == CellShape::triangle) {
    // Points (i/n, j/n), i + j <= n, row by row in j.
    std::vector<int> first_of_row;
    for (int j = 0; j <= n; ++j) {
      first_of_row.push_back(static_cast<int>(s.points.size()));
      for (int i = 0; i + j <= n; ++i) s.points.push_back({static_cast<double>(i) / n, static_cast<double>(j) / n});
    }
    const auto at = [&first_of_row](int i, int j) { return first_of_row[static_cast<std::size_t>(j)] + i; };
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i + j < n; ++i) {
        s.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < n) s.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
    return s;
  }
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) s.points.push_back({-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n});
  }
  const auto at = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      // The square's diagonal towards the centre: along xi = eta in the (+, +) and (-, -) quarters.
      const bool rising = (2 * i + 1 - n) * (2 * j + 1 - n) > 0;
      if (rising) {
        s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      } else {
        s.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        s.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  return s;
}

const Subdivision& drawing_subdivision(const ElementFamily& family, bool many) {
  static const Subdivision triangle1 = subdivide(CellShape::triangle, 1), triangle2 = subdivide(CellShape::triangle, 2),
                           triangle4 = subdivide(CellShape::triangle, 4), square2 = subdivide(CellShape::quadrilateral, 2),
                           square4 = subdivide(CellShape::quadrilateral, 4);
  const bool triangle = family.cell == CellShape::triangle;
  if (!family.quadratic()) return triangle ? triangle1 : square2;
  if (many) return triangle ? triangle2 : square2;
  return triangle ? triangle4 : square4;
}

int drawing_edge_pieces(const ElementFamily& family, bool many) {
  if (!family.quadratic()) return 1;
  return many ? 2 : 4;
}

}  // namespace saasgaps::plot
