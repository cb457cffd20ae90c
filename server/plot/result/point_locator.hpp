#pragma once
/// Which solid elements hold a point (r, z) of the undeformed mesh, and where in each (its
/// reference coordinates, element_map.hpp: the element's own map, curved edges included), found
/// through a uniform grid of buckets over the mesh's bounding box (about one bucket per element,
/// each listing the elements whose bounding boxes touch it), so a lookup costs a few inverse maps
/// whatever the mesh's size. A quadratic edge's box includes the control point of its curve
/// (2 m - (a + b)/2 for corners a, b and mid-side node m), which bounds the curve.

#include <optional>
#include <vector>

#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

/// A point of an element's reference cell.
struct ReferenceCoordinates {
  double xi = 0.0, eta = 0.0;
};

/// How far outside the reference cell a point may lie and still belong to the element (round-off
/// of a point on an edge: such a point belongs to both neighbours).
inline constexpr double reference_slack = 1e-9;

struct Location {
  std::size_t element = 0;  ///< index into mesh.solids
  ReferenceCoordinates at;  ///< the point in the element's reference cell
};

class PointLocator {
 public:
  explicit PointLocator(const ResultMesh& mesh);

  /// The element holding (r, z): on an edge or a corner, the first in the mesh's order of those
  /// holding it; none outside the mesh.
  std::optional<Location> locate(double r, double z) const;

  /// Every element holding (r, z) (several on an edge or at a node), in the mesh's order.
  std::vector<Location> locate_all(double r, double z) const;

 private:
  const ResultMesh& mesh_;
  double r0_ = 0.0, z0_ = 0.0, cell_r_ = 1.0, cell_z_ = 1.0;
  int columns_ = 1, rows_ = 1;
  std::vector<std::size_t> first_;   ///< per bucket, the start of its elements in elements_ (CSR)
  std::vector<std::size_t> elements_;
};

}  // namespace saasgaps::plot
