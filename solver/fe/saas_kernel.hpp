#pragma once
/// The report's two elements (SAAS III): the constant-strain triangle (tri3) and the quadrilateral
/// of four constant-strain triangles meeting at a centre node at the mean of the corners (saas),
/// whose centre's two DOFs are condensed out statically. Their geometry is element_geometry.hpp's.
///
/// Weights: plane analyses integrate over thickness t (w = t A); axisymmetric ones over the full ring
/// (w = 2 pi r_c A, with the hoop strain u/r taken at the triangle centroid r_c). A lone axisymmetric
/// triangle samples u/r at three interior points instead (the centroid alone leaves it a spurious
/// zero-energy mode); its stresses are still reported at the centroid.
///
/// Both keep one material point, the centre: a tri3's only strain, a saas quad's weighted mean of
/// its four triangles. Their arithmetic is the program's since 1976's tables were reproduced, on
/// fixed-size matrices, and its digits are pinned by the regression data: change it only knowingly.

#include <span>

#include "solver/fe/element_kernel.hpp"

namespace saasgaps {

/// Condensed 8 x 8 (saas) or 6 x 6 (tri3) stiffness and loads.
ElementMatrices saas_matrices(const ElementData& e);

/// The centre state (the one material point) from the corner displacements.
ElementStates saas_states(const ElementData& e, std::span<const double> u);

/// One constant-strain triangle of a report element: its vertices (indices into the corners 0..3
/// and, for a saas quad, the centre 4 at the mean of the corners), centroid, volume weight w (t A, or
/// 2 pi r_c A) and its state, whose w-weighted mean is the element's centre state.
struct TriangleState {
  std::array<int, 3> vertex{0, 1, 2};
  Vec2 centroid = Vec2::Zero();
  double area = 0.0;
  double w = 0.0;
  ElementState state;
};

/// The triangles of a report element and their states: four for a saas quad, one for a tri3.
/// Returns how many were written into `out`.
int saas_triangle_states(const ElementData& e, std::span<const double> u, std::array<TriangleState, 4>& out);

}  // namespace saasgaps
