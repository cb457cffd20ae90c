#pragma once
/// New element sizes from the error field (the adaptive loop, io/import/adaptive_loop.hpp), by
/// equidistribution (Zienkiewicz and Zhu): the permissible error of each of the N elements is
///   e_bar = target * sqrt((n^2 + e^2) / N)
/// (n the energy norm, e the error of error_estimate), so that N elements each at e_bar give the
/// relative error `target`. Element k with error e_k and size h_k gets
///   xi_k = e_k / e_bar,   h_new = h_k / xi_k^(1/p),
/// p the convergence rate of its family in the energy norm (1 for the linear families and the
/// report's element, 2 for tri6, quad8, quad9), clamped per cycle to h_k / 4 <= h_new <= 2 h_k and
/// to the geometry's own size: extent / 2000 <= h_new <= extent / 2 (extent the larger side of the
/// bounding box). When the sizes would need more than `max_nodes` nodes (about 1 node per h^2 of
/// area for quadrilaterals, 1 per 0.43 h^2 for triangles: a node per element pair), every size grows
/// by one factor so that they do not.
///
/// h_k is the element's size: sqrt(area) for a quadrilateral, the side of the equilateral triangle
/// of its area (sqrt(4 area / sqrt 3)) for a triangle. The field Gmsh gets: each node the mean of the
/// new sizes of the elements around it, on the previous mesh's corners (quadrilaterals split in two
/// triangles).

#include <cstddef>

#include "io/mesher/gmsh_mesh.hpp"
#include "solver/model/model.hpp"
#include "solver/state/solution.hpp"

namespace saasgaps::io {

struct AdaptSizes {
  SizeField field;
  double predicted_nodes = 0.0;  ///< nodes the new sizes ask for, after the max_nodes bound
  bool bounded_by_nodes = false;  ///< the sizes grew to keep within max_nodes
};

/// The sizes for relative error `target` from a solved model (its elements' `error` and its
/// error_estimate). Throws SolverError when the solution carries no estimate.
AdaptSizes adapt_sizes(const Model& model, const Solution& solution, double target, std::size_t max_nodes);

}  // namespace saasgaps::io
