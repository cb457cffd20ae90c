#pragma once
/// Which solid element holds a point (r, z) of the undeformed mesh, and the point's linear
/// interpolation weights there, found through a uniform grid of buckets over the mesh's bounding box
/// (about one bucket per element, each listing the elements whose bounding boxes touch it), so a
/// lookup costs a few point-in-triangle tests whatever the mesh's size.
///
/// An element is split into triangles as the contour plot splits it (contour_bands.hpp:
/// triangulate), so that values interpolated here are the ones the contour plot draws.

#include <array>
#include <optional>
#include <vector>

#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

struct Location {
  std::size_t element = 0;         ///< index into mesh.solids
  std::array<int, 3> nodes{};      ///< the corners of the triangle holding the point (node indices)
  std::array<double, 3> weights{}; ///< barycentric weights of those corners (sum 1)
};

class PointLocator {
 public:
  explicit PointLocator(const ResultMesh& mesh);

  /// The element holding (r, z) (on an edge: one of its elements); none outside the mesh.
  std::optional<Location> locate(double r, double z) const;

 private:
  const ResultMesh& mesh_;
  double r0_ = 0.0, z0_ = 0.0, cell_r_ = 1.0, cell_z_ = 1.0;
  int columns_ = 1, rows_ = 1;
  std::vector<std::size_t> first_;   ///< per bucket, the start of its elements in elements_ (CSR)
  std::vector<std::size_t> elements_;
};

}  // namespace saasgaps::plot
